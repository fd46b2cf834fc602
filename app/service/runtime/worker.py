"""A pool of worker processes for SymPy and numerics on systems users type in.

User input can make SymPy run for ever (automatic evaluation of innocent-looking
constants, expansions that explode) or eat all memory, and a thread cannot be
stopped.  So every such job runs in a separate process:

* pebble's ``ProcessPool`` enforces a hard time limit per job by killing the
  worker that runs it, then starts a fresh worker: the pool stays usable;
* each worker caps its own address space (``RLIMIT_AS``) in its initializer,
  so a job that allocates too much gets a ``MemoryError`` (or dies) instead of
  pushing the server out of memory;
* workers are forked from a ``forkserver`` that has already imported the engine
  and numerics, so a replacement worker starts in milliseconds and never
  inherits the web server's threads or locks;
* a pool found broken (every worker gone) is replaced on the next job.

The pool also heals itself:

* a worker retires (ends after sending its answer, and pebble starts a fresh
  one) after a ``MemoryError``, a ``RecursionError`` or any failure that is not
  a refusal of the input, and whenever it ends a job above its resident-size
  threshold (``settings().retire_rss_mb``), so a memory bomb cannot leave a
  bloated or broken worker behind to fail the next honest jobs;
* each worker leads its own process group, and the SIGTERM that pebble sends
  to a timed-out job's worker kills the whole group; a worker dies with the
  web process that owns the pool (a thread waits on that process's pidfd: the
  forkserver outlives its parent while any worker lives, so the parent's end
  would otherwise go unnoticed until the job ends) and with the forkserver
  (``PR_SET_PDEATHSIG``);
* workers start from ``app.service.runtime.worker_entry``, never by re-running the
  server's ``__main__`` (a launcher script or a script fed on stdin);
* a broken pool is stopped and joined before the next one starts;
* users' generated code and compiled functions go to a folder bounded in size
  (app/service/runtime/disk.py), pruned by the workers after their jobs;
* a job's unexpected failure reaches the user as one plain sentence, never
  with a server path or an internal name (the details go to the log).

Failures come back as ``JobFailed`` (app/errors.py's ``WorkerFailed``) with a
``kind``: ``timeout``, ``memory``, ``crashed`` or ``unavailable``.
"""

from __future__ import annotations

import asyncio
import ctypes
import gc
import logging
import os
import resource
import select
import signal
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import Future
from concurrent.futures.process import BrokenProcessPool
from multiprocessing import context as mp_context
from multiprocessing import popen_forkserver, spawn
from typing import Any

import pebble.pool.process
from pebble import ProcessExpired, ProcessPool

from app.engine.algebra import work
from app.errors import OverCapacity, Refused, WorkerFailed
from app.numerics.paths import use_user_folder
from app.service.runtime import disk, resident
from app.settings import settings

log = logging.getLogger(__name__)

MAX_TASKS = 200  # a worker is replaced after this many jobs, so caches cannot grow without bound
# what the forkserver imports once for every worker it forks (a missing module is skipped); numba
# (with its cache folder set) and scipy too, which the web process itself imports on first use (app/late.py)
PRELOAD = (
    "app.service.users.user_systems",
    "app.service.simulations.simulation",
    "app.service.tutor.checking",
    "app.numerics.kernels.common",
    "scipy.integrate",
    "scipy.linalg",
    "scipy.optimize",
    "app.service.users.worker_warmup",  # last: a small derivation, so that no worker's first job pays for first calls
)
ENTRY = "app.service.runtime.worker_entry"
# a job's failure that is about the input, already worded for the user; anything else is the server's
REFUSALS: tuple[type[BaseException], ...] = (Refused, OverCapacity)  # app/errors.py: the input's or the load's
UNEXPECTED = "the server could not run this request (an internal failure, logged for the maintainers); try again"


class JobFailed(WorkerFailed):
    """A job of this pool that did not finish: ``kind`` is timeout, memory, crashed or unavailable."""


def _address_space() -> int:
    """The current virtual memory size of this process, in bytes."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024
    return 0


WORKER_NICENESS = 10


PR_SET_PDEATHSIG = 1  # linux/prctl.h

# In a worker: the resident size at which it retires after its current job, and whether it will.
_retire_bytes = 0
_retiring = False


def _resident() -> int:
    """The resident set size of this process, in bytes."""
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def _die_with_parent() -> None:
    """Ask the kernel to kill this process when its parent (the forkserver) ends."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() == 1:  # the parent was already gone before the request took effect
        os._exit(1)


def _kill_group(signum: int = signal.SIGTERM, frame: Any = None) -> None:
    """SIGTERM (pebble stopping this worker, e.g. for a timed-out job): end the job's whole process group.

    Only a group this worker leads: before it has one of its own (``initialize_worker``'s first act), the
    group is its web process's, and with it the server's and whatever started the server."""
    if os.getpgrp() == os.getpid():
        os.killpg(0, signal.SIGKILL)
    os.kill(os.getpid(), signal.SIGKILL)


def _watch_owner(owner: int) -> None:
    """End this worker (and its process group) as soon as the web process ``owner`` ends."""
    try:
        handle = os.pidfd_open(owner)
    except ProcessLookupError:
        _kill_group()
    except OSError:  # no pidfd on this kernel: look every second
        handle = None

    def watch() -> None:
        if handle is not None:
            select.select([handle], [], [])
        else:
            while os.path.exists(f"/proc/{owner}"):
                time.sleep(1)
        _kill_group()

    threading.Thread(target=watch, name="owner-watch", daemon=True).start()


def _tasks_until_retired(tasks: Callable[..., Any]) -> Callable[..., Any]:
    """pebble's task iterator, ended before the next task once this worker decided to retire.

    The worker then leaves its loop and exits normally (as after ``max_tasks``), and
    pebble starts a fresh one; the answer of the last job has already been sent."""

    def until_retired(channel: Any, max_tasks: int) -> Any:
        for task in tasks(channel, max_tasks):
            yield task
            if _retiring:
                return

    return until_retired


def initialize_worker(memory_mb: int, retire_mb: int = 0, owner: int = 0, users: bool = True) -> None:
    """Run in each new worker: cap its address space at what it has plus ``memory_mb``,
    yield the CPU to the web processes (users' long derivations never slow the pages and
    scene simulations of everyone else), lead a process group, die with the parent, and
    retire once above ``retire_mb`` resident.  A worker for ``users``' systems writes their
    generated code to the bounded folder; the scenes' worker keeps the chapter's."""
    global _retire_bytes
    # a group of its own before anything can end it: ending "its group" must never reach the web process's
    os.setpgid(0, 0)
    if owner:  # next: the watching thread's stack counts in the address space measured below
        _watch_owner(owner)
    if users:  # the budget with the web processes' measured size (app/service/runtime/resident.py)
        memory_mb = min(memory_mb, resident.job_memory_mb())
    limit = _address_space() + memory_mb * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    os.nice(WORKER_NICENESS)
    signal.signal(signal.SIGTERM, _kill_group)
    _die_with_parent()
    _retire_bytes = retire_mb * 2**20
    if users:
        use_user_folder()  # users' generated code goes to the bounded folder (app/service/runtime/disk.py)
    # this pebble internal is pinned in pyproject.toml (pebble < 5.3); tests/web/api/test_api_user_worker.py covers it
    pebble.pool.process.worker_get_next_task = _tasks_until_retired(pebble.pool.process.worker_get_next_task)
    # What the forkserver imported (SymPy, SciPy, numba, the engine: some 180,000 objects) lives as long as
    # the worker: the cyclic collector stops walking it. Each full collection walked it all, a sixth of a user's
    # double pendulum (0.79 s → 0.60 s in a worker), and wrote to every page the worker shares with the forkserver.
    gc.freeze()


def execute(function: Callable[..., Any], *args: Any) -> Any:
    """Run a job in the worker, deciding whether the worker retires after it."""
    global _retiring
    work.start_afresh()  # each job's count of work, and so what its bounds let through, is its own
    try:
        return function(*args)
    except REFUSALS:
        raise
    except BaseException:  # out of memory, too deep, or broken: a fresh worker takes the next job
        _retiring = True
        raise
    finally:
        if _retire_bytes and _resident() > _retire_bytes:
            _retiring = True
        try:
            disk.prune_now_and_then()
        except OSError:
            log.exception("could not prune the cache of users' systems")


def stopped(exitcode: int | None) -> str:
    """What ended a worker before its job did, from its exit code: a signal (negative code) or an exit.

    A worker that runs out of its memory cap gets a MemoryError (reported as such), so an end by a
    signal is something outside the job: an operator, the container's own memory limit (SIGKILL from
    the kernel), or the server shutting down."""
    if exitcode is not None and exitcode < 0:
        try:
            name = signal.Signals(-exitcode).name
        except ValueError:
            name = f"signal {-exitcode}"
        return (
            f"the worker running this job was stopped by {name} before it finished (from outside the job: "
            "an operator, the server restarting, or the machine's own limits); try again"
        )
    code = "" if exitcode is None else f" (exit code {exitcode})"
    return f"the worker running this job ended unexpectedly{code} before it finished; try again"


class _EntryPopen(popen_forkserver.Popen):
    """Start a worker from ``ENTRY`` instead of re-running the parent's ``__main__``."""

    _lock = threading.Lock()

    def _launch(self, process_obj: Any) -> None:
        with self._lock:
            original = spawn.get_preparation_data

            def preparation(name: str) -> dict[str, Any]:
                data = original(name)
                data.pop("init_main_from_path", None)
                data["init_main_from_name"] = ENTRY
                return data

            spawn.get_preparation_data = preparation
            try:
                super()._launch(process_obj)  # type: ignore[misc]  # multiprocessing internals, untyped
            finally:
                spawn.get_preparation_data = original


class _EntryProcess(mp_context.ForkServerProcess):
    @staticmethod
    def _Popen(process_obj: Any) -> _EntryPopen:
        return _EntryPopen(process_obj)


class _EntryContext(mp_context.ForkServerContext):
    Process = _EntryProcess


def _context(preload: Sequence[str]) -> _EntryContext:
    context = _EntryContext()
    context.set_forkserver_preload(list(preload))
    return context


class WorkerPool:
    """A restartable pebble process pool with per-job time limits and a memory cap."""

    def __init__(
        self,
        workers: int | None = None,
        memory_mb: int | None = None,
        preload: Sequence[str] = PRELOAD,
        retire_mb: int | None = None,
        users: bool = True,
    ):
        self.users = users
        self.workers = workers or settings().worker_count
        self.memory_mb = memory_mb or settings().job_memory_mb
        self.retire_mb = retire_mb if retire_mb is not None else settings().retire_rss_mb
        self.preload = tuple(preload)
        self._pool: ProcessPool | None = None
        self._lock = threading.Lock()

    def _running_pool(self) -> ProcessPool:
        with self._lock:
            if self._pool is None or not self._pool.active:
                if self._pool is not None:
                    self._pool.stop()
                    self._pool.join(timeout=5)
                self._pool = ProcessPool(
                    max_workers=self.workers,
                    max_tasks=MAX_TASKS,
                    initializer=initialize_worker,
                    initargs=(self.memory_mb, self.retire_mb, os.getpid(), self.users),
                    context=_context(self.preload),
                )
            return self._pool

    def submit(self, function: Callable[..., Any], *args: Any, timeout: float) -> Future:
        """Schedule ``function(*args)``; the worker is killed if it runs longer than ``timeout`` s."""
        try:
            return self._running_pool().schedule(execute, args=(function, *args), timeout=timeout)
        except (RuntimeError, OSError, BrokenProcessPool):
            pass  # the pool stopped between the check and the call: the next call stops, joins and replaces it
        try:
            return self._running_pool().schedule(execute, args=(function, *args), timeout=timeout)
        except (RuntimeError, OSError, BrokenProcessPool):
            raise JobFailed("the worker pool could not start a worker; try again", "unavailable") from None

    def outcome(self, future: Future, timeout: float) -> Any:
        """The job's result, or JobFailed saying why there is none."""
        try:
            return future.result()
        except TimeoutError:
            raise JobFailed(
                f"the work took longer than the limit of {timeout:g} s and was stopped", "timeout"
            ) from None
        except MemoryError:
            # the cap as the worker had it (the budget with the measured web size)
            cap = min(self.memory_mb, resident.job_memory_mb()) if self.users else self.memory_mb
            raise JobFailed(f"the work needed more than the limit of {cap} MB of memory", "memory") from None
        except RecursionError:
            raise JobFailed("the expressions are nested too deeply to work with", "memory") from None
        except ProcessExpired as exc:
            raise JobFailed(stopped(exc.exitcode), "crashed") from None
        except BrokenProcessPool:  # the next submit stops and joins this pool, then starts another
            raise JobFailed("the worker pool was restarting; try again", "unavailable") from None
        except REFUSALS:
            raise
        except Exception as exc:  # the server's failure: logged in full, told in one plain sentence
            log.error("a job failed in the worker: %s: %s", type(exc).__name__, exc)
            raise JobFailed(UNEXPECTED, "unavailable") from None

    def run(self, function: Callable[..., Any], *args: Any, timeout: float) -> Any:
        """Run a job and wait for it (from a thread, never from the event loop)."""
        return self.outcome(self.submit(function, *args, timeout=timeout), timeout)

    async def run_async(self, future: Future, timeout: float) -> Any:
        """Await a submitted job without holding a thread; cancelling the await kills the job."""
        try:
            await asyncio.wrap_future(future)
        except asyncio.CancelledError:
            task = asyncio.current_task()
            gave_way = getattr(future, "gave_way", None)
            if gave_way and not (task is not None and task.cancelling()):
                # the job, not this await, was cancelled: fair shares gave its slot to someone else
                raise OverCapacity(gave_way, 1) from None
            future.cancel()  # pebble kills the worker of a running job that is cancelled
            raise
        except BaseException:  # noqa: S110 - the job's own failure, read by outcome()
            pass
        return self.outcome(future, timeout)

    def stop(self) -> None:
        with self._lock:
            if self._pool is not None:
                self._pool.stop()
                self._pool.join(timeout=5)
                self._pool = None


def ending(future: Future) -> str:
    """How a finished job ended, for fair shares: done, refused, timeout, memory, crashed, failed or cancelled."""
    if future.cancelled():
        return "cancelled"
    error = future.exception()
    if error is None:
        return "done"
    if isinstance(error, TimeoutError):
        return "timeout"
    if isinstance(error, (MemoryError, RecursionError)):
        return "memory"
    if isinstance(error, ProcessExpired):
        return "crashed"
    return "refused" if isinstance(error, REFUSALS) else "failed"
