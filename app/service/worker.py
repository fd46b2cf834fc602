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

Failures come back as ``JobFailed`` (app/errors.py's ``WorkerFailed``) with a
``kind``: ``timeout``, ``memory``, ``crashed`` or ``unavailable``.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import os
import resource
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import Future
from concurrent.futures.process import BrokenProcessPool
from typing import Any

from pebble import ProcessExpired, ProcessPool

from app.errors import WorkerFailed
from app.settings import settings

MAX_TASKS = 200  # a worker is replaced after this many jobs, so caches cannot grow without bound
PRELOAD = ("app.service.user_systems", "app.service.simulation", "app.service.checking")  # a missing module is skipped


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


def initialize_worker(memory_mb: int) -> None:
    """Run in each new worker: cap its address space at what it has plus ``memory_mb``,
    and yield the CPU to the web processes, so users' long derivations never slow
    the pages and scene simulations of everyone else."""
    limit = _address_space() + memory_mb * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    os.nice(WORKER_NICENESS)


def _context(preload: Sequence[str]):
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(list(preload))
    return context


class WorkerPool:
    """A restartable pebble process pool with per-job time limits and a memory cap."""

    def __init__(self, workers: int | None = None, memory_mb: int | None = None, preload: Sequence[str] = PRELOAD):
        self.workers = workers or settings().worker_count
        self.memory_mb = memory_mb or settings().worker_memory_mb
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
                    initargs=(self.memory_mb,),
                    context=_context(self.preload),
                )
            return self._pool

    def submit(self, function: Callable[..., Any], *args: Any, timeout: float) -> Future:
        """Schedule ``function(*args)``; the worker is killed if it runs longer than ``timeout`` s."""
        try:
            return self._running_pool().schedule(function, args=args, timeout=timeout)
        except RuntimeError:  # the pool stopped between the check and the call: start afresh once
            with self._lock:
                self._pool = None
        try:
            return self._running_pool().schedule(function, args=args, timeout=timeout)
        except (RuntimeError, OSError, BrokenProcessPool):
            with self._lock:
                self._pool = None
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
            raise JobFailed(f"the work needed more than the limit of {self.memory_mb} MB of memory", "memory") from None
        except RecursionError:
            raise JobFailed("the expressions are nested too deeply to work with", "memory") from None
        except ProcessExpired as exc:
            raise JobFailed(
                f"the worker stopped unexpectedly (exit code {exc.exitcode}); the work may need more "
                f"than the limit of {self.memory_mb} MB of memory",
                "crashed",
            ) from None
        except BrokenProcessPool:
            with self._lock:
                self._pool = None
            raise JobFailed("the worker pool was restarting; try again", "unavailable") from None

    def run(self, function: Callable[..., Any], *args: Any, timeout: float) -> Any:
        """Run a job and wait for it (from a thread, never from the event loop)."""
        return self.outcome(self.submit(function, *args, timeout=timeout), timeout)

    async def run_async(self, future: Future, timeout: float) -> Any:
        """Await a submitted job without holding a thread; cancelling the await kills the job."""
        try:
            await asyncio.wrap_future(future)
        except asyncio.CancelledError:
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


_shared: WorkerPool | None = None
_shared_lock = threading.Lock()


def pool() -> WorkerPool:
    """The process-wide pool, created on first use."""
    global _shared
    with _shared_lock:
        if _shared is None:
            _shared = WorkerPool()
        return _shared
