"""A doomed request from one session does not hold another session's small derivation (issue 35).

Through the whole service path a page takes (``UserSystems``: the result cache, the fair-share gate, the
worker pool with its hard limit), with a real user system: a twelve-link chain (the largest allowed), whose
whole document takes well over DOOMED_SECONDS here (the eight-link chain's alone takes about 7 s on a quiet
machine), sent with a hard limit of DOOMED_SECONDS, so it runs until the pool stops it.  While it runs,
another session derives a one-link pendulum.  The test asserts order, not time (speed figures are
benchmarks): the small derivation is answered while the doomed job is still running, so it never waited
for it; its delay beside the doomed job against the same derivation alone is printed and measured by
benchmarks/bench_doomed.py (the issue's bound is 2 s).

tests/service/users/test_pool_not_blocked.py shows the same at the pool alone (a sleeping job, no sessions).
"""

from __future__ import annotations

import asyncio
import time

import pytest

from app.engine.parser.user_system import UserSystem
from app.errors import Refused, WorkerFailed
from app.service.runtime.fairness import Fairness
from app.service.runtime.worker import WorkerPool
from app.service.users.user_systems import UserSystems
from app.settings import Settings

DOOMED_SECONDS = 4.0  # the hard limit the doomed system runs into (the server's default is 30 s)


def chain(links: int) -> dict:
    """A chain of ``links`` equal pendulums given by its particles (the doomed system at twelve)."""
    names = [f"q{i}" for i in range(links)]
    particles = [
        {"mass": "m", "position": [" + ".join(f"l*sin({q})" for q in names[: i + 1]), "0",
                                   " ".join(f"- l*cos({q})" for q in names[: i + 1])]}
        for i in range(links)
    ]  # fmt: skip
    return {
        "coordinates": names,
        "parameters": [{"name": "m", "value": 1.0}, {"name": "l", "value": 1.0}, {"name": "g", "value": 9.8}],
        "particles": particles,
        "potential": " + ".join(f"m*g*({p['position'][2]})" for p in particles),
    }


def one_link(g: float) -> UserSystem:
    """A small derivation no cache holds (``g`` differs per call)."""
    return UserSystem.of({
        "coordinates": ["theta"],
        "parameters": [{"name": "g", "value": g}, {"name": "l", "value": 1.0}],
        "lagrangian": "l**2*theta_dot**2/2 + g*l*cos(theta)",
    })  # fmt: skip


async def small_beside_doomed(users: UserSystems) -> dict[str, float | bool]:
    # the pool's first job starts its workers: a small derivation first, which is also the baseline
    await users.derive(one_link(9.7), "session-b", "10.0.0.2")
    started = time.perf_counter()
    await users.derive(one_link(9.71), "session-b", "10.0.0.2")
    alone = time.perf_counter() - started

    doomed = asyncio.ensure_future(users.derive(UserSystem.of(chain(12)), "session-a", "10.0.0.1"))
    while not any(t.running for t in users._queued.values()):  # the doomed job holds a worker
        await asyncio.sleep(0.05)
    doomed_started = time.perf_counter()
    await asyncio.sleep(1.0)  # well into its work
    started = time.perf_counter()
    await users.derive(one_link(9.72), "session-b", "10.0.0.2")
    beside = time.perf_counter() - started
    doomed_running = not doomed.done()
    with pytest.raises((Refused, WorkerFailed)) as refused:
        await doomed
    return {
        "alone": alone,
        "beside": beside,
        "doomed_running": doomed_running,
        "doomed_seconds": time.perf_counter() - doomed_started,
        "refusal": str(refused.value),
    }


def beside_doomed() -> dict[str, float | bool]:
    """``small_beside_doomed`` on a service of its own: two workers, the fair share, the doomed hard limit."""
    pool = WorkerPool(workers=2)
    users = UserSystems(pool, gate=Fairness(capacity=8, workers=2, queue_seconds=30),
                        config=Settings(derive_seconds=DOOMED_SECONDS))  # fmt: skip
    try:
        return asyncio.run(small_beside_doomed(users))
    finally:
        pool.stop()


@pytest.mark.slow
def test_a_doomed_system_does_not_hold_another_sessions_small_derivation():
    seen = beside_doomed()
    print(f"small derivation alone {seen['alone']:.2f} s, beside the doomed one {seen['beside']:.2f} s")
    # answered while the doomed job still ran: it was never queued behind it
    assert seen["doomed_running"], seen
    # and the doomed job did run into its hard limit (not refused at once for some other reason)
    assert f"longer than the limit of {DOOMED_SECONDS:g} s" in str(seen["refusal"]), seen
