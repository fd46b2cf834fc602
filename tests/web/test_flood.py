"""Under a flood: /healthz never waits for work, scene simulations fail fast when every slot is taken."""

import inspect

import pytest

from app import main
from app.service.simulations import simulation

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def test_healthz_runs_on_the_event_loop_and_does_no_work():
    # a plain ``def`` would queue in the thread pool behind every running simulation
    assert inspect.iscoroutinefunction(main.health)
    assert "await" not in inspect.getsource(main.health)


def test_healthz_answers_and_a_simulation_is_refused_while_every_slot_is_taken(client, services):
    taken = 0
    while services.gates.slots.acquire(blocking=False):
        taken += 1
    try:
        assert client.get("/healthz").json() == {"status": "ok"}
        response = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "t_end": 1})
        assert response.status_code == 429 and response.headers["Retry-After"] == "1"
        assert "too many simulations" in response.json()["detail"]
    finally:
        for _ in range(taken):
            services.gates.slots.release()
    assert client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "t_end": 1}).status_code == 200


def test_heavy_simulations_take_at_most_half_of_the_slots(client, services):
    taken = 0
    while services.gates.heavy.acquire(blocking=False):
        taken += 1
    assert taken == max(1, simulation.SLOTS // 2)
    try:
        heavy = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "t_end": 1e4})
        assert heavy.status_code == 429 and "long or high-accuracy" in heavy.json()["detail"]
        tight = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "rtol": 1e-11})
        assert tight.status_code == 429
        light = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}})
        assert light.status_code == 200  # the light runs students send still find a slot
    finally:
        for _ in range(taken):
            services.gates.heavy.release()
