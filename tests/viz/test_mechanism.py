"""The scenes' drawings: geometry that must hold whatever the run (evaluated from the spec's trees)."""

import math

import pytest
import sympy as sp

from app.engine.document.model import ConstraintForce
from app.engine.document.trees import of_sympy
from app.scenes import SCENES
from app.scenes.beads import WIRE_REACH
from app.viz.exprtree import evaluate
from app.viz.mechanism import FAMILIES, mechanism


def spec_of(scene_id, forces=()):
    s = SCENES[scene_id]
    particles = [(p.label, p.position) for p in s.system.particles]
    return mechanism(s.family, particles, s.system.coordinates, "animation-3d" in s.panels, forces=forces)


def env_of(scene_id, **state):
    s = SCENES[scene_id]
    env = {p.name: p.default for p in s.system.parameters} | {"t": 0.0}
    for q in s.system.coordinates:
        env[f"qmin_{q}"], env[f"qmax_{q}"] = -3.0, 4.0
    return env | state


def at(spec, index, env):
    return [evaluate(c, env) for c in spec["points"][index]["xyz"]]


@pytest.mark.slow
@pytest.mark.parametrize("y1, y2", [(0.0, 0.0), (2.5, -3.0), (-1.0, 3.7)])
def test_pulley_strings_are_vertical_and_keep_their_length(y1, y2):
    spec = spec_of("pulley")
    env = env_of("pulley", y1=y1, y2=y2)
    strings = [link for link in spec["links"] if link["style"] == "string"]
    assert len(strings) == 4 and len(spec["wheels"]) == 3
    total = 0.0
    for link in strings:
        (xa, za), (xb, zb) = at(spec, link["from"], env), at(spec, link["to"], env)
        assert xa == pytest.approx(xb, abs=1e-12)  # the radius W/3 makes every straight piece vertical
        total += abs(za - zb)
    # the straight pieces' total changes by nothing as the masses move (the wraps are fixed arcs)
    rest = env_of("pulley", y1=0.0, y2=0.0)
    total0 = sum(abs(at(spec, s["from"], rest)[1] - at(spec, s["to"], rest)[1]) for s in strings)
    assert total == pytest.approx(total0, rel=1e-12)


@pytest.mark.slow
def test_pulley_is_as_wide_as_a_fraction_of_its_motion():
    spec = spec_of("pulley")
    env = env_of("pulley", y1=0.0, y2=0.0)  # extents -3..4 on both: W = 0.3 * 14 = 4.2
    assert at(spec, 1, env)[0] - at(spec, 0, env)[0] == pytest.approx(8.4)


def test_incline_ramp_starts_at_the_foot_and_holds_the_block():
    spec = spec_of("incline-block")
    env = env_of("incline-block", X=2.0)
    labels = [p["label"] for p in spec["points"]]
    foot, top = labels.index("foot"), labels.index("top")
    assert at(spec, foot, env) == [0.0, 0.0]
    a = env["alpha"]
    block, summit = at(spec, 0, env), at(spec, top, env)
    # the block lies on the ramp's slope, below its top
    assert block[1] == pytest.approx(block[0] * math.tan(a)) and summit[1] == pytest.approx(summit[0] * math.tan(a))
    assert summit[0] > block[0]
    assert spec["solids"] == [{"label": "ramp", "corners": [foot, top, labels.index("corner")]}]
    assert [c["style"] for c in spec["curves"]] == ["ground"]


def test_rotating_parabola_is_drawn_turning_in_the_lab_frame():
    spec = spec_of("rotating-parabola")
    assert spec["dim"] == 3 and "Lab frame" in spec["caption"]
    wire = next(c for c in spec["curves"] if c["label"] == "wire")
    assert wire["moving"]
    env = env_of("rotating-parabola", rho=0.5)
    quarter = env | {"t": math.pi / (2 * env["omega"])}
    x0, y0, _ = at(spec, 0, env)
    x1, y1, _ = at(spec, 0, quarter)
    assert (x0, y0) == pytest.approx((0.5, 0.0)) and (x1, y1) == pytest.approx((0.0, 0.5), abs=1e-12)


@pytest.mark.parametrize("reach", [0.2, 32.0])
def test_the_turning_wire_is_drawn_to_its_ends_however_far_the_run_goes(reach):
    # prof-m 8: a bead flung out to ρ = 32 m drew a 1000 m-tall wire; the wire is drawn to its ends, ρ = ±1 m
    spec = spec_of("rotating-parabola")
    env = env_of("rotating-parabola") | {"qmin_rho": -reach, "qmax_rho": reach}
    wire = next(c for c in spec["curves"] if c["label"] == "wire")
    assert (evaluate(wire["from"], env), evaluate(wire["to"], env)) == (-WIRE_REACH, WIRE_REACH)
    rim = next(c for c in spec["curves"] if c["label"] == "rim")
    assert evaluate(rim["xyz"][2], env | {"s": 0.0}) == pytest.approx(env["alpha"] * WIRE_REACH**2)


def test_constraint_forces_become_arrows_on_their_particle():
    alpha = sp.Symbol("alpha")
    unit = [-sp.sin(alpha), sp.Integer(0), sp.cos(alpha)]  # as the document carries it: trees the engine wrote
    forces = [
        ConstraintForce.model_construct(
            name="normal force", particle=1, direction_trees=[of_sympy(e) for e in unit], acts_on=[]
        )
    ]
    spec = spec_of("incline-block", forces)
    assert spec["forces"] == [
        {"name": "normal force", "on": 0, "direction": [["neg", ["sin", "alpha"]], ["cos", "alpha"]]}
    ]


@pytest.mark.slow
@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_every_family_has_a_caption_of_what_it_draws(scene_id):
    assert SCENES[scene_id].family in FAMILIES
    spec = spec_of(scene_id)
    assert spec is not None and spec["caption"]
    assert "arrow" not in spec["caption"]
    # a caption names a centre of mass only where the drawing marks one (the rod's, of the physical pendulum)
    marked = any(point["label"] == "centre of mass" for point in spec["points"])
    assert "centre of mass" not in spec["caption"] or marked
    springs = [link for link in spec["links"] if link["style"] == "spring"]
    assert bool(springs) == (scene_id in {"tabletop-spring", "rail-two-body", "coupled-oscillators"})


def _ranges(name, lo, hi):
    return {f"qmin_{name}": lo, f"qmax_{name}": hi}


ALPHAS = [0.01, 0.3, 0.5, 1.0, 1.5]  # across the scenes' allowed range of α


@pytest.mark.parametrize("alpha", ALPHAS)
@pytest.mark.parametrize(("dmin", "dmax"), [(0.0, 0.0), (0.0, 2.5), (-1.0, 3.0), (-3.0, -0.5), (0.2, 8.0)])
def test_the_wedge_holds_the_block_on_its_slope_wherever_the_run_takes_it(alpha, dmin, dmax):
    spec = spec_of("movable-incline")
    labels = [p["label"] for p in spec["points"]]
    assert labels[:2] == ["wedge", "block"]  # the names sit by their own bodies
    block = spec["points"][1]
    assert block["block"] == ["neg", "alpha"] and block["base"] == "ahead"  # the block lies down the slope from D
    top, foot, corner = (labels.index(c) for c in ("wedge top", "wedge foot", "wedge corner"))
    assert spec["solids"] == [{"label": "wedge", "corners": [top, foot, corner]}]
    for X in (-2.0, 0.0, 1.5):
        env = env_of("movable-incline", X=X, alpha=alpha) | _ranges("D", dmin, dmax) | _ranges("X", -2.0, 1.5)
        (tx, tz), (fx, fz), (cx, cz) = (at(spec, i, env) for i in (top, foot, corner))
        assert cz == pytest.approx(fz) and cx == pytest.approx(tx)  # a right-angled wedge standing on its base
        slope = math.hypot(fx - tx, fz - tz)
        floor = next(c for c in spec["curves"] if c["label"] == "floor")
        assert evaluate(floor["xyz"][1], env | {"s": 0.0}) == pytest.approx(fz)  # the floor is the wedge's base
        # the wedge's own point is inside the triangle: right of the vertical side, above the base, under the slope
        wx, wz = at(spec, 0, env)
        assert tx < wx < fx and fz < wz < tz - (wx - tx) * math.tan(alpha)
        for D in [dmin + (dmax - dmin) * f for f in (0.0, 0.5, 1.0)]:
            bx, bz = at(spec, 1, env | {"D": D})
            along = math.hypot(bx - tx, bz - tz)
            # on the slope line, between the top corner and the foot, with room below it for the block's base
            assert abs((bx - tx) * (fz - tz) - (bz - tz) * (fx - tx)) <= 1e-9 * slope**2
            assert bx >= tx - 1e-12 and along <= slope - 0.15 * abs(dmax) - 0.5 + 1e-9
            assert bz >= fz  # never below the floor


@pytest.mark.parametrize("alpha", ALPHAS)
@pytest.mark.parametrize(("smin", "smax", "r"), [(0.0, 0.0, 0.3), (0.0, 4.0, 0.3), (-1.0, 3.0, 0.05), (0.0, 2.0, 2.0)])
def test_the_rolling_cylinder_rests_on_the_wedges_slope_and_turns_as_it_rolls(alpha, smin, smax, r):
    spec = spec_of("rolling-cylinder-wedge")
    labels = [p["label"] for p in spec["points"]]
    assert labels[:2] == ["wedge", "cylinder"]
    (wheel,) = spec["wheels"]
    assert wheel["at"] == 1 and wheel["wrap"] == "none"  # the cylinder is the wheel, and no string wraps it
    top, foot = labels.index("wedge top"), labels.index("wedge foot")
    for X in (-2.0, 0.0, 1.5):
        env = (
            env_of("rolling-cylinder-wedge", X=X, alpha=alpha, r=r) | _ranges("s", smin, smax) | _ranges("X", -2.0, 1.5)
        )
        (tx, tz), (fx, fz) = at(spec, top, env), at(spec, foot, env)
        slope = math.hypot(fx - tx, fz - tz)
        for s in [smin + (smax - smin) * f for f in (0.0, 0.5, 1.0)]:
            here = env | {"s": s}
            cx, cz = at(spec, 1, here)
            assert evaluate(wheel["radius"], here) == pytest.approx(r)
            # the centre is r above the slope line (on the side away from the wedge), its foot on the slope between
            # the top corner and the wedge's foot, with a diameter to spare
            above = ((cz - tz) * (fx - tx) - (cx - tx) * (fz - tz)) / slope
            assert above == pytest.approx(r)
            along = ((cx - tx) * (fx - tx) + (cz - tz) * (fz - tz)) / slope
            assert along == pytest.approx(s - min(smin, 0.0)) and along <= slope - r
            # rolling down the slope (to the right) it turns clockwise: by −s/r, counter-clockwise in the view
            assert evaluate(wheel["turn"], here) == pytest.approx(-s / r)


@pytest.mark.parametrize("alpha", ALPHAS)
@pytest.mark.parametrize("xmax", [0.0, 0.5, 3.0, 10.0])
def test_the_ramp_holds_the_block_from_its_foot_to_the_top_of_the_run(alpha, xmax):
    spec = spec_of("incline-block")
    labels = [p["label"] for p in spec["points"]]
    assert spec["points"][0]["block"] == "alpha" and spec["points"][0]["base"] == "ahead"  # it lies up the slope
    foot, top = labels.index("foot"), labels.index("top")
    env = env_of("incline-block", alpha=alpha) | _ranges("X", 0.0, xmax)
    (fx, fz), (tx, tz) = at(spec, foot, env), at(spec, top, env)
    slope = math.hypot(tx - fx, tz - fz)
    for X in [xmax * f for f in (0.0, 0.5, 1.0)]:
        bx, bz = at(spec, 0, env | {"X": X})
        # at X = 0 the block's base starts at the foot: nothing of it below the floor; above, room for the block
        assert bz >= fz - 1e-12 and bx >= fx - 1e-12
        assert math.hypot(bx - fx, bz - fz) <= slope - 0.15 * xmax - 0.5 + 1e-9


@pytest.mark.slow
def test_the_string_pulls_every_mass_it_holds():
    from app.service.chapter.derivations import scene_document

    spec = spec_of("pulley", scene_document("pulley").constraint_forces)
    tension = [f for f in spec["forces"] if f["name"] == "string tension"]
    assert sorted(f["on"] for f in tension) == [0, 1, 2]  # the left, right and middle masses
    env = env_of("pulley", y1=0.3, y2=-0.2)
    for f in tension:
        up = [evaluate(c, env) for c in f["direction"]]
        assert up == pytest.approx([0.0, 1.0])  # every piece of string pulls upward
        # the middle mass hangs from the wheel on two pieces of string: twice the tension
        assert evaluate(f["ratio"], env) == pytest.approx(2.0) if f["on"] == 2 else "ratio" not in f


def test_the_helix_opens_on_a_view_that_shows_its_turns():
    """prof-e 14: side-on, the helix looked like a flat wave. Looking down at pitch p, a turn of radius R is an
    ellipse 2R sin p tall and the turns lie (2π/α) cos p apart: the ellipse must be at least half the spacing."""
    view = spec_of("helix-bead").get("view")
    assert view is not None, "the helix needs its own opening view"
    env = env_of("helix-bead")
    tall = 2 * env["R"] * math.sin(view["pitch"])
    apart = 2 * math.pi / env["alpha"] * math.cos(view["pitch"])
    assert tall >= 0.5 * apart, (tall, apart)


def test_a_surface_given_only_through_the_coordinates_is_said_to_be_undrawn():
    # prof-n 9: a particle inside a cone is drawn as a ball in space with no cone; the caption says why
    cone = [("ball", ("r*sin(a)*cos(phi)", "r*sin(a)*sin(phi)", "r*cos(a)"))]
    spec = mechanism("", cone, ["r", "phi"], True, defaults={"a": 0.5, "r": 1.0, "phi": 0.0})
    assert spec["caption"].endswith(
        "The surface the coordinates hold a body on is not drawn: it is given only through the coordinates."
    )
    wire = [("bead", ("x", "0", "x**2"))]
    spec = mechanism("", wire, ["x"], False, defaults={"x": 0.5})
    assert "The curve the coordinates hold a body on is not drawn" in spec["caption"]
    # a free particle, and a pendulum whose rod shows what holds it, have nothing undrawn
    free = mechanism("", [("ball", ("x", "y", "z"))], ["x", "y", "z"], True, defaults={})
    rod = mechanism("", [("bob", ("l*sin(theta)", "0", "-l*cos(theta)"))], ["theta"], False, defaults={"l": 1.0})
    assert "not drawn" not in free["caption"] and "not drawn" not in rod["caption"]


@pytest.mark.slow
def test_a_wheel_given_its_turning_angle_carries_it_and_one_without_does_not(monkeypatch):
    from app.viz import mechanism as module

    # a disc of radius R rolling along x without slipping: its centre at x, turned by −x/R (clockwise as it rolls)
    family = module.Family(
        points=(("disc", ("x", "0", "R")),),
        wheels=(("disc", "R", "none", "-x/R"),),
    )
    monkeypatch.setitem(module.FAMILIES, "rolling-test", family)
    spec = mechanism("rolling-test", [("disc", ("x", "0", "R"))], ("x",), False)
    (wheel,) = spec["wheels"]
    assert wheel["wrap"] == "none"
    assert evaluate(wheel["turn"], {"x": 0.5, "R": 0.25, "t": 0.0}) == pytest.approx(-2.0)
    assert "turn" not in spec_of("pulley")["wheels"][0]


@pytest.mark.parametrize("z", [0.0, 0.7, -1.2])
def test_the_massive_pulley_turns_with_its_string_and_its_strands_hang_from_the_rim(z):
    spec = spec_of("massive-pulley")
    env = env_of("massive-pulley", z=z)
    (wheel,) = spec["wheels"]
    # the string does not slip: the rim turns through the string's travel, R × (the turning angle) = z
    assert evaluate(wheel["turn"], env) * env["R"] == pytest.approx(z)
    assert wheel["wrap"] == "top" and evaluate(wheel["radius"], env) == pytest.approx(env["R"])
    strings = [link for link in spec["links"] if link["style"] == "string"]
    assert len(strings) == 2
    hanging = 0.0
    for link in strings:
        (xa, za), (xb, zb) = at(spec, link["from"], env), at(spec, link["to"], env)
        # vertical, from one side of the rim
        assert xa == pytest.approx(xb, abs=1e-12) and abs(xa) == pytest.approx(env["R"])
        hanging += za - zb
    # what one strand gains the other loses: the two hang 2d in all whatever z
    assert hanging == pytest.approx(2 * env["d"])


@pytest.mark.slow
def test_the_physical_pendulum_is_a_bar_with_its_centre_of_mass_marked():
    # prof-q 9: a thin rod with a ball at its middle read as a bob on a string; the rod is a body (a bar) from the
    # pivot to its free end, and the point at its middle is its centre of mass, drawn as a mark on it
    spec = spec_of("physical-pendulum")
    labels = [p["label"] for p in spec["points"]]
    (bar,) = spec["links"]
    assert bar["style"] == "bar" and (labels[bar["from"]], labels[bar["to"]]) == ("pivot", "end")
    (centre,) = [p for p in spec["points"] if p["mass"]]
    assert centre["label"] == "centre of mass" and centre["centre"] is True
    env = env_of("physical-pendulum", theta=0.7)
    ends = [at(spec, k, env) for k in (bar["from"], bar["to"])]
    assert at(spec, 0, env) == pytest.approx([(a + b) / 2 for a, b in zip(*ends, strict=True)])
    # no other scene's body is drawn as a centre mark, nor joined by a bar
    others = [spec_of(s) for s in sorted(SCENES) if s != "physical-pendulum"]
    assert not any(p.get("centre") for o in others for p in o["points"])
    assert not any(link["style"] == "bar" for o in others for link in o["links"])
