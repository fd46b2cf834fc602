"""The worker pool behind /api/derive and /api/simulate: time limit, memory cap, recovery, healing.

The jobs below are module-level functions, so a worker process can import them.
"""

import asyncio
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import pytest

from app.engine.errors import DerivationError
from app.service.runtime.worker import UNEXPECTED, JobFailed, WorkerPool

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

ROOT = Path(__file__).resolve().parents[3]


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


def raise_refusal():
    raise DerivationError("a refusal worded for the user", "x")


def fail_like_a_broken_install():
    raise OSError("could not load library 'libllvmlite.so' from '/tmp/tmpab12/site-packages/llvmlite/binding'")


_hoard = []


def keep(megabytes):
    """Allocate and keep memory in the worker (a job that leaves its worker bloated)."""
    _hoard.append(bytearray(megabytes * 2**20))
    return os.getpid()


def generated_folder():
    from app.numerics.paths import generated_dir

    return generated_dir().name


def collector():
    """The cyclic collector's state in this worker: enabled, and how many objects it no longer walks."""
    import gc

    return gc.isenabled(), gc.get_freeze_count()


def warmed():
    """The size of the warm-up document this worker inherited from its forkserver (0: it failed)."""
    import sys

    warmup = sys.modules.get("app.service.users.worker_warmup")
    return warmup.DOCUMENT_BYTES if warmup is not None else None


def signal_then_sleep(path, seconds):
    """Write this worker's pid where the test waits for it, then sleep."""
    Path(path).write_text(str(os.getpid()))
    time.sleep(seconds)


def spawn_grandchild_then_sleep(path, seconds):
    child = subprocess.Popen(["sleep", "120"])
    Path(path).write_text(str(child.pid))
    time.sleep(seconds)


def alive(pid):
    """Whether a process exists and is not a zombie."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state not in ("Z", "X")


def wait_for(condition, seconds=30):
    deadline = time.monotonic() + seconds
    while not condition() and time.monotonic() < deadline:
        time.sleep(0.05)
    return condition()


def worker_pids():
    """The live pool workers of this process: children of its forkserver."""
    me = str(os.getpid())
    pids = []
    for status in Path("/proc").glob("[0-9]*/status"):
        try:
            fields = dict(line.split(":\t", 1) for line in status.read_text().splitlines() if ":\t" in line)
        except OSError:
            continue
        parent = fields.get("PPid", "").strip()
        try:
            grandparent = Path(f"/proc/{parent}/status").read_text().split("PPid:\t", 1)[1].split()[0]
        except (OSError, IndexError):
            continue
        if grandparent == me and alive(int(status.parent.name)):
            pids.append(int(status.parent.name))
    return pids


def resident_mb(pid):
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return 0.0


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


RETIRE_MB = 400


@pytest.fixture(scope="module")
def pool():
    p = WorkerPool(workers=1, memory_mb=256, retire_mb=RETIRE_MB)
    yield p
    p.stop()


def test_a_job_returns_its_result(pool):
    assert pool.run(sleep_then_return, 0, timeout=60) == 0


def test_a_worker_leaves_what_the_forkserver_imported_out_of_the_collectors_walk(pool):
    enabled, frozen = pool.submit(collector, timeout=30).result(timeout=60)
    # the preloaded SymPy, SciPy, numba and engine (about 180,000 objects); cycles made by jobs are still collected
    assert enabled and frozen > 50_000, frozen


def test_every_worker_starts_from_a_forkserver_that_derived_a_small_system(pool):
    # the swing of app/service/users/worker_warmup.py, derived before any worker was forked: a full document
    assert pool.submit(warmed, timeout=30).result(timeout=60) > 10_000


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


def test_memory_beyond_the_cap_fails_cleanly_and_the_worker_retires(pool):
    before = pool.run(whoami, timeout=60)
    with pytest.raises(JobFailed) as caught:
        pool.run(allocate, 2048, timeout=60)
    assert caught.value.kind == "memory" and "256 MB" in str(caught.value)
    assert pool.run(allocate, 16, timeout=60) == 16 * 2**20
    assert pool.run(whoami, timeout=60) != before  # the worker that ran out ended itself


def test_a_worker_over_its_resident_threshold_retires_after_its_job():
    small = WorkerPool(workers=1, memory_mb=256, retire_mb=100)
    try:
        bloated = small.run(keep, 150, timeout=60)  # answers, then ends: 150 MB kept is over the 100 MB threshold
        assert wait_for(lambda: not alive(bloated))
        assert small.run(whoami, timeout=60) != bloated
    finally:
        small.stop()


@pytest.mark.slow
def test_after_a_burst_of_memory_bombs_honest_jobs_succeed_and_no_worker_stays_bloated():
    bombs = WorkerPool(workers=2, memory_mb=256, retire_mb=RETIRE_MB)
    try:
        futures = [bombs.submit(allocate, 2048, timeout=60) for _ in range(6)]
        futures += [bombs.submit(keep, 200, timeout=60) for _ in range(2)]  # a job that leaves its worker at 400+ MB
        for future in futures:
            try:
                bombs.outcome(future, 60)
            except JobFailed as exc:
                assert exc.kind in ("memory", "crashed")
        honest = [bombs.submit(allocate, 16, timeout=60) for _ in range(10)]
        assert [bombs.outcome(f, 60) for f in honest] == [16 * 2**20] * 10
        assert wait_for(lambda: all(resident_mb(pid) <= RETIRE_MB for pid in worker_pids()), 10)
        assert worker_pids(), "the pool keeps its workers"
    finally:
        bombs.stop()


def test_a_crashed_worker_is_reported_and_replaced(pool):
    with pytest.raises(JobFailed) as caught:
        pool.run(die, 3, timeout=60)
    assert caught.value.kind == "crashed" and "exit code 3" in str(caught.value)
    assert pool.run(sleep_then_return, 0, timeout=60) == 0


def test_workers_write_users_generated_code_to_the_bounded_folder(pool):
    assert pool.run(generated_folder, timeout=60) == "generated-user"  # pruned by app/service/runtime/disk.py
    assert generated_folder() == "generated"  # the chapter's, in the web process, is not


def test_a_refusal_comes_back_as_it_is(pool):
    with pytest.raises(DerivationError, match="worded for the user"):
        pool.run(raise_refusal, timeout=60)


def test_an_unexpected_failure_is_told_without_paths_or_names_and_the_worker_is_replaced(pool):
    before = pool.run(whoami, timeout=60)
    with pytest.raises(JobFailed) as caught:
        pool.run(fail_like_a_broken_install, timeout=60)
    message = str(caught.value)
    assert caught.value.kind == "unavailable" and message == UNEXPECTED
    assert "/" not in message and "llvmlite" not in message and "OSError" not in message
    assert pool.run(whoami, timeout=60) != before  # a worker that failed this way may be broken: it retired


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


def test_cancelling_the_await_kills_the_job(pool, tmp_path):
    started = tmp_path / "started"

    async def main():
        future = pool.submit(signal_then_sleep, str(started), 60, timeout=90)
        task = asyncio.ensure_future(pool.run_async(future, 90))
        # at least one turn of the loop: the task is inside its await before it is cancelled (a worker
        # that writes the file before this coroutine first yields must not let it cancel a task never started)
        await asyncio.sleep(0)
        while not started.exists() or not started.read_text():  # the job is running in its worker
            await asyncio.sleep(0.02)
        task.cancel()
        with pytest.raises(asyncio.CancelledError):
            await task
        return future

    future = run_in_own_loop(main)
    assert wait_for(future.cancelled, 20)
    assert wait_for(lambda: not alive(int(started.read_text())), 20)  # the worker running it was killed
    assert pool.run(sleep_then_return, 0, timeout=60) == 0


def test_a_timed_out_jobs_process_group_is_killed(pool, tmp_path):
    started = tmp_path / "grandchild"
    with pytest.raises(JobFailed) as caught:
        pool.run(spawn_grandchild_then_sleep, str(started), 60, timeout=2)
    assert caught.value.kind == "timeout"
    assert wait_for(lambda: not alive(int(started.read_text())), 20)


def _script(body, **values):
    return textwrap.dedent(body).format(root=str(ROOT), **{k: str(v) for k, v in values.items()})


@pytest.mark.slow
def test_a_launcher_fed_on_stdin_still_runs_jobs():
    """Workers do not re-run the parent's ``__main__`` (here a script no child could read again)."""
    script = _script("""
        import sys
        sys.path.insert(0, {root!r})
        from app.service.runtime.worker import WorkerPool
        print("launched")  # a launcher's top level: it must not run again in the workers
        pool = WorkerPool(workers=1, memory_mb=256, preload=())
        print(pool.run(len, "abc", timeout=60))
        pool.stop()
    """)
    done = subprocess.run([sys.executable, "-"], input=script, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.split() == ["launched", "3"]


@pytest.mark.slow
def test_a_killed_web_process_leaves_no_job_running(tmp_path):
    started = tmp_path / "started"
    script = _script("""
        import sys, time
        sys.path.insert(0, {root!r})
        sys.path.insert(0, {tests!r})
        from app.service.runtime.worker import WorkerPool
        from test_api_user_worker import signal_then_sleep
        pool = WorkerPool(workers=1, memory_mb=256, preload=())
        pool.submit(signal_then_sleep, {started!r}, 300, timeout=600)
        time.sleep(600)
    """, tests=Path(__file__).parent, started=started)
    server = subprocess.Popen([sys.executable, "-c", script])
    try:
        assert wait_for(lambda: started.exists() and started.read_text(), 60)
        job = int(started.read_text())
        assert alive(job)
        server.send_signal(signal.SIGKILL)  # as the kernel's OOM killer would
        server.wait(10)
        assert wait_for(lambda: not alive(job), 10)  # long before its 600 s limit
    finally:
        server.kill()
        server.wait(10)


def test_a_stopped_pool_starts_again(pool):
    pool.stop()
    assert pool.run(sleep_then_return, 0, timeout=60) == 0
