"""A long derivation says which part it is on, and the session that started it can stop it (issue 45, item 6).

Through a real server process (its worker pool, its cache folder): the whole derivation of a triple pendulum
typed as particles takes seconds; while it runs, GET /api/derive/progress/{key} names the part and how long,
POST /api/derive/cancel/{key} stops it, the request waiting for it is answered 422 with kind "cancelled", the
progress file is gone, and the pool derives the next system as before."""

from __future__ import annotations

import threading
import time

import httpx2 as httpx
import pytest

from app.service.users.user_checks import checked, spec_key
from app.web.schemas.user import SystemSpec
from tests.web.api.test_classes_processes import server


def triple_pendulum(g: float) -> dict:
    x, z, particles = "", "", []
    for link in "abc":
        x, z = f"{x} + l*sin({link})".lstrip(" +"), f"{z} - l*cos({link})"
        particles.append({"mass": "m", "position": [x, "0", z]})
    return {
        "coordinates": ["a", "b", "c"],
        "parameters": [{"name": "m", "value": 1.0}, {"name": "l", "value": 1.0}, {"name": "g", "value": g}],
        "particles": particles,
        "potential": "-m*g*l*(3*cos(a) + 2*cos(b) + cos(c))",
    }


def key_of(spec: dict) -> str:
    return spec_key(checked(SystemSpec.model_validate(spec).to_spec()))


def test_a_bad_key_is_refused_and_an_unknown_one_is_not_running(client):
    assert client.get("/api/derive/progress/" + "0" * 64).json() == {
        "running": False, "part": None, "part_seconds": None, "seconds": None,
    }  # fmt: skip
    refused = client.get("/api/derive/progress/not-a-key")
    assert refused.status_code == 422 and "64 hexadecimal digits" in refused.json()["detail"]
    nothing = client.post("/api/derive/cancel/" + "0" * 64)
    assert nothing.status_code == 422 and "no derivation of this system is running" in nothing.json()["detail"]


@pytest.mark.slow
def test_a_running_derivation_tells_its_part_and_stops_when_asked(tmp_path):
    spec = triple_pendulum(9.7731)  # a value no cache holds
    key = key_of(spec)
    env = {"LAGRANGE_CACHE_DIR": str(tmp_path / "cache"), "LAGRANGE_DATA_DIR": str(tmp_path / "data")}
    with server(env) as (url, _):
        answers: list[httpx.Response] = []
        waiting = threading.Thread(target=lambda: answers.append(httpx.post(f"{url}/api/derive", json=spec, timeout=300)))
        waiting.start()
        deadline, seen = time.monotonic() + 120, None
        while time.monotonic() < deadline:
            seen = httpx.get(f"{url}/api/derive/progress/{key}").json()
            if seen["running"]:
                break
            time.sleep(0.2)
        assert seen and seen["running"], "the derivation never said it was running"
        assert seen["part"] and seen["seconds"] >= seen["part_seconds"] >= 0
        stopped = httpx.post(f"{url}/api/derive/cancel/{key}")
        assert stopped.status_code == 202, stopped.text
        waiting.join(60)
        (answer,) = answers
        assert answer.status_code == 422 and answer.json()["kind"] == "cancelled", answer.text
        assert "stopped, as you asked" in answer.json()["detail"]
        assert httpx.get(f"{url}/api/derive/progress/{key}").json()["running"] is False
        assert list((tmp_path / "cache" / "progress").glob("*.json")) == []
        # the pool goes on: the same system's equations come back
        again = httpx.post(f"{url}/api/derive/equations", json=spec, timeout=300)
        assert again.status_code == 200 and len(again.json()["equations_of_motion"]) == 3
