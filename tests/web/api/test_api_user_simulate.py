"""POST /api/simulate: user systems simulated in the worker pool, with the scene endpoint's result JSON."""

import math

import numpy as np
import pytest
import sympy as sp

from app.numerics.methods import STIFF
from app.web.api import examples_user
from app.web.api.examples_user import DOUBLE_PENDULUM, FORCED_SPRING, SIMULATE_EXAMPLES, SIMULATE_REFUSED
from tests.numerics.systems import LOPSIDED_CHAIN, STIFF_SOFT_CHAIN
from tests.web.api.test_api_user_equilibria import CONE_BY_ITS_AXIS

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def simulate(client, body):
    response = client.post("/api/simulate", json=body)
    assert response.status_code == 200, response.text
    return response.json()


def test_forced_spring_matches_the_closed_form_solution(client):
    """An independent check: m x'' + b x' + k x = F cos(w t), solved by hand (dsolve) from x = 1 at rest."""
    body = {**FORCED_SPRING, "initial": {"x": 1.0, "x_dot": 0.0}, "t_end": 10.0, "samples": 101, "rtol": 1e-10}
    result = simulate(client, body)
    values = {p["name"]: p["value"] for p in FORCED_SPRING["parameters"]}
    t = sp.Symbol("t", real=True)
    x = sp.Function("x")
    m, k, b, F, w = (sp.Rational(str(values[n])) for n in ("m", "k", "b", "F", "w"))
    ode = sp.Eq(m * x(t).diff(t, 2) + b * x(t).diff(t) + k * x(t), F * sp.cos(w * t))
    exact = sp.lambdify(t, sp.dsolve(ode, x(t), ics={x(0): 1, x(t).diff(t).subs(t, 0): 0}).rhs, "math")
    error = max(abs(xs - exact(ts)) for ts, xs in zip(result["t"], result["state"]["x"], strict=True))
    assert error < 1e-7
    stats = result["stats"]
    # the reported error estimate is honest: not far below the true error, not wildly above it
    assert stats["error_estimate"] is not None and error / 10 <= stats["error_estimate"] + 1e-12
    # the force does work, so neither E nor h is conserved and none is reported as such
    assert result["conserved"] == {}


def test_double_pendulum_conserves_energy(client):
    body = SIMULATE_EXAMPLES["double-pendulum"]["value"]
    result = simulate(client, body)
    assert set(result["state"]) == {"theta1", "theta1_dot", "theta2", "theta2_dot"}
    assert len(result["t"]) == body["samples"] and result["t"][-1] == pytest.approx(body["t_end"])
    energy = result["energy"]
    assert max(abs(e - energy[0]) for e in energy) < 1e-6 * max(1.0, abs(energy[0]))
    assert "E" in result["conserved"]


def test_parameter_values_come_from_the_declaration(client):
    slow = {**FORCED_SPRING, "initial": {"x": 1.0}, "t_end": 2.0, "samples": 3, "forces": {}}
    stiff = {**slow, "parameters": [{**p, "value": 16.0} if p["name"] == "k" else p for p in slow["parameters"]]}
    # without forces, x(t) = cos(sqrt(k/m) t): a stiffer spring turns faster
    for spec, omega in ((slow, 2.0), (stiff, 4.0)):
        x_end = simulate(client, spec)["state"]["x"][-1]
        assert x_end == pytest.approx(math.cos(omega * 2.0), abs=1e-6)


def test_documented_simulation_is_what_the_api_answers(client):
    documented = examples_user.SIMULATE_RESPONSE
    result = simulate(client, SIMULATE_EXAMPLES["forced-spring"]["value"])
    assert result["t"] == documented["t"]
    for name, series in documented["state"].items():
        assert result["state"][name] == pytest.approx(series, rel=1e-9, abs=1e-12), name
    assert result["stats"]["method"] == documented["stats"]["method"]


def test_documented_simulation_refusal_is_what_the_api_answers(client):
    response = client.post("/api/simulate", json=SIMULATE_REFUSED["value"])
    assert response.status_code == 422
    assert response.json() == examples_user.ERROR_EXAMPLES[422]["simulate"]["response"]


@pytest.mark.parametrize(
    ("change", "where"),
    [
        ({"initial": {"x": 1.0}, "t_end": 1e9}, "t_end"),
        ({"initial": {"x": 1.0}, "samples": 10**7}, "samples"),
        ({"initial": {"x": 1.0}, "method": "Euler"}, "method"),
        ({"initial": {"x": 1.0}, "rtol": 0.5}, "rtol"),
        ({"initial": {"x": 1e300}}, "initial"),
        ({}, "initial"),
        ({"initial": {"x": 1.0}, "parameters": [{"name": "k", "value": 1e14}, "m", "b", "F", "w"]}, "parameters"),
        (
            {"initial": {"x": 1.0}, "lagrangian": "x_dot*x", "kinetic": None, "potential": None, "forces": {}},
            "lagrangian",
        ),
    ],
)
def test_bad_simulate_requests_are_located_422s(client, change, where):
    response = client.post("/api/simulate", json={**FORCED_SPRING, **change})
    assert response.status_code == 422, response.text[:300]
    answer = response.json()
    located = [*(answer.get("loc") or []), *(str(p) for e in answer.get("errors") or [] for p in e["loc"])]
    assert where in located or where in answer["detail"], answer


def test_nan_in_initial_state_is_refused(client):
    body = b'{"coordinates": ["x"], "parameters": ["k"], "lagrangian": "x_dot**2/2 - k*x**2/2", "initial": {"x": NaN}}'
    response = client.post("/api/simulate", content=body, headers={"content-type": "application/json"})
    assert response.status_code == 422 and "finite" in response.json()["detail"]


def test_hostile_expressions_are_refused_before_simulating(client):
    body = {**DOUBLE_PENDULUM, "potential": "__import__('os').system('true')", "initial": {"theta1": 1.0}}
    response = client.post("/api/simulate", json=body)
    assert response.status_code == 422 and response.json()["loc"] == ["body", "potential"]


@pytest.mark.parametrize("body", [LOPSIDED_CHAIN, STIFF_SOFT_CHAIN], ids=["masses 1e-9 and 1e9", "stiff-soft chain"])
def test_auto_runs_the_stiff_chains_with_the_compiled_radau(client, body):
    """Issue 47: both were refused (out of time); auto now steps over the fast mode with the compiled Radau IIA,
    the whole run, with an error estimate from the same method.  The light mass of the lopsided chain cannot
    start quiet to the last digit (its acceleration must be -0.75 m/s^2 at once, x1 0.5 + 4e-19 m): the fast
    velocity swings by 5e-10 m/s, five times atol, which no explicit method could follow for 10 s (2.4e9
    steps), so auto says that the implicit method damps it."""
    result = simulate(client, {**body, "samples": 201})
    stats = result["stats"]
    assert stats["method"] == STIFF and stats["path"] == "compiled", stats["reason"]
    assert stats["reason"].startswith("stiff") and stats["t_end_reached"] == body["t_end"]
    assert stats["error_estimate"] is not None and STIFF in stats["error_reference"]
    assert stats["steps"] < 1000
    if body is LOPSIDED_CHAIN:
        assert "far too many" in stats["reason"]
        assert len(stats["warnings"]) == 1 and "damps it" in stats["warnings"][0]
    else:
        assert not stats["warnings"]
    # the slow motion: x2 follows its own oscillator, x1 stays where the springs balance it
    x1, x2 = np.array(result["state"]["x1"]), np.array(result["state"]["x2"])
    balance = 0.5 if body is LOPSIDED_CHAIN else 1.0 / (1e8 + 1.0)
    assert np.abs(x1 - balance * x2).max() < 1e-6 * np.abs(x2).max()
    assert np.ptp(x2) > 0.5  # it does move: over a swing of the slow mode


# a bead on a cone of half-angle a about the vertical axis, apex down: r is its distance from the axis
CONE = CONE_BY_ITS_AXIS


def test_a_distance_declared_never_negative_ends_the_run_where_it_reaches_zero(client):
    """Released at rest, the bead slides straight down its generator: r̈ = −g sin a cos a, so it reaches the
    apex at t = √(2 r₀ / (g sin a cos a)); past it r would be negative, which the declaration rules out."""
    body = {**CONE, "initial": {"r": 1.0}, "t_end": 10.0, "samples": 401, "rtol": 1e-10}
    doc = simulate(client, body)
    event = doc["stats"]["event"]
    assert event is not None and event["name"] == "r reaches 0"
    assert "r ≥ 0" in event["message"] and "run ends" in event["message"]
    arrival = math.sqrt(2.0 / (9.81 * math.sin(0.5) * math.cos(0.5)))
    assert event["t"] == pytest.approx(arrival, rel=1e-6)
    assert doc["t"][-1] == event["t"] and min(doc["state"]["r"]) >= -1e-9
    # a system without a declared distance runs to its end
    free = simulate(client, {**body, "nonnegative": []})
    assert free["stats"]["event"] is None and min(free["state"]["r"]) < -1.0
