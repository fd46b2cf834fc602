"""One simulation: plan it (``app.numerics.plan``), run it under the budget, estimate its global error.

Order of work: the plan (analyse the start, choose, name the reference), run the
method (switching to the compiled Radau IIA if ``auto``'s explicit method meets stiffness on the way),
run the reference for the error estimate, compare.  Everything shares one
deadline.  The main run exceeding it is an error (too much work); the
reference exceeding it only costs the estimate, with a warning.

A server passes ``wait_for_compile=False`` to the plan: when ``auto`` picks a
compiled method whose numba code is not ready in this process yet (a background
thread is compiling it), scipy's DOP853 on the generated scalar right-hand side
answers instead, for the run and the reference, and ``Outcome.path`` says so.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from concurrent.futures import Future
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from app.numerics import events as terminal
from app.numerics import limits
from app.numerics.choose import Analysis
from app.numerics.errors import TooMuchWork
from app.numerics.estimate import Estimate, above_tolerance, compare, reference_problem
from app.numerics.methods import AUTO, METHODS, Problem, Trajectory
from app.numerics.methods.symplectic import FixedStep
from app.numerics.plan import Plan, plan
from app.numerics.system import NumericSystem


@dataclass
class Outcome:
    trajectory: Trajectory
    method: str
    reason: str
    analysis: Analysis
    estimate: Estimate | None
    warnings: list[str] = field(default_factory=list)
    compile_seconds: float = 0.0
    path: str = "compiled"  # "compiled", "scipy" (a scipy method was asked for or chosen), "scipy-fallback"
    event: terminal.Hit | None = None  # the terminal event that ended the run, if one did
    alongside: Any = None  # what ``run``'s ``alongside`` returned for the final trajectory (None if not called)


class Beside(Protocol):
    """How a run may use a second core, given by its caller (a server counts its busy cores and keeps the
    threads): ``own()`` is held around the run's own stepping; ``submit(work)`` runs ``work`` (the error
    estimate's reference) in another thread and returns its future, or None when no core is free (the
    reference then runs after the run). Without one, a run uses the caller's thread alone."""

    def own(self) -> AbstractContextManager: ...

    def submit(self, work: Callable[[], Trajectory]) -> Future | None: ...


def _reference_ahead(problem: Problem, beside: Beside) -> Future | None:
    """Start the compiled reference of a non-stiff adaptive run beside it, if the caller has a core free."""
    name, tight = reference_problem(problem, stiff=False, compiled=True)
    tight.max_steps = _budget_for(name)
    return beside.submit(lambda: METHODS[name].integrate(tight))


def _budget_for(method_name: str) -> int:
    return limits.COMPILED_STEPS if METHODS[method_name].compiled else limits.SCIPY_STEPS


def bounds(system: NumericSystem, y0: np.ndarray) -> np.ndarray:
    """|y_i| limits: a coordinate that is not an angle may not exceed RUNAWAY_FACTOR times its starting scale."""
    n = system.n
    bound = np.empty(2 * n)
    bound.fill(limits.STATE_BOUND)  # np.full's numbers without its Python (10-20 us right after other work)
    for i in range(n):
        if not (system.periodic and system.periodic[i]):
            bound[i] = limits.RUNAWAY_FACTOR * max(1.0, abs(float(y0[i])))
    return bound


def sample_times(t_end: float, samples: int) -> np.ndarray:
    """The samples' times, t_i = i h with h = t_end / (samples - 1), the last exactly t_end: the numbers
    ``np.linspace(0, t_end, samples)`` gives (its own steps, in its order), without its general
    function's work, which took 30-80 us of a default simulation right after other work."""
    step = t_end / (samples - 1) if samples > 1 else 0.0
    if not step > 0.0:
        return np.linspace(0.0, t_end, samples)  # no step (one sample), or t_end at or below zero
    t = np.arange(samples, dtype=np.float64)
    t *= step
    t[-1] = t_end
    return t


def simulate(
    system: NumericSystem,
    k: np.ndarray,
    y0: np.ndarray,
    t_end: float,
    samples: int,
    method: str = AUTO,
    rtol: float = limits.RTOL_DEFAULT,
    atol: float = limits.ATOL_DEFAULT,
    wall_seconds: float | None = None,
    estimate: bool = True,
    wait_for_compile: bool = True,
    events: Sequence[terminal.EventFunction] = (),
    beside: Beside | None = None,
) -> Outcome:
    """Plan and run in one call (scripts and tests); a server plans first to take its throttles (see ``run``)."""
    planned = plan(system, k, y0, t_end, samples, method, rtol, atol, estimate, wait_for_compile)
    return run(planned, wall_seconds, events=events, beside=beside)


def run(
    plan: Plan,
    wall_seconds: float | None = None,
    python_loop: Callable[[], AbstractContextManager] = nullcontext,
    events: Sequence[terminal.EventFunction] = (),
    elsewhere: Callable[[Plan, float], Outcome] | None = None,
    alongside: Callable[[Trajectory], Any] | None = None,
    beside: Beside | None = None,
) -> Outcome:
    """Run a plan under one deadline, on the caller's thread.  ``python_loop()`` is entered around a Python step loop the plan did not
    foresee (the stiff hand-over to scipy's Radau while the compiled one is not ready); the caller holds it already when ``plan.python_loop``.

    ``elsewhere(plan, wall_seconds)``, when given, runs a plan that steps in Python (a scipy method, as
    asked for or chosen, or after the hand-over) in another process and returns its outcome: a server
    keeps such loops out of its web process, where they would hold the GIL the event loop needs.  The
    scipy fallback while compiling stays here (short runs, and a worker would first have to start).

    ``alongside(trajectory)``, when given, is called on the final trajectory while the reference that
    started beside the main run is still finishing (a server computes the observables there); its
    result is ``Outcome.alongside``.  A run handed to ``elsewhere`` does not call it.

    ``beside`` (see ``Beside``), when given, may run the error estimate's reference in another thread while the
    run steps; the estimate is the same either way."""
    wall_seconds = limits.WALL_SECONDS if wall_seconds is None else wall_seconds
    if elsewhere is not None and plan.python_loop and plan.path != "scipy-fallback":
        return elsewhere(plan, wall_seconds)
    system, k, y0 = plan.system, plan.k, plan.y0
    t = sample_times(plan.t_end, plan.samples)
    atol_vector = np.empty(y0.size)
    atol_vector.fill(plan.atol)
    name, reason, chosen, path, analysis = plan.name, plan.reason, plan.method, plan.path, plan.analysis
    estimate = plan.reference is not None

    warnings: list[str] = []
    if analysis.unresolvable and chosen.implicit:
        warnings.append(
            f"a fast mode (|λ| = {analysis.spectral_radius:.3g}/s) swings at the start by about "
            f"{analysis.fast_amplitude:.2g} times the tolerance; the implicit method damps it, so the samples show "
            "the slow motion without that swing"
        )
    # compiling (first use in this process, or after a change) happens before the clock starts
    before = time.perf_counter()
    for needed in (chosen, plan.reference):
        if needed is not None and needed.compiled:
            needed.prepare(system)
    compile_seconds = time.perf_counter() - before
    deadline = time.perf_counter() + wall_seconds

    problem = Problem(system, k, y0, t, plan.rtol, atol_vector, bounds(system, y0), deadline, _budget_for(name))
    options = {"stop_on_stiff": True} if plan.watch_stiffness else {}
    # the reference of a non-stiff adaptive compiled run does not depend on the run: with a second core
    # (``beside``), it starts now
    adaptive = path == "compiled" and not isinstance(chosen, FixedStep)
    start_ahead = estimate and adaptive and not plan.stiff
    with beside.own() if beside is not None else nullcontext():  # this run's own core
        ahead = _reference_ahead(problem, beside) if beside is not None and start_ahead else None
        try:
            trajectory = chosen.integrate(problem, **options)
        except TooMuchWork as exc:
            if plan.requested != AUTO:
                raise
            if isinstance(chosen, FixedStep):
                # auto never refuses what another method can do: its symplectic pick past its step limit
                # hands the run to the adaptive default in what is left of the deadline
                instead = plan.instead_of_symplectic(_why(exc))
                return run(instead, max(deadline - time.perf_counter(), 0.0), events=events, elsewhere=elsewhere,
                           alongside=alongside, beside=beside)  # fmt: skip
            if exc.partial is None:
                raise
            # auto's adaptive run out of budget: it answers with the samples it reached, saying how far it got
            trajectory = exc.partial
    if trajectory.stiff_detected and not trajectory.complete and options:
        # the explicit run found h |lambda| at its stability limit for 15 steps in a row: redo it with Radau IIA
        # in what is left of the deadline (the reference started beside it is dropped)
        handed = plan.handed_over(trajectory.t_reached)
        with python_loop() if handed.python_loop else nullcontext():
            outcome = run(
                handed, max(deadline - time.perf_counter(), 0.0), events=events, elsewhere=elsewhere,
                alongside=alongside, beside=beside,
            )  # fmt: skip
        outcome.compile_seconds += compile_seconds
        return outcome
    if trajectory.stiff_detected:
        warnings.append(
            f"{name} detected stiffness (its step size is held at the stability limit): an implicit method "
            "(Radau or BDF) may be much cheaper here"
        )
    # a terminal event (the block at the foot of its ramp) ends the run there: the estimate
    # compares the samples before it, the run keeps them and the state at the event
    hit = terminal.first_hit(system, events, trajectory, k) if events else None
    compared = terminal.before(trajectory, hit) if hit is not None else trajectory
    if not trajectory.complete and hit is None:
        warnings.append(trajectory.stop_reason)
    if hit is not None:
        trajectory = terminal.ended(trajectory, hit)
    # the caller's work on the final trajectory, on this core while the reference finishes on the other
    done_alongside = alongside(trajectory) if alongside is not None else None
    compiled = path != "scipy-fallback"
    result = (
        estimate_error(system, problem, chosen, compared, plan.stiff, warnings, compiled, ahead) if estimate else None
    )
    fixed = isinstance(chosen, FixedStep)
    if result is not None and (note := above_tolerance(result, compared, problem.rtol, problem.atol, fixed)):
        warnings.append(note)  # the run did not deliver the tolerance asked for: say so, and why
    return Outcome(trajectory, name, reason, analysis, result, warnings, compile_seconds, path, hit, done_alongside)


def _why(exc: TooMuchWork) -> str:
    """The step limit's sentence, without the advice that follows it (auto is taking that advice)."""
    text = str(exc).split(". ")[0]
    return "stopped: " + text.removeprefix("too much work for ").split(": ", 1)[-1]


def estimate_error(
    system: NumericSystem,
    problem: Problem,
    method,
    trajectory: Trajectory,
    stiff: bool,
    warnings: list[str],
    compiled: bool = True,
    ahead: Future | None = None,
) -> Estimate | None:
    """Run the reference (see ``estimate``) in what is left of the budget and compare."""
    if isinstance(method, FixedStep):
        ref_name, ref_problem, factor = method.name, problem, 1.0 / (1.0 - 2.0**-method.order)
        # a fixed-step run records its substeps and step size
        assert trajectory.substeps is not None and trajectory.step_size is not None
        options = {"substeps": 2 * trajectory.substeps}
        label = (
            f"{method.name} with half the step (h = {trajectory.step_size / 2:.3g} s), Richardson factor {factor:.3g}"
        )
    else:
        ref_name, ref_problem = reference_problem(problem, stiff, compiled)
        ref_problem.max_steps = _budget_for(ref_name)
        factor, options = 1.0, {}
        label = f"{ref_name} at rtol={ref_problem.rtol:.1e}, atol={float(ref_problem.atol.max()):.1e}"
    try:
        # the same run, already started beside the main one (see _reference_ahead)
        reference = ahead.result() if ahead is not None else METHODS[ref_name].integrate(ref_problem, **options)
    except TooMuchWork:
        warnings.append("no error estimate: the reference run did not fit in the time budget")
        return None
    if reference.t.size < trajectory.t.size:
        warnings.append(
            f"the error estimate covers t <= {reference.t_reached:.4g} s only (the reference stopped there)"
        )
    return compare(trajectory, reference, system.coordinates, label, factor)
