"""The cores a simulation may use: its own, and a second one for its error estimate's reference run.

A run steps on the caller's thread; ``app.service.simulations.simulation_run`` starts the reference of a non-stiff
compiled run in another thread while the run goes on (the compiled kernels release the GIL), but only
while a core is free.
A core is free when this process's runs and references leave one and the machine's load average
(other processes included) leaves at least half a core idle: on a busy shared machine a second thread
only adds switching. The load average counts this server's own runs of the last minute, so one client
sending requests back to back holds it near 1: the half core keeps the second core for that client's
reference on a 2-core machine.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable, Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from contextlib import contextmanager
from typing import Any

IDLE_NEEDED = 0.5  # of a core, on average over the last minute, for a reference to run beside its run


def machine_load() -> float:
    """The machine's load average over the last minute (0 where the platform has none)."""
    try:
        return os.getloadavg()[0]
    except (AttributeError, OSError):  # no load average on this platform: count only our own threads
        return 0.0


class Cores:
    """Busy threads of this process's simulations (runs and references) against the machine's cores."""

    def __init__(self, count: int | None = None, load: Callable[[], float] | None = None) -> None:
        self.count = count or os.cpu_count() or 1
        self.load = load  # the machine's load average (``machine_load`` when not given)
        self.busy = 0
        self.lock = threading.Lock()
        self._pool: ThreadPoolExecutor | None = None

    def take(self, force: bool = False) -> bool:
        """One core for this process's work, if one is free; ``force``: a run's own core, always taken."""
        with self.lock:
            load = (self.load or machine_load)()
            if not force and (self.busy >= self.count or load > self.count - IDLE_NEEDED):
                return False
            self.busy += 1
            return True

    def give(self) -> None:
        with self.lock:
            self.busy -= 1

    @contextmanager
    def own(self) -> Iterator[None]:
        """Held around a run's own stepping: its core counts as busy."""
        self.take(force=True)
        try:
            yield
        finally:
            self.give()

    def submit(self, work: Callable[[], Any]) -> Future | None:
        """``work`` in another thread if a core is free (its core given back when it ends), else None."""
        if not self.take():
            return None
        try:
            with self.lock:
                if self._pool is None:
                    self._pool = ThreadPoolExecutor(max_workers=self.count, thread_name_prefix="reference")
            future = self._pool.submit(work)
        except RuntimeError:  # the interpreter is shutting down
            self.give()
            return None
        future.add_done_callback(lambda _: self.give())
        return future


# this process's cores: every simulation the service runs counts against them
CORES = Cores()
