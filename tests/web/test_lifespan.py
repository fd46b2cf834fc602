"""The app's lifespan builds its services, hands them to the routes and stops them at shutdown."""

import os
import time

import pytest
from fastapi.testclient import TestClient

from app.main import app
from app.service.services import Services


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True


@pytest.mark.slow  # starts a worker pool of its own (the forkserver imports the engine)
def test_each_lifespan_has_its_own_services_and_joins_its_workers_at_shutdown(client):
    session = client.app_state["services"]
    with TestClient(app) as other:
        services = other.app_state["services"]
        assert isinstance(services, Services) and services is not session
        assert services.users.pool is services.pool and services.checking.users is services.users
        assert other.get("/healthz").status_code == 200
        worker = services.pool.run(os.getpid, timeout=60)
        scenes_worker = services.scenes.run(os.getpid, timeout=60)
        assert len({worker, scenes_worker, os.getpid()}) == 3 and _alive(worker) and _alive(scenes_worker)
    # shutdown stopped the pools and joined their processes; the session's services still serve
    deadline = time.monotonic() + 10
    while (_alive(worker) or _alive(scenes_worker)) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _alive(worker) and not _alive(scenes_worker)
    assert client.app_state["services"] is session and client.get("/healthz").status_code == 200
