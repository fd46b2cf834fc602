"""Controls: useful slider ranges inside the allowed ones, log scales, and marks where the motion changes kind."""

import math

import pytest
import sympy as sp

from app.scenes import SCENES
from app.scenes.beads import WIRE_REACH
from app.service.chapter.derivations import PROCESS_SCENES, derivation_document
from app.viz.control_ranges import useful_range
from app.web.pages.chapter import page_model


def control(scene_id, name):
    m = page_model(scene_id, None, PROCESS_SCENES)
    return next(c for c in m["parameters"] + m["initial"] if c["name"] == name)


def test_damping_slider_is_logarithmic_and_marks_critical_damping():
    b = control("damped-pendulum", "b")
    p = {k: v.default for k, v in ((q.name, q) for q in SCENES["damped-pendulum"].system.parameters)}
    critical = 2 * p["m"] * p["R"] ** 2 * math.sqrt(p["g"] / p["R"])  # b_c = 2 M ω, M = m R², ω² = g/R
    assert [float(t["value"]) for t in b["ticks"]] == pytest.approx([critical], rel=1e-5)
    assert b["log"] and float(b["min"]) == 0 and float(b["max"]) == 100
    lo, hi = float(b["slider_min"]), float(b["slider_max"])
    assert 0 < lo < p["b"] < critical < hi < 100 and hi / lo >= 50


def test_the_rotating_wire_marks_where_the_bottom_turns_unstable():
    omega = control("rotating-parabola", "omega")
    p = {q.name: q.default for q in SCENES["rotating-parabola"].system.parameters}
    assert [float(t["value"]) for t in omega["ticks"]] == pytest.approx([math.sqrt(2 * p["g"] * p["alpha"])], rel=1e-5)
    # in the order of the LaTeX the page prints for the same ω² (issue 40: SymPy's 2αg was the label's)
    w2 = derivation_document("rotating-parabola")["effective_potential"]["equilibria"][0]["omega_squared"]
    assert w2["latex"] == r"2 g \alpha - \omega^{2}" and w2["unicode"] == "2gα − ω²"
    assert omega["ticks"][0]["label"] == "2gα − ω² = 0: ρ = 0 changes stability"


def test_the_start_on_the_turning_wire_is_between_its_ends():
    # the set-up ends where ρ² reaches WIRE_REACH²: a start beyond an end of the wire is not on the wire
    rho = control("rotating-parabola", "rho")
    assert (float(rho["min"]), float(rho["max"])) == (-WIRE_REACH, WIRE_REACH)
    assert rho["allowed"] == "−1 to 1 m"
    # the foot of the ramp (X ≥ 0) still opens the incline's slider at 0
    assert float(control("incline-block", "X")["min"]) == 0


def test_the_pendulums_rate_marks_the_separatrix():
    rate = control("simple-pendulum", "theta_dot")
    p = {q.name: q.default for q in SCENES["simple-pendulum"].system.parameters}
    theta0 = SCENES["simple-pendulum"].initial["theta"]
    # ½ m R² θ̇₀² + m g R (1 − cos θ₀) = 2 m g R
    v = math.sqrt(2 * p["g"] / p["R"] * (1 + math.cos(theta0)))
    assert sorted(float(t["value"]) for t in rate["ticks"]) == pytest.approx([-v, v], rel=1e-5)
    assert [t["text"] for t in rate["ticks"] if t["text"]] == [
        f"±{v:.4g} rad/s (separatrix from θ(0) = {theta0:.4g} rad: just reaches θ = π)"
    ]
    assert float(rate["max"]) >= 1.5 * v


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_sliders_stay_inside_the_allowed_range(scene_id):
    for c in page_model(scene_id, None, PROCESS_SCENES)["parameters"]:
        assert (
            float(c["min"]) <= float(c["slider_min"]) <= float(c["value"]) <= float(c["slider_max"]) <= float(c["max"])
        )
        assert all(float(c["min"]) <= float(t["value"]) <= float(c["max"]) for t in c["ticks"])


def test_useful_range_is_a_decade_about_the_default():
    assert useful_range(1.0, 0.01, 100.0) == (0.1, 10.0, True)
    assert useful_range(-2.0, -10.0, 10.0) == (-10.0, 10.0, False)  # a signed quantity keeps its range


@pytest.mark.slow
def test_work_precision_only_where_the_reference_is_not_a_polynomial():
    for scene_id in SCENES:
        shown = "work-precision" in page_model(scene_id, None, PROCESS_SCENES)["panels"]
        # a coordinate is a name of the acceleration's expression, not a letter in its text (the s of sin α)
        coordinates = set(derivation_document(scene_id)["coordinates"])
        constant = all(
            not {s.name for s in sp.sympify(a["sympy"]).free_symbols} & coordinates
            for a in derivation_document(scene_id)["accelerations"].values()
        )
        assert shown == (not constant), scene_id
