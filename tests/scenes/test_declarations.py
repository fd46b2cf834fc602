"""Every scene is declared as the issue fixes it, with consistent defaults and panels."""

import pytest

from app.engine.derivation.dimensions import number_beside_units, system_dimensions
from app.scenes import SCENES
from app.service.chapter.derivations import PROCESS_SCENES, derivation, scene_document
from app.viz.panels import OPTIONAL, constant_accelerations
from app.web.pages.chapter import page_model

# id -> (coordinates, parameters), exactly as the API promises them
TABLE = {
    "simple-pendulum": (("theta",), ("m", "g", "R")),
    "helix-bead": (("z",), ("m", "g", "R", "alpha")),
    "incline-block": (("X",), ("m", "g", "alpha")),
    "tabletop-spring": (("r", "theta"), ("m", "k")),
    "spherical-pendulum": (("theta", "phi"), ("m", "g", "R")),
    "rail-two-body": (("x1", "x2"), ("m1", "m2", "k", "l0")),
    "pulley": (("y1", "y2"), ("m1", "m2", "M", "g", "d", "c")),
    "movable-incline": (("X", "D"), ("m", "M", "g", "alpha")),
    "rotating-parabola": (("rho",), ("m", "g", "alpha", "omega")),
    "damped-pendulum": (("theta",), ("m", "g", "R", "b")),
    "double-pendulum": (("theta1", "theta2"), ("m1", "m2", "l1", "l2", "g")),
    "coupled-oscillators": (("x1", "x2"), ("m", "k", "kappa", "d")),
    "physical-pendulum": (("theta",), ("M", "l", "g")),
    "rolling-cylinder-wedge": (("X", "s"), ("m", "M", "r", "g", "alpha")),
    "massive-pulley": (("z",), ("m1", "m2", "M", "R", "g", "d")),
}
BEYOND_CHAPTER = {
    "double-pendulum",
    "coupled-oscillators",
    "damped-pendulum",
    "physical-pendulum",
    "rolling-cylinder-wedge",
    "massive-pulley",
}
# what the engine must find: cyclic coordinates and whether h = E
CYCLIC = {
    "tabletop-spring": ("theta",),
    "spherical-pendulum": ("phi",),
    "movable-incline": ("X",),
    "rolling-cylinder-wedge": ("X",),
}
MOVING_CONSTRAINT = {"rotating-parabola"}
# the rotating parabola too: in the lab frame its bead goes round the axis with the wire
THREE_D = {"spherical-pendulum", "helix-bead", "rotating-parabola"}


def test_all_scenes_are_registered_and_the_later_ones_marked():
    assert set(SCENES) == set(TABLE)
    assert {sid for sid, s in SCENES.items() if s.beyond_chapter} == BEYOND_CHAPTER


@pytest.mark.parametrize("scene_id", sorted(TABLE))
def test_coordinates_and_parameters(scene_id):
    s = SCENES[scene_id]
    coordinates, parameters = TABLE[scene_id]
    assert s.id == scene_id
    assert s.system.coordinates == coordinates
    assert tuple(p.name for p in s.system.parameters) == parameters


@pytest.mark.parametrize("scene_id", sorted(TABLE))
def test_texts_defaults_and_ranges(scene_id):
    s = SCENES[scene_id]
    assert s.title and s.summary and len(s.statement) > 80 and s.figure
    assert s.section.startswith("4.") and s.t_end > 0
    for p in s.system.parameters:
        assert p.unit and p.description, p.name
        assert p.min is not None and p.max is not None and p.min <= p.default <= p.max, p.name
    expected = {f"{q}{suffix}" for q in s.system.coordinates for suffix in ("", "_dot")}
    assert set(s.initial) == expected


@pytest.mark.parametrize("scene_id", sorted(TABLE))
def test_panels_are_what_the_scene_needs(scene_id):
    s = SCENES[scene_id]
    d = derivation(scene_id)
    # a scene declares only optional panels; the page adds every other panel its derivation supports
    assert set(s.panels) <= set(OPTIONAL) and len(set(s.panels)) == len(s.panels)
    panels = set(page_model(scene_id, None, PROCESS_SCENES)["panels"])
    assert "energy" in panels and "phase" in panels
    # the error-against-run-time chart only where the motion is not a polynomial in t
    assert ("work-precision" in panels) == (not constant_accelerations(scene_document(scene_id)))
    # 3-D only where the motion is 3-D; exactly one animation
    assert ("animation-3d" in panels) == (scene_id in THREE_D)
    assert ("animation-2d" in panels) != ("animation-3d" in panels)
    # h against E only where they differ
    assert ("h-vs-e" in panels) == (not d.energetics.h_equals_e)
    # momenta only with a conserved generalized momentum: a cyclic coordinate's, or a sum such as the total
    assert ("momenta" in panels) == any(c.name.startswith("p_") for c in d.energetics.conserved)
    assert set(d.energetics.cyclic) <= {c.name.removeprefix("p_") for c in d.energetics.conserved}
    if "effective-potential" in panels:
        assert d.reduction is not None
    if "small-oscillations" in panels:
        # an equilibrium that is stable, or stable for some parameters (stable is None)
        assert any(e.stable is not False for e in d.reduction.equilibria)
    assert ("constraint-force" in panels) == bool(s.system.constraints)


@pytest.mark.parametrize("scene_id", sorted(TABLE))
def test_cyclic_coordinates_and_h_equals_e(scene_id):
    en = derivation(scene_id).energetics
    assert en.cyclic == CYCLIC.get(scene_id, ())
    assert en.h_equals_e == (scene_id not in MOVING_CONSTRAINT)
    names = {c.name for c in en.conserved}
    assert {f"p_{c}" for c in en.cyclic} <= names
    if scene_id == "damped-pendulum":
        assert not names & {"h", "E"}
    elif scene_id in MOVING_CONSTRAINT:
        assert "h" in names and "E" not in names
    else:
        assert "E" in names


def test_the_pulleys_lengths_are_named():
    # issue 40: a textbook names its lengths; a bare number for a length (the middle mass once hung at
    # −(y₁ + y₂)/2 − 1, the end masses at x = ±1) is a form no reader could check the units of
    d = derivation("pulley")
    known = system_dimensions(d)
    for r in d.mechanics.positions:
        for x in r:
            assert not x.is_Number or x == 0, r
            assert not number_beside_units(x, known), r
