"""Poincaré sections and measured normal modes over the API: scenes and user systems, refusals with reasons."""

import pytest

SYSTEM = {
    "coordinates": ["x", "y"],
    "parameters": [{"name": "k", "value": 2}],
    "kinetic": "x_dot**2/2 + y_dot**2/2",
    "potential": "x**2/2 + k*y**2/2",
}


def test_scene_section_has_points_on_the_energy_surface(client):
    r = client.post("/api/scenes/double-pendulum/poincare", json={"count": 3, "t_end": 40})
    assert r.status_code == 200
    body = r.json()
    assert body["axes"] == {"q": "theta1", "q_dot": "theta1_dot", "p": "p_theta1"}
    assert len(body["orbits"]) == 3 and all(len(o["q"]) == len(o["p"]) > 3 for o in body["orbits"])
    assert all(o["energy_drift"] < 1e-6 for o in body["orbits"])


@pytest.mark.parametrize(
    ("url", "body", "status", "words"),
    [
        ("/api/scenes/simple-pendulum/poincare", {}, 422, "two coordinates"),
        ("/api/scenes/double-pendulum/poincare", {"count": 99}, 422, "less than or equal to 12"),
        ("/api/scenes/double-pendulum/poincare", {"coordinate": "zz"}, 422, "choose one of theta1, theta2"),
        ("/api/scenes/nope/poincare", {}, 404, "known scenes"),
    ],
)
def test_bad_sections_are_refused_with_a_reason(client, url, body, status, words):
    r = client.post(url, json=body)
    assert r.status_code == status and words in r.text


def test_scene_modes_measured_match_predicted(client):
    r = client.get("/api/scenes/coupled-oscillators/modes")
    assert r.status_code == 200
    (eq,) = r.json()
    assert [m["omega_squared"] for m in eq["modes"]] == pytest.approx([10.0, 12.0])
    for m in eq["modes"]:
        assert m["measured"] == pytest.approx(m["predicted"], rel=0.01)


def test_scene_modes_follow_the_parameters(client):
    # coupled oscillators: omega^2 = k/m and k/m + 2 kappa/m; with k = 10, m = 1, kappa = 0.1: 10 and 10.2
    r = client.post("/api/scenes/coupled-oscillators/modes-at", json={"parameters": {"kappa": 0.1}})
    assert r.status_code == 200
    (eq,) = r.json()
    assert eq["parameters"] == {"m": 1.0, "k": 10.0, "kappa": 0.1, "d": 1.0}
    assert [m["predicted"] for m in eq["modes"]] == pytest.approx([10**0.5, 10.2**0.5])
    assert eq["modes"][1]["shape"] == pytest.approx({"x1": -1.0, "x2": 1.0})
    for m in eq["modes"]:
        assert m["measured"] == pytest.approx(m["predicted"], rel=1e-4)


@pytest.mark.parametrize(
    ("body", "status", "words"),
    [({"parameters": {"kappa": -5}}, 422, "outside its allowed range"), ({"parameters": {"zz": 1}}, 422, "unknown parameter")],
)
def test_scene_modes_refuse_bad_parameters(client, body, status, words):
    r = client.post("/api/scenes/coupled-oscillators/modes-at", json=body)
    assert r.status_code == status and words in r.text


@pytest.mark.slow
def test_user_system_modes_and_section_run_in_the_pool(client):
    r = client.post("/api/modes", json=SYSTEM)
    assert r.status_code == 200
    measured = sorted(m["measured"] for m in r.json()[0]["modes"])
    assert measured == pytest.approx([1.0, 2**0.5], rel=1e-3)
    r = client.post("/api/poincare", json={**SYSTEM, "energy": 1.0, "count": 2, "t_end": 30})
    assert r.status_code == 200 and len(r.json()["orbits"]) == 2
    r = client.post("/api/poincare", json={**SYSTEM, "coordinate": "z"})
    assert r.status_code == 422 and "choose one of x, y" in r.json()["detail"]
