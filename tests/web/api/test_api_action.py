"""The action over the API: a scene and a user system, the documented answer, refusals with reasons."""

import math

import pytest

OSCILLATOR = {
    "coordinates": ["x"],
    "parameters": [{"name": "m", "value": 2}, {"name": "w", "value": 3}],
    "lagrangian": "m*x_dot**2/2 - m*w**2*x**2/2",
}
KEYS = {
    "epsilons", "action", "true", "first_variation", "second_variation", "kind", "conjugate_time", "error_estimate",
}  # fmt: skip


def test_scene_action_rises_on_both_sides_below_the_conjugate_time(client):
    body = {"initial": {"theta": 1.0, "theta_dot": 0.0}, "t_end": 0.6, "coordinate": "theta", "k": 1,
            "epsilons": [-0.2, 0.0, 0.2]}  # fmt: skip
    r = client.post("/api/scenes/simple-pendulum/action", json=body)
    assert r.status_code == 200
    a = r.json()
    assert KEYS <= set(a)
    assert a["action"][1] == a["true"] and a["action"][0] > a["true"] < a["action"][2]
    assert a["kind"] == "minimum" and a["conjugate_time"] is None and abs(a["first_variation"]) < 1e-8
    assert "return _L;" in a["preview"]["lagrangian"] and len(a["path"]["t"]) == len(a["path"]["L"])


def test_scene_action_is_a_saddle_past_the_focus(client):
    r = client.post("/api/scenes/simple-pendulum/action", json={"initial": {"theta": 0.01}, "t_end": 2.0})
    a = r.json()
    assert a["kind"] == "saddle" and a["second_variation"] < 0
    assert a["conjugate_time"] == pytest.approx(math.pi / math.sqrt(9.81), rel=1e-4)


@pytest.mark.slow
def test_user_system_action_runs_in_the_pool(client):
    T = 1.5
    r = client.post(
        "/api/action",
        json={"system": OSCILLATOR, "initial": {"x": 0.5}, "t_end": T, "epsilons": [0.1]},
    )
    assert r.status_code == 200, r.text
    a = r.json()
    assert a["action"][0] - a["true"] == pytest.approx(0.01 * (T / 2) * ((math.pi / T) ** 2 - 9), rel=1e-8)
    assert a["conjugate_time"] == pytest.approx(math.pi / 3, rel=1e-8) and a["kind"] == "saddle"


CYCLOTRON = {
    "coordinates": ["x", "y"],
    "parameters": [{"name": "m", "value": 1}, {"name": "w", "value": 2}],
    "lagrangian": "m*(x_dot**2 + y_dot**2)/2 + m*w*(x*y_dot - y*x_dot)/2",
}


@pytest.mark.slow
def test_cyclotron_focus_where_det_j_only_touches_zero(client):
    # a charge in a uniform field, ω_c = qB/m = 2: every path from a point meets it again after 2π/ω_c = π,
    # while det J = 2(1 - cos ω_c t)/ω_c² never turns negative
    body = {"system": CYCLOTRON, "initial": {"x": 0.3, "y_dot": 0.5}, "t_end": 4.0, "coordinate": "x"}
    a = client.post("/api/action", json=body).json()
    assert a["conjugate_time"] == pytest.approx(math.pi, rel=1e-8)
    short = client.post("/api/action", json={**body, "t_end": 3.0}).json()
    assert short["conjugate_time"] is None and short["kind"] == "minimum"


@pytest.mark.parametrize(
    ("body", "words"),
    [
        ({"t_end": 1, "coordinate": "phi"}, "unknown coordinate 'phi'; choose one of theta"),
        ({"t_end": 0}, "t_end must be positive"),
        ({"t_end": -2}, "t_end must be positive"),
        ({"t_end": 500}, "beyond this system's limit for the action, 100 s"),
        ({"t_end": 1, "epsilons": [0.1] * 102}, "at most 101"),
        ({"t_end": 1, "shape": "bump"}, "shapes are sine"),
        ({"t_end": 1, "k": 0}, "k must be a whole number from 1 to 50"),
        ({"t_end": 1, "initial": {"zeta": 1}}, "unknown initial value 'zeta'"),
    ],
)
def test_bad_requests_are_refused_with_a_reason(client, body, words):
    r = client.post("/api/scenes/simple-pendulum/action", json=body)
    assert r.status_code == 422 and words in r.json()["detail"], r.text


@pytest.mark.slow
def test_unknown_scene_and_user_refusals(client):
    assert client.post("/api/scenes/nope/action", json={"t_end": 1}).status_code == 404
    r = client.post("/api/action", json={"system": OSCILLATOR, "t_end": 1, "coordinate": "y"})
    assert r.status_code == 422 and "choose one of x" in r.json()["detail"]


def test_relax_finds_the_pendulum_path_and_a_saddle_past_the_focus(client):
    r = client.post("/api/scenes/simple-pendulum/action/relax", json={"t_end": 0.9, "initial": {"theta": 1.0}})
    assert r.status_code == 200, r.text
    a = r.json()
    assert a["kind"] == "minimum" and a["difference"] < 1e-6 and len(a["iterations"]) >= 2
    assert abs(a["shooting"]["velocity"]["theta_dot"]) < 1e-8  # the true path starts at rest
    r = client.post("/api/scenes/simple-pendulum/action/relax", json={"t_end": 1.5, "initial": {"theta": 1.0}})
    assert r.json()["kind"] == "saddle" and r.json()["negative_directions"] == 1


@pytest.mark.parametrize(
    ("body", "words"),
    [
        ({"t_end": 1, "steps": 2}, "steps must be a whole number from 4 to 1000"),
        ({"t_end": 1, "trial": {"theta": [0.0, 1.0]}}, "must hold steps + 1 = 201 values"),
        ({"t_end": 1, "start": {"phi": 0.0}, "end": {"theta": 0.0}}, "unknown coordinate 'phi' in start"),
        ({"t_end": 0}, "t_end must be in (0, 100] s"),
    ],
)
def test_bad_relax_requests_are_refused(client, body, words):
    r = client.post("/api/scenes/simple-pendulum/action/relax", json=body)
    assert r.status_code == 422 and words in r.json()["detail"], r.text


@pytest.mark.slow
def test_user_system_relax_runs_in_the_pool(client):
    r = client.post("/api/action/relax", json={"system": OSCILLATOR, "t_end": 0.5, "start": {"x": 0}, "end": {"x": 1}})
    assert r.status_code == 200, r.text
    a = r.json()
    # x(t) = sin(ωt)/sin(ωT) between x(0) = 0 and x(T) = 1
    t = a["t"][len(a["t"]) // 2]
    assert a["q"]["x"][len(a["t"]) // 2] == pytest.approx(math.sin(3 * t) / math.sin(1.5), abs=1e-7)


def _pendulum_trial(client, T, lift, k):
    """The true pendulum path from θ = 1 rad over [0, T] on 200 steps, lifted by lift · sin(kπt/T)."""
    a = client.post("/api/scenes/simple-pendulum/action/relax", json={"t_end": T, "initial": {"theta": 1.0}}).json()
    return [q + lift * math.sin(k * math.pi * t / T) for t, q in zip(a["t"], a["shooting"]["q"]["theta"], strict=True)]


def test_relax_says_when_it_found_the_true_path(client):
    T = 2.0
    trial = _pendulum_trial(client, T, 3.0, 1)
    a = client.post("/api/scenes/simple-pendulum/action/relax",
                    json={"t_end": T, "initial": {"theta": 1.0}, "trial": {"theta": trial}}).json()  # fmt: skip
    assert a["found"] is True and a["reasons"] == [] and a["advice"] == []
    assert a["converged"] and a["residual"] < 1e-11 and a["difference"] < 1e-6
    assert a["kind"] == "saddle"  # T = 2 s is past the kinetic focus t* = 1.07 s


def test_relax_refuses_a_path_no_motion_follows(client):
    # a trial path far above the true one (the report: the page certified a curve climbing to 8 rad)
    T = 2.0
    trial = _pendulum_trial(client, T, 12.0, 1)
    a = client.post("/api/scenes/simple-pendulum/action/relax",
                    json={"t_end": T, "initial": {"theta": 1.0}, "trial": {"theta": trial}}).json()  # fmt: skip
    assert a["found"] is False and not a["converged"]
    assert a["reasons"] == ["not-stationary", "disagrees"] and a["difference"] > 1.0
    assert a["advice"] == ["closer-trial", "shorter-t", "from-shooting"]
    # the shooting solution offered as the new start is the true motion, which starts at rest
    assert abs(a["shooting"]["velocity"]["theta_dot"]) < 1e-8
    start = client.post("/api/scenes/simple-pendulum/action/relax",
                        json={"t_end": T, "initial": {"theta": 1.0}, "trial": a["shooting"]["q"]}).json()  # fmt: skip
    assert start["found"] is True and start["difference"] < 1e-6
