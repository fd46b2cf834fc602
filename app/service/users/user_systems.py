"""Systems users type in: derive, simulate and export them through the worker pool.

Each method takes a checked ``UserSystem`` (the route builds it once with
``user_checks.checked``, pure Python, which reads each expression's text once);
the event loop only looks up caches and awaits: the jobs (``user_jobs``) build
what was read in SymPy, derive and simulate in a worker process
under a hard time limit and a memory cap, with one fair-share ticket per job,
and a request identical to one already running waits for that job.
"""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable
from typing import Any

from cachetools import LRUCache

from app.engine.parser.user_system import UserSystem
from app.errors import Refused, WorkerFailed
from app.service.runtime import fairness as fair
from app.service.runtime import progress, worker
from app.service.users.user_checks import spec_key
from app.service.users.user_jobs import derive_job, export_job, modes_job, poincare_job, simulate_job
from app.settings import Settings, settings

CANCELLED = "the derivation was stopped, as you asked; what was shown before stays, and deriving again starts it anew"


class ResultCache:
    """A small LRU of finished documents (bytes), bounded in entries and in total size.

    Each entry is charged at least ``total_bytes / entries``, so one cachetools LRU
    bounded in bytes holds at most ``entries`` of them.
    """

    def __init__(self, entries: int = 256, total_bytes: int = 64 * 2**20):
        self.total_bytes = total_bytes
        floor = total_bytes // entries
        self._items: LRUCache[str, bytes] = LRUCache(maxsize=total_bytes, getsizeof=lambda v: max(len(v), floor))
        self._lock = threading.Lock()

    def get(self, key: str) -> bytes | None:
        with self._lock:
            return self._items.get(key)

    def put(self, key: str, value: bytes) -> None:
        with self._lock:
            if key in self._items or len(value) > self.total_bytes // 4:
                return
            self._items[key] = value


class UserSystems:
    """Derive and simulate user systems: caches, fairness, then the worker pool."""

    def __init__(self, pool: worker.WorkerPool, gate: fair.Fairness | None = None, config: Settings | None = None):
        config = config or settings()
        self.derive_seconds = config.derive_seconds
        self.simulate_seconds = config.simulate_seconds
        self.pool = pool
        self.gate = gate or fair.Fairness(capacity=4 * pool.workers, workers=pool.workers)
        self.derivations = ResultCache()
        self.simulations = ResultCache(entries=64)
        self.exports = ResultCache(entries=64)
        self._running: dict[tuple[int, str], asyncio.Future] = {}
        self._queued: dict[tuple[int, str], fair.Ticket] = {}  # the ticket of each running slot
        self._waiters: dict[tuple[int, str], int] = {}
        self._cancelled: set[str] = set()  # keys whose job its client stopped (``cancel``)

    async def _run(
        self, cache: ResultCache, key: str, client: str, address: str, timeout: float, job, *args,
        ended: Callable[[], None] | None = None,
    ) -> bytes:
        """A cached answer, else the same request already running, else a new job (one fair-share ticket);
        ``ended()`` is called when a new job ends, however it ends (its worker killed too)."""
        cached = cache.get(key)
        if cached is not None:
            return cached
        # a classroom opening one shared link asks for the same system at once: one job serves them all
        slot = (id(asyncio.get_running_loop()), key)
        running = self._running.get(slot)
        if running is None:
            self._cancelled.discard(key)
            ticket = self.gate.admit(client, address)
            running = asyncio.ensure_future(self._job(cache, key, ticket, timeout, job, args))
            self._running[slot] = running
            self._queued[slot] = ticket
            running.add_done_callback(lambda done: self._finished(slot, done))
            if ended is not None:
                running.add_done_callback(lambda _: ended())
        # a client that goes away does not stop the job the others wait for; the last one to go, while it queues, does
        self._waiters[slot] = self._waiters.get(slot, 0) + 1
        try:
            return await asyncio.shield(running)
        except asyncio.CancelledError:
            task = asyncio.current_task()
            if running.cancelled() and key in self._cancelled and not (task is not None and task.cancelling()):
                # the job was stopped by its client (``cancel``), not this request by its client leaving
                raise WorkerFailed(CANCELLED, "cancelled") from None
            queued = self._queued.get(slot)
            if self._waiters.get(slot) == 1 and queued is not None and not queued.running:
                running.cancel()
            raise
        finally:
            if slot in self._waiters:
                self._waiters[slot] -= 1

    def cancel(self, key: str, client: str) -> None:
        """Stop the job of ``key`` that ``client`` started: a running job's worker is killed (pebble), a queued
        job leaves the queue, and the request waiting for it is answered ``WorkerFailed(kind="cancelled")``.
        Refused when no such job runs in this process, when it is another client's, or when other requests
        wait for it too (a class opening one shared link)."""
        slot = (id(asyncio.get_running_loop()), key)
        running, ticket = self._running.get(slot), self._queued.get(slot)
        if running is None or ticket is None:
            raise Refused("no derivation of this system is running on this server: it has ended, or it runs on "
                          "another replica", part=key)  # fmt: skip
        if ticket.client != client:
            raise Refused("this derivation was asked for by another session: only the session that asked can stop it")
        if self._waiters.get(slot, 0) > 1:
            raise Refused("others are waiting for this derivation too, so it goes on; leaving the page frees your place")
        self._cancelled.add(key)
        if ticket.job is not None:
            ticket.job.cancel()  # pebble stops the worker that runs it
        running.cancel()

    async def run_job(
        self, cache: ResultCache, key: str, client: str, address: str, timeout: float, job, *args
    ) -> bytes:
        """Another kind of job on user text (checking a student's answer): same cache, sharing, fair share and pool."""
        return await self._run(cache, key, client, address, timeout, job, *args)

    def _finished(self, slot: tuple[int, str], done: asyncio.Future) -> None:
        self._running.pop(slot, None)
        self._queued.pop(slot, None)
        self._waiters.pop(slot, None)
        if not done.cancelled():
            done.exception()  # retrieved here too, in case every waiter went away

    async def _job(self, cache: ResultCache, key: str, ticket: fair.Ticket, timeout: float, job, args) -> bytes:
        def submit() -> Any:
            try:
                future = self.pool.submit(job, *args, timeout=timeout)
            except BaseException:
                ticket.release("failed")
                raise
            # the slot is freed when the job really ends; a job out of time or memory counts against its client
            future.add_done_callback(lambda done: ticket.release(worker.ending(done)))
            return future

        await self.gate.turn(ticket)  # a fair turn for a worker, within the queue deadline
        # in a thread: the first job starts the forkserver (importing the engine), which takes seconds
        future = await asyncio.to_thread(submit)
        ticket.job = future  # a shared key's job may have to give way to a session's (app/service/runtime/fairness.py)
        result = await self.pool.run_async(future, timeout)
        cache.put(key, result)
        return result

    async def derive(self, user: UserSystem, client: str, address: str) -> bytes:
        key = spec_key(user)
        # the worker removes its progress file at the end of the job; a killed worker cannot (a timeout, ``cancel``)
        return await self._run(
            self.derivations, key, client, address, self.derive_seconds, derive_job, user,
            ended=lambda: progress.clear(key),
        )  # fmt: skip

    async def simulate(self, user: UserSystem, request: Any, client: str, address: str) -> bytes:
        key = spec_key(user, request.model_dump(mode="json"))
        return await self._run(
            self.simulations, key, client, address, self.simulate_seconds, simulate_job, user, request
        )

    async def simulation_job(
        self, kind: str, job: Callable[..., bytes], user: UserSystem, options: dict[str, Any], client: str, address: str
    ) -> bytes:
        """``job(user, options)`` of a simulation's kind (a Poincaré section, the action, a relaxation): cached with
        the simulations under ``kind`` and the options, under the simulation's time limit."""
        key = spec_key(user, kind, options)
        return await self._run(self.simulations, key, client, address, self.simulate_seconds, job, user, options)

    async def poincare(self, user: UserSystem, options: dict[str, Any], client: str, address: str) -> bytes:
        return await self.simulation_job("poincare", poincare_job, user, options, client, address)

    async def modes(self, user: UserSystem, client: str, address: str) -> bytes:
        key = spec_key(user, "modes")
        cached = self.simulations.get(key)
        if cached is not None:
            return cached
        # the derivation first, under its own limit (a refusal is the derivation's); the job measures its modes
        await self.derive(user, client, address)
        return await self._run(self.simulations, key, client, address, self.simulate_seconds, modes_job, user)

    async def export(
        self, user: UserSystem, fmt: str, initial: dict[str, float], t_end: float | None, client: str, address: str
    ) -> bytes:
        """``{"content", "filename", "media_type"}`` as JSON bytes, made in the pool under the derive limit."""
        key = spec_key(user, "export", fmt, initial, t_end)
        cached = self.exports.get(key)
        if cached is not None:
            return cached
        # the derivation the page already asked for (cached), or a derive job first: the export only prints
        document = await self.derive(user, client, address)
        return await self._run(
            self.exports, key, client, address, self.derive_seconds, export_job, user, fmt, initial, t_end, document
        )
