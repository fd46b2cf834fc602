"""How many simulations run at once in a process (its gates), and how many are running (the in-flight count)."""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager, contextmanager
from typing import Any, Protocol

from app.errors import OverCapacity
from app.numerics import limits
from app.numerics.methods.base import Method
from app.numerics.system import NumericSystem
from app.settings import container_cpus, settings

SLOTS = max(2, container_cpus())


class Ready(Protocol):
    """Whether ``method``'s compiled code for ``system`` is loaded in this process (nothing left to compile)."""

    def __call__(self, method: Method, system: NumericSystem, /) -> bool: ...


def _ready(method: Method, system: NumericSystem) -> bool:
    return method.ready(system)


class Offload(Protocol):
    """Runs ``job(*args)`` in a worker process and returns its result (``WorkerPool.run``)."""

    def __call__(self, job: Callable[..., Any], /, *args: Any, timeout: float) -> Any: ...


@contextmanager
def slot(gate: threading.BoundedSemaphore, message: str, wall_seconds: float | None = None) -> Iterator[None]:
    """Hold one of a gate's slots, or refuse as busy: under a flood a request fails fast (the
    ``scene_queue_seconds`` setting, at most a run's ``wall_seconds``) rather than holding a server thread
    while it waits."""
    wall_seconds = limits.WALL_SECONDS if wall_seconds is None else wall_seconds
    if not gate.acquire(timeout=min(settings().scene_queue_seconds, wall_seconds)):
        raise OverCapacity(message, 1)
    try:
        yield
    finally:
        gate.release()


class InFlight:
    """Simulations running through one ``Gates`` (the app's): its warm-up thread gives way to them between its steps."""

    def __init__(self) -> None:
        self._count = 0
        self._changed = threading.Condition()

    @contextmanager
    def serving(self) -> Iterator[None]:
        with self._changed:
            self._count += 1
        try:
            yield
        finally:
            with self._changed:
                self._count -= 1
                self._changed.notify_all()

    def wait_quiet(self, timeout: float) -> bool:
        """Wait until no simulation runs, at most ``timeout`` seconds; True when quiet."""
        with self._changed:
            return self._changed.wait_for(lambda: self._count == 0, timeout)


class Gates:
    """How many simulations run at once in one process: ``slots`` in all, at most half of them heavy.

    The app builds its own (``app.service.services``) and gives it to the routes, with ``offload``:
    the ``run`` of a worker process of its own for the scenes' runs that step in Python (scipy's
    loops hold the GIL for their whole run; there they cannot delay the event loop, ``/healthz``
    included, and they never wait behind a user's derivation).  One such run at a time per web
    process (``python_loop``), so that worker is free whenever a run is sent to it.

    ``answer_while_compiling`` (a server that compiles its kernels in the background): an ``auto``
    request whose compiled method is not ready yet is answered by scipy instead of waiting on numba.
    A worker's job or a script builds its own (``Gates()``), which runs everything in line and compiles first.

    ``wall_seconds``: one run's time budget (``limits.WALL_SECONDS``; a test gives a short one).
    ``compiled``: whether a method's compiled code for a system is ready in this process (its own
    ``ready``, what ``app.numerics.jit`` has loaded; a test gives a server where nothing is yet).
    ``in_flight``: the simulations running through these gates, which the warm-up gives way to."""

    def __init__(
        self,
        slots: int = SLOTS,
        offload: Offload | None = None,
        answer_while_compiling: bool = False,
        wall_seconds: float = limits.WALL_SECONDS,
        compiled: Ready | None = None,
    ) -> None:
        self.offload = offload
        self.answer_while_compiling = answer_while_compiling
        self.wall_seconds = wall_seconds
        self.compiled: Ready = compiled or _ready
        self.in_flight = InFlight()
        self.slots = threading.BoundedSemaphore(slots)
        self.heavy = threading.BoundedSemaphore(max(1, slots // 2))
        # scipy's integrators loop in Python and hold the GIL for their whole run: one at a
        # time per process, so they cannot starve the compiled runs and pages served beside them.
        self.python = threading.BoundedSemaphore(1)

    def any(self) -> AbstractContextManager[None]:
        """Hold one slot, or refuse as busy."""
        return slot(
            self.slots, "too many simulations are running at once; try again in a few seconds", self.wall_seconds
        )

    def heavy_run(self) -> AbstractContextManager[None]:
        """Hold one of the heavy runs' slots, or refuse as busy."""
        return slot(
            self.heavy,
            "too many long or high-accuracy simulations are running; try again shortly, or ask for less",
            self.wall_seconds,
        )

    def python_loop(self) -> AbstractContextManager[None]:
        """Hold the one slot for a Python step loop, or refuse as busy."""
        return slot(
            self.python,
            "another scipy (Python step loop) run is in progress here; try again in a few seconds, "
            "or ask for a compiled method",
            self.wall_seconds,
        )
