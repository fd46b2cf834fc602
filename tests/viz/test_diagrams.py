"""Each scene names its drawing family; the diagrams and the animations are kept per family, not per scene."""

import re

import pytest

from app.scenes import SCENES
from app.viz import diagrams, mechanism


def card(scene_id: str) -> str:
    s = SCENES[scene_id]
    defaults = {p.name: p.default for p in s.system.parameters}
    particles = [(p.label, p.position) for p in s.system.particles]
    return diagrams.diagram(s.family, s.title, s.figure, defaults, dict(s.initial), s.system.coordinates, particles,
                            marks=s.marks)  # fmt: skip


def test_every_family_is_drawn_both_ways_and_used_by_a_scene():
    used = {s.family for s in SCENES.values()}
    assert used == set(diagrams.FAMILIES) == set(mechanism.FAMILIES)
    # the tables are keyed by family: two scenes drawn alike share one entry
    assert SCENES["simple-pendulum"].family == SCENES["damped-pendulum"].family


def test_a_mark_adds_to_the_family_drawing():
    # the drag drawn as the force on the bob (its torque about the pivot is Q_θ = −b θ̇), labelled with its
    # magnitude against the velocity v drawn beside it: no sign on the label to read twice (prof-l 6)
    damped = card("damped-pendulum")
    assert "(b/R) |θ̇|" in damped and "−(b/R)" not in damped and ">v</text>" in damped
    assert "(b/R)" not in card("simple-pendulum") and ">v</text>" not in card("simple-pendulum")


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_each_scene_draws_its_family_not_the_generic_figure(scene_id):
    s = SCENES[scene_id]
    particles = [(p.label, p.position) for p in s.system.particles]
    generic = diagrams.diagram("", s.title, s.figure, {}, dict(s.initial), s.system.coordinates, particles)
    assert card(scene_id) != generic and "coordinates: " in generic and "coordinates: " not in card(scene_id)


def test_the_pulley_figure_marks_all_three_heights_its_caption_names():
    # the caption says "heights y₁, y₂, Y measured upward": each is drawn, in the coordinates' colour
    svg = card("pulley")
    assert "Y measured upward" in SCENES["pulley"].figure
    for name in ("y₁", "y₂", "−Y"):  # prof-l 2: the arrow down to M, below the line, is −Y (Y itself is negative)
        assert f">{name}</text>" in svg, name
    # prof-h 2: measured from the line where U = 0, the string makes Y = −(y₁ + y₂)/2 − c negative: M hangs
    # below the line while the end masses are above it, and the figure says so
    assert ">U = 0</text>" in svg and "(Y < 0)" in SCENES["pulley"].figure
    # prof-k 3: no stray "< 0" floats beside Y's arrow; the arrow and the caption say it
    assert "&lt; 0</text>" not in svg


def test_the_pulley_figure_draws_every_strand_vertical():
    # prof-k 3: Y = −(y₁ + y₂)/2 − c holds only for vertical strands (a V of slanted ones makes the loop's length
    # nonlinear in Y), so every strand is vertical and leaves its pulley at a side, tangent to the rim
    svg = card("pulley")
    pulleys = [tuple(float(v) for v in m) for m in re.findall(r'<circle cx="([\d.]+)" cy="([\d.]+)" r="([\d.]+)"', svg)]
    strands = re.findall(r'<line x1="([\d.]+)" y1="([\d.]+)" x2="([\d.]+)" y2="([\d.]+)" stroke="#1b1f24" '
                         r'stroke-width="2"/>', svg)  # fmt: skip
    assert len(pulleys) == 3 and len(strands) >= 4
    sides = {(cx + sign * r, cy) for cx, cy, r in pulleys for sign in (-1, 1)}
    for x1, y1, x2, y2 in ((float(v) for v in s) for s in strands):
        assert x1 == x2, (x1, y1, x2, y2)
    tangent = [s for s in strands if (float(s[0]), float(s[1])) in sides]
    # the two end masses' strands and the movable pulley's two, each from a fixed pulley's side
    assert len(tangent) == 4
    movable = min(pulleys, key=lambda c: c[2])
    assert sorted(float(s[0]) for s in tangent if float(s[3]) == movable[1]) == [
        movable[0] - movable[2],
        movable[0] + movable[2],
    ]


@pytest.mark.parametrize("scene_id", ["spherical-pendulum", "helix-bead"])
def test_the_azimuth_is_drawn_from_a_named_x_axis(scene_id):
    # φ is an angle from the x axis: the axis is drawn and named, and φ labels an arc from it
    svg = card(scene_id)
    assert ">x</text>" in svg and ">φ</text>" in svg


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "damped-pendulum"])
def test_the_pendulum_figure_marks_the_origin_its_statement_measures_from(scene_id):
    """prof-o F9: the statement measures x across and z up from the lowest point of the swing; the figure drew
    neither. Both axes are drawn from there, and the caption says so."""
    svg = card(scene_id)
    assert ">x</text>" in svg and ">z</text>" in svg
    assert "lowest point" in SCENES[scene_id].statement and "lowest point" in SCENES[scene_id].figure
