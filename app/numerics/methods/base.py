"""The rules every integrator follows; subclasses only supply the mathematics.

A ``Problem`` is one initial-value problem y' = F(t, y), y = (q, q_dot), sampled
at fixed times.  ``Method.integrate`` checks that the method applies, runs the
subclass's ``_run`` under the budget (a deadline and a step limit), and turns
the outcome into a ``Trajectory``: either the whole interval, or the part
before the motion left its bounds (a runaway, a singularity) with a message
saying where and why.  Running out of budget raises ``TooMuchWork``.
"""

from __future__ import annotations

import importlib
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any

import numpy as np

from app.numerics.errors import SimulationError, TooMuchWork
from app.numerics.system import NumericSystem


@dataclass
class Problem:
    system: NumericSystem
    k: np.ndarray  # parameter values, in the system's order
    y0: np.ndarray  # (q, q_dot) at t[0]
    t: np.ndarray  # sample times, increasing, t[0] the start
    rtol: float
    atol: np.ndarray  # per component of y
    bound: np.ndarray  # |y_i| beyond bound_i ends the run
    deadline: float  # time.perf_counter() value at which work must stop
    max_steps: int

    @property
    def t_end(self) -> float:
        return float(self.t[-1])

    def remaining(self) -> float:
        return self.deadline - time.perf_counter()


@dataclass
class Trajectory:
    method: str
    t: np.ndarray
    y: np.ndarray  # shape (len(t), 2n): q then q_dot
    steps: int
    rhs_evaluations: int
    wall_time_s: float
    complete: bool = True
    stop_reason: str = ""
    stiff_detected: bool = False
    notes: list[str] = field(default_factory=list)
    step_size: float | None = None  # fixed-step methods
    substeps: int | None = None  # fixed-step methods: steps per interval between samples

    @property
    def t_reached(self) -> float:
        return float(self.t[-1]) if self.t.size else 0.0


class Method:
    """Base class: a named integrator with its applicability rule."""

    # Class attributes describe a method (as scipy's own ``RK45`` does); a subclass with a ``name`` is a
    # concrete method and the registry (``app.numerics.methods``) lists it.
    name = ""
    family = ""  # "explicit", "implicit", "symplectic", "switching"
    order = 0
    compiled = False  # the step loop runs in numba (else in Python, holding the GIL throughout)
    implicit = False  # solves equations per step (with the engine's Jacobian where it takes one)
    summary = ""
    label = ""  # the method's name as the pages' menus and run details print it (``name`` is the API's value)

    kernel_module = ""  # the compiled loop this method runs (imported, so compiled or loaded, by prepare)

    def prepare(self, system: NumericSystem) -> None:
        """Compile (or load from the disk cache) what the method runs, before any clock starts."""
        if self.compiled:
            from app.numerics import jit

            system.compiled()
            self.loop()
            jit.mark_ready(self.kernel_module)

    def loop(self) -> ModuleType:
        """The module of the compiled loop, imported (so compiled or loaded) on first use and kept: importing
        it again at every run, though only a lookup, went through importlib's machinery each time."""
        found = self.__dict__.get("_kernel")
        if found is None:
            found = self._kernel = importlib.import_module(self.kernel_module)
        return found

    def ready(self, system: NumericSystem) -> bool:
        """True when ``prepare`` would return at once: nothing left to compile for this system."""
        from app.numerics import jit

        return not self.compiled or (jit.ready(self.kernel_module) and system.is_compiled())

    def applicable(self, system: NumericSystem) -> str | None:
        """None when the method can integrate the system; otherwise why not."""
        return None

    def integrate(self, problem: Problem, **options) -> Trajectory:
        why_not = self.applicable(problem.system)
        if why_not:
            raise SimulationError(f"method {self.name} cannot integrate this system: {why_not}", "method")
        if problem.remaining() <= 0:
            raise TooMuchWork(f"no time left in the budget for {self.name}", "t_end")
        start = time.perf_counter()
        trajectory = self._run(problem, **options)
        trajectory.wall_time_s = time.perf_counter() - start
        return trajectory

    def _run(self, problem: Problem, **options: Any) -> Trajectory:
        raise NotImplementedError

    def too_much(self, problem: Problem, what: str) -> TooMuchWork:
        exc = TooMuchWork(
            f"too much work for {self.name}: {what} before t = {problem.t_end:g} s. "
            "Shorten t_end, loosen rtol/atol, or choose another method (method 'auto' picks one for the problem).",
            "t_end",
        )
        exc.what = what
        return exc


def drive(step: Callable[[int], int], steps_done: Callable[[], float], problem: Problem, method: Method) -> int:
    """Call a resumable compiled kernel in chunks, checking the deadline and step limit between them.

    Chunks start small and grow to about 50 ms, so a slow right-hand side
    cannot overrun the deadline by more than one short chunk.
    """
    from app.numerics.kernels.common import RUNNING

    chunk = 2_000
    while True:
        before = time.perf_counter()
        status = step(chunk)
        elapsed = time.perf_counter() - before
        if status != RUNNING:
            return status
        if steps_done() >= problem.max_steps:
            raise method.too_much(problem, f"more than {problem.max_steps:,} steps")
        if time.perf_counter() >= problem.deadline:
            raise method.too_much(problem, "the wall-clock budget ran out")
        chunk = int(min(max(chunk * 0.05 / max(elapsed, 1e-6), 100), 2_000_000))


def run_kernel(
    method: Method,
    problem: Problem,
    kernel: Any,
    call: Callable[[int], int],
    arrays: tuple[np.ndarray, np.ndarray, np.ndarray],
    **stats_from_state: int,
) -> Trajectory:
    """Drive a compiled kernel (``call(chunk)``) to the end of ``problem`` and read its result.

    ``arrays`` are the kernel's work arrays ``(state, samples, last y)``. ``stats_from_state``
    names further slots of the state to report as booleans (e.g. ``stiff_detected=STIFF_SEEN``).
    The samples reached are kept when the budget runs out (``TooMuchWork.partial``).
    """
    st, Y, y = arrays

    def stats() -> dict[str, int]:
        return {"steps": int(st[kernel.STEPS]), "rhs_evaluations": int(st[kernel.NFEV])}

    try:
        status = drive(call, lambda: st[kernel.STEPS], problem, method)
    except TooMuchWork as exc:
        raise cut_short(exc, method, problem, Y, int(st[kernel.NEXT_OUT]), **stats()) from None
    flags = {name: bool(st[slot]) for name, slot in stats_from_state.items()}
    trajectory = finished(method, problem, Y, int(st[kernel.NEXT_OUT]), status, last=y, **stats(), **flags)
    if st[kernel.REJECTED]:
        trajectory.notes.append(f"{int(st[kernel.REJECTED])} rejected steps")
    return trajectory


def cut_short(exc: TooMuchWork, method: Method, problem: Problem, Y: np.ndarray, filled: int, **stats) -> TooMuchWork:
    """``exc`` carrying the samples reached before the budget ran out (``TooMuchWork.partial``), if any."""
    if filled >= 2:
        t = problem.t[:filled]
        reason = (
            f"{method.name} stopped ({exc.what or 'out of budget'}) at t = {t[-1]:.6g} s of {problem.t_end:g} s: "
            "the motion up to there is shown (a shorter t_end or a looser rtol/atol gives the whole run)"
        )
        exc.partial = Trajectory(
            method.name, t, Y[:filled], complete=False, stop_reason=reason, wall_time_s=0.0, **stats
        )
    return exc


# why a run stops, in a student's words, by the kernel's status (app/numerics/kernels/common.py)
_WHY_STOPPED = {
    "step size underflow": "no step, however small, could follow the equations from there: they change without "
    "bound, as where they divide by a quantity that reaches zero (r = 0 of polar coordinates, the apex of a cone)",
    "non-finite state": "the equations give an infinite or undefined value there, as where they divide by zero",
    "implicit stage equations did not converge": "the implicit method could not solve its equations for the next "
    "step there, as where the motion changes without bound",
}


def stop_sentence(problem: Problem, status: int, where: str, last: np.ndarray | None) -> str:
    """Why a run ended early, where, and at which coordinates: "the run stops at t = 1.102 s, at r = 0.0003 m,
    φ = 2.1: no step, however small, could follow the equations from there: …"."""
    from app.engine.display.names import unicode
    from app.numerics.kernels.common import STATUS_NAMES

    name = STATUS_NAMES.get(status, "stopped")
    at = ""
    if last is not None:
        coords = problem.system.coordinates
        at = ", at " + ", ".join(
            f"{unicode(q)} = {float(v):.3g}" for q, v in zip(coords, last[: len(coords)], strict=True)
        )
    why = _WHY_STOPPED.get(name, "the equations cannot be followed further")
    return f"the run stops at {where}{at}: {why}"


def outside_names(problem: Problem, y: np.ndarray) -> str:
    """Which components are beyond their bounds, e.g. "|rho| passed 1e+03"."""
    coords = problem.system.coordinates
    labels = [*coords, *(f"{q}_dot" for q in coords)]
    beyond = [
        f"|{labels[i]}| passed {problem.bound[i]:.3g}" for i in range(y.size) if not abs(y[i]) <= problem.bound[i]
    ]
    return ", ".join(beyond) or "the state left its bounds"


def finished(
    method: Method, problem: Problem, Y: np.ndarray, filled: int, status: int, last: np.ndarray | None = None, **stats
) -> Trajectory:
    """A trajectory from kernel output: complete, or cut at the last sample reached with the reason."""
    from app.numerics.kernels.common import BOUND, DONE

    if status == BOUND and filled:
        # keep the samples up to the first one outside the bounds (a long step may have passed several)
        outside = np.any(~(np.abs(Y[:filled]) <= problem.bound), axis=1)
        if outside.any():
            filled = int(np.argmax(outside)) + 1
    t = problem.t[:filled]
    y = Y[:filled]
    if status == DONE:
        return Trajectory(method.name, t, y, complete=True, wall_time_s=0.0, **stats)
    where = f"t = {t[-1]:.6g} s" if filled else "the start"
    if status == BOUND:
        reason = (
            f"the motion ran away: {outside_names(problem, last if last is not None else Y[filled - 1])} after {where}, "
            "so the run stops there"
        )
    else:
        reason = stop_sentence(problem, status, where, Y[filled - 1] if filled else None)
    return Trajectory(method.name, t, y, complete=False, stop_reason=reason, wall_time_s=0.0, **stats)
