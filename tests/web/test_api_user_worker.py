"""The worker pool behind /api/derive and /api/simulate: time limit, memory cap, recovery.

The jobs below are module-level functions, so a worker process can import them.
"""

import asyncio
import os
import threading
import time

import pytest

from app.service.worker import JobFailed, WorkerPool


def sleep_then_return(seconds):
    time.sleep(seconds)
    return seconds


def allocate(megabytes):
    block = bytearray(megabytes * 2**20)
    return len(block)


def die(code):
    os._exit(code)


def whoami():
    return os.getpid()


def raise_value_error():
    raise ValueError("a job's own error")


def run_in_own_loop(coroutine_function):
    """asyncio.run in a thread of its own (the browser tests' Playwright keeps a loop running in the main one)."""
    outcome = {}

    def target():
        try:
            outcome["value"] = asyncio.run(coroutine_function())
        except BaseException as exc:  # handed to the test's thread
            outcome["error"] = exc

    thread = threading.Thread(target=target)
    thread.start()
    thread.join(120)
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]


@pytest.fixture(scope="module")
def pool():
    p = WorkerPool(workers=1, memory_mb=256)
    yield p
    p.stop()


def test_a_job_returns_its_result(pool):
    assert pool.run(sleep_then_return, 0, timeout=60) == 0


def test_a_job_over_its_time_limit_is_killed_and_the_pool_recovers(pool):
    before = pool.run(whoami, timeout=60)
    started = time.monotonic()
    with pytest.raises(JobFailed) as caught:
        pool.run(sleep_then_return, 30, timeout=0.5)
    assert caught.value.kind == "timeout" and "0.5 s" in str(caught.value)
    assert time.monotonic() - started < 20  # stopped long before the job would have ended
    after = pool.run(whoami, timeout=60)
    assert after != before  # a fresh worker replaced the killed one
    assert pool.run(sleep_then_return, 0, timeout=60) == 0


def test_memory_beyond_the_cap_fails_cleanly(pool):
    with pytest.raises(JobFailed) as caught:
        pool.run(allocate, 2048, timeout=60)
    assert caught.value.kind == "memory" and "256 MB" in str(caught.value)
    assert pool.run(allocate, 16, timeout=60) == 16 * 2**20


def test_a_crashed_worker_is_reported_and_replaced(pool):
    with pytest.raises(JobFailed) as caught:
        pool.run(die, 3, timeout=60)
    assert caught.value.kind == "crashed" and "exit code 3" in str(caught.value)
    assert pool.run(sleep_then_return, 0, timeout=60) == 0


def test_a_jobs_own_exception_comes_back(pool):
    with pytest.raises(ValueError, match="own error"):
        pool.run(raise_value_error, timeout=60)


def test_awaiting_a_job_does_not_hold_the_event_loop(pool):
    async def main():
        future = pool.submit(sleep_then_return, 0.3, timeout=60)
        ticks = 0

        async def tick():
            nonlocal ticks
            while not future.done():
                ticks += 1
                await asyncio.sleep(0.01)

        result, _ = await asyncio.gather(pool.run_async(future, 60), tick())
        return result, ticks

    result, ticks = run_in_own_loop(main)
    assert result == 0.3 and ticks > 5


def test_cancelling_the_await_kills_the_job(pool):
    async def main():
        future = pool.submit(sleep_then_return, 30, timeout=60)
        task = asyncio.ensure_future(pool.run_async(future, 60))
        await asyncio.sleep(0.5)
        task.cancel()
        with pytest.raises(asyncio.CancelledError):
            await task
        return future

    future = run_in_own_loop(main)
    deadline = time.monotonic() + 20
    while not future.done() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert future.cancelled() or future.done()
    assert pool.run(sleep_then_return, 0, timeout=60) == 0


def test_a_stopped_pool_starts_again(pool):
    pool.stop()
    assert pool.run(sleep_then_return, 0, timeout=60) == 0
