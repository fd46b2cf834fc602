"""A doomed request does not hold another session's small derivation (issue 35): the default pool has two
workers where memory allows, so a job running to its time limit leaves the other free.  Measured as ordering:
the small derivation is answered while the doomed job is still running."""

from __future__ import annotations

import time

import pytest

from app.engine.parser.user_system import UserSystem
from app.service.runtime.worker import WorkerPool
from app.service.users.user_jobs import derive_job
from app.settings import Settings

ONE_LINK = {
    "coordinates": ["theta"],
    "parameters": [{"name": "g", "value": 9.81}, {"name": "l", "value": 1.0}],
    "lagrangian": "l**2*theta_dot**2/2 + g*l*cos(theta)",
}


def test_the_default_pool_has_two_workers_where_memory_allows():
    assert Settings(workers=0, memory_budget_mb=16_000).worker_count == 2
    # a budget too small for two useful jobs: one worker, each job still able to work
    assert Settings(workers=0, memory_budget_mb=700, web_processes=1).worker_count == 1


@pytest.mark.slow
def test_a_doomed_job_does_not_hold_a_small_derivation():
    pool = WorkerPool(workers=Settings(memory_budget_mb=16_000).worker_count)
    try:
        # a job that runs until it is stopped at its limit (a stand-in for a system that never finishes)
        doomed = pool.submit(time.sleep, 60.0, timeout=30.0)
        small = pool.submit(derive_job, UserSystem.of(ONE_LINK), timeout=30.0)
        assert small.result(timeout=30.0)  # the derivation document, as bytes
        assert not doomed.done()  # answered while the doomed job still runs: it was never queued behind it
    finally:
        pool.stop()
