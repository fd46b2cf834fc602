"""POST /api/scenes/{id}/simulate and GET /api/scenes/{id}/work-precision follow their contract."""

import pytest

from app.numerics import limits
from app.numerics.methods import STIFF
from app.scenes import SCENES
from app.scenes.beads import WIRE_REACH
from app.service.answers import Answers
from app.service.simulations import work_precision
from app.service.simulations.simulation import Gates
from app.web.api.deps import remembered_answers, simulation_gates


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_simulate_every_scene(client, scene_id):
    response = client.post(f"/api/scenes/{scene_id}/simulate", json={"initial": {}, "samples": 40, "t_end": 1.0})
    assert response.status_code == 200, response.text
    doc = response.json()
    scene = SCENES[scene_id]
    assert len(doc["t"]) == 40 and doc["t"][-1] == 1.0
    names = [*scene.system.coordinates, *(f"{q}_dot" for q in scene.system.coordinates)]
    assert set(doc["state"]) == set(names)
    assert all(len(v) == 40 for v in doc["state"].values())
    assert len(doc["energy"]) == len(doc["hamiltonian"]) == 40
    assert set(doc["stats"]) >= {
        "method",
        "reason",
        "steps",
        "rhs_evaluations",
        "wall_time_s",
        "error_estimate",
        "max_energy_drift",
        "max_hamiltonian_drift",
        "warnings",
        "t_end_reached",
    }
    assert isinstance(doc["conserved"], dict) and isinstance(doc["constraint_forces"], dict)


@pytest.mark.slow
def test_requested_method_and_tolerances(client):
    body = {"initial": {"theta": 2.0}, "method": "RK45", "rtol": 1e-6, "atol": 1e-9, "samples": 11, "t_end": 2.0}
    doc = client.post("/api/scenes/simple-pendulum/simulate", json=body).json()
    assert doc["stats"]["method"] == "RK45" and doc["stats"]["reason"] == "requested"
    assert doc["state"]["theta"][0] == 2.0


@pytest.mark.parametrize(
    "raw",
    [
        '{"initial": {"theta": NaN}}',
        '{"initial": {"theta": Infinity}}',
        '{"initial": {"theta": 1.0}, "parameters": {"g": -Infinity}}',
        '{"initial": {"theta": 1.0}, "t_end": NaN}',
    ],
)
def test_non_finite_numbers_are_422(client, raw):
    response = client.post(
        "/api/scenes/simple-pendulum/simulate", content=raw, headers={"content-type": "application/json"}
    )
    assert response.status_code == 422
    assert "finite" in response.json()["detail"]


@pytest.mark.parametrize(
    "body, where",
    [
        ({}, "initial"),
        ({"initial": {}, "samples": limits.SAMPLES_MAX + 1}, "samples"),
        ({"initial": {}, "t_end": -1}, "t_end"),
        ({"initial": {}, "t_end": limits.T_END_MAX * 10}, "t_end"),
        ({"initial": {}, "rtol": 0.5}, "rtol"),
        ({"initial": {}, "method": "Euler"}, "method"),
        ({"initial": {}, "extra": 1}, "extra"),
        ({"initial": {}, "parameters": {"m": 1e300}}, "parameters"),
    ],
)
def test_out_of_range_requests_are_422(client, body, where):
    response = client.post("/api/scenes/simple-pendulum/simulate", json=body)
    assert response.status_code == 422
    assert where in response.json()["detail"]


def test_scene_ranges_and_names_are_checked(client):
    response = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "parameters": {"R": 0}})
    assert response.status_code == 422
    assert "parameters.R = 0 is outside its allowed range [0.05, 100.0] m" in response.json()["detail"]
    response = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {"phi": 1}})
    assert response.status_code == 422 and "allowed: theta, theta_dot" in response.json()["detail"]


def test_unknown_scene_is_404(client):
    assert client.post("/api/scenes/nope/simulate", json={"initial": {}}).status_code == 404
    assert client.get("/api/scenes/nope/work-precision").status_code == 404


@pytest.mark.slow
def test_too_much_work_is_422_not_a_hang(client, services, override):
    override(simulation_gates, Gates(offload=services.scenes.run, wall_seconds=0.3))  # a short time budget
    body = {"initial": {}, "parameters": {"k": 1000}, "t_end": 1000, "method": "LSODA", "rtol": 1e-10}
    response = client.post("/api/scenes/tabletop-spring/simulate", json=body)
    assert response.status_code == 422
    assert response.json()["detail"].startswith("too much work for LSODA")


def test_the_incline_run_ends_at_the_foot_of_the_ramp(client):
    doc = client.post("/api/scenes/incline-block/simulate", json={"initial": {}}).json()
    event = doc["stats"]["event"]
    assert event["name"] == "foot of the ramp" and event["message"].startswith("The block reached the foot")
    assert doc["t"][-1] == event["t"] and min(doc["state"]["X"]) >= -1e-9
    other = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "samples": 20}).json()
    assert other["stats"]["event"] is None


def test_the_bead_flung_out_leaves_the_wire_at_its_end(client):
    # ω = 8 rad/s > √(2gα) = 4.43 rad/s: the bead runs outward and the run ends at the wire's end, ρ = 1 m
    body = {"initial": {"rho": 0.15, "rho_dot": 0.0}, "parameters": {"omega": 8.0}}
    doc = client.post("/api/scenes/rotating-parabola/simulate", json=body).json()
    event = doc["stats"]["event"]
    assert event["name"] == "end of the wire" and event["message"].startswith("The bead reached the end of the wire")
    assert doc["t"][-1] == event["t"] == pytest.approx(0.5073, abs=1e-4)
    assert doc["state"]["rho"][-1] == pytest.approx(WIRE_REACH, abs=1e-6) and max(doc["state"]["rho"]) <= WIRE_REACH + 1e-9
    # on the other branch the same, at ρ = −1 m
    body["initial"]["rho"] = -0.15
    doc = client.post("/api/scenes/rotating-parabola/simulate", json=body).json()
    assert doc["stats"]["event"]["name"] == "end of the wire" and doc["state"]["rho"][-1] == pytest.approx(-WIRE_REACH, abs=1e-6)
    # below the critical rate the bead swings about the bottom and stays on the wire for the whole run
    body = {"initial": {"rho": 0.15, "rho_dot": 0.0}, "parameters": {"omega": 4.0}}
    assert client.post("/api/scenes/rotating-parabola/simulate", json=body).json()["stats"]["event"] is None


@pytest.mark.slow
def test_runaway_stops_with_a_message(client):
    # an inverted oscillator, ẍ = x: x grows as e^t with nothing to end it
    body = {"coordinates": ["x"], "parameters": [], "lagrangian": "x_dot**2/2 + x**2/2", "initial": {"x": 0.5},
            "t_end": 1000, "samples": 500}  # fmt: skip
    doc = client.post("/api/simulate", json=body).json()
    assert doc["stats"]["complete"] is False and doc["stats"]["t_end_reached"] < 1000
    assert len(doc["t"]) < 500 and any("ran away" in w for w in doc["stats"]["warnings"])


@pytest.mark.slow
def test_work_precision_endpoint(client, monkeypatch, tmp_path, override):
    monkeypatch.setattr(work_precision, "SWEEP", [1e-3, 1e-6])
    override(remembered_answers, Answers.start(tmp_path))  # the route's caches, empty, on a disk of their own
    doc = client.get("/api/scenes/incline-block/work-precision").json()
    # the report went to the app's cache, not to a module's
    assert [p.name.startswith("incline-block-") for p in (tmp_path / "work-precision").iterdir()] == [True]
    assert "constant-acceleration" in doc["reference"]
    methods = {run["method"] for run in doc["runs"]}
    assert len(methods) >= 4 and {STIFF, "Radau"} <= methods  # the compiled Radau IIA beside scipy's
    for run in doc["runs"]:
        assert set(run) >= {"method", "rtol", "error", "wall_time_s", "rhs_evaluations"}


def test_openapi_lists_the_routes(client):
    paths = client.get("/openapi.json").json()["paths"]
    assert "post" in paths["/api/scenes/{scene_id}/simulate"]
    assert "get" in paths["/api/scenes/{scene_id}/work-precision"]


def test_display_precision_rounds_the_series_not_the_stats(client):
    body = {"initial": {"theta": 2.0}, "samples": 60, "t_end": 3.0}
    full = client.post("/api/scenes/simple-pendulum/simulate", json=body)
    display = client.post("/api/scenes/simple-pendulum/simulate", json={**body, "precision": "display"})
    assert full.status_code == display.status_code == 200
    a, b = full.json(), display.json()
    for name in ("theta", "theta_dot"):
        for x, r in zip(a["state"][name], b["state"][name], strict=True):
            assert abs(r - x) <= 5e-7 * abs(x)
            assert float(f"{x:.7g}") == r
    assert a["stats"]["error_estimate"] == b["stats"]["error_estimate"]
    assert a["t"] == b["t"]
    # E and h keep every digit: their change since t = 0 is plotted, and rounded it would be a staircase
    assert a["energy"] == b["energy"] and a["hamiltonian"] == b["hamiltonian"]
    assert len(display.content) < 0.85 * len(full.content)


def test_precision_must_be_full_or_display(client):
    response = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "precision": "half"})
    assert response.status_code == 422 and "precision" in response.json()["detail"]


@pytest.mark.parametrize("coding", ["zstd", "gzip"])
def test_api_responses_are_compressed_for_clients_that_accept_it(client, coding):
    url = "/api/scenes/simple-pendulum/simulate"
    packed = client.post(url, json={"initial": {}}, headers={"Accept-Encoding": coding})
    plain = client.post(url, json={"initial": {}}, headers={"Accept-Encoding": "identity"})
    assert packed.headers["content-encoding"] == coding and "content-encoding" not in plain.headers
    assert packed.headers["vary"] == plain.headers["vary"] == "Accept-Encoding"
    assert packed.json()["t"] == plain.json()["t"]
    assert int(packed.headers["content-length"]) < len(plain.content) / 2


def test_a_request_while_kernels_compile_is_answered_by_scipy(client, services, override):
    # the gates of a server that warms up in the background, where nothing is compiled yet
    nothing_compiled = Gates(offload=services.scenes.run, answer_while_compiling=True, compiled=lambda m, s: False)
    override(simulation_gates, nothing_compiled)
    response = client.post("/api/scenes/damped-pendulum/simulate", json={"initial": {}, "samples": 30})
    assert response.status_code == 200, response.text
    stats = response.json()["stats"]
    assert stats["path"] == "scipy-fallback" and stats["method"] == "DOP853"
    assert stats["error_estimate"] is not None and "still being compiled" in stats["reason"]
