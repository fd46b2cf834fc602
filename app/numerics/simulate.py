"""One simulation, as ``solve_ivp`` runs one: a plan (``app.numerics.plan``) in, an ``Outcome`` out, on the caller's thread.

``run`` composes four pieces, and a caller that wants to place them (a server: which thread, which process)
composes the same pieces itself:

* ``start(plan, wall_seconds)``: the compiled code made ready (before the clock starts), the deadline set, the problem posed;
* ``integrate(started, events)``: the chosen method steps to the end (or to a terminal event); a run that
  cannot go on with its plan says which plan it continues with instead (``Continued``): ``auto``'s explicit
  method meeting stiffness hands over to Radau IIA, its symplectic pick past its step limit to the adaptive pair;
* ``reference_first(started)``: the error estimate's reference of a non-stiff adaptive compiled run, which does
  not depend on the run, so it may run before or beside it (``Started.independent_reference`` says when);
* ``finish(stepped, reference)``: the reference run (unless it was run already), the comparison, the warnings.

Everything shares one deadline.  The main run exceeding it is an error (too much work); the reference
exceeding it only costs the estimate, with a warning.

A server passes ``wait_for_compile=False`` to the plan: when ``auto`` picks a compiled method whose numba
code is not ready in this process yet, scipy's DOP853 on the generated scalar right-hand side answers
instead, for the run and the reference, and ``Outcome.path`` says so.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field

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


@dataclass
class Started:
    """A plan ready to step: its compiled code loaded, its deadline set, its problem posed."""

    plan: Plan
    problem: Problem
    compile_seconds: float
    warnings: list[str]

    @property
    def independent_reference(self) -> bool:
        """True when the error estimate's reference does not depend on the run (a non-stiff adaptive
        compiled run, whose reference is a tighter run of the compiled pair): it may run before or beside it."""
        p = self.plan
        adaptive = p.path == "compiled" and not isinstance(p.method, FixedStep)
        return p.reference is not None and adaptive and not p.stiff


@dataclass
class Stepped:
    """A plan's main run, stepped to its end, to its terminal event or as far as its budget allowed."""

    started: Started
    trajectory: Trajectory  # ended at the terminal event, if one was hit
    compared: Trajectory  # the samples the estimate compares: those before the event
    hit: terminal.Hit | None
    warnings: list[str]


@dataclass
class Continued:
    """A run that goes on with another plan, in what is left of its deadline."""

    plan: Plan
    deadline: float  # time.perf_counter() value
    compile_seconds: float  # spent on the plan it leaves, counted in the outcome

    def wall_seconds(self) -> float:
        """What is left of the deadline, now."""
        return max(self.deadline - time.perf_counter(), 0.0)


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
) -> Outcome:
    """Plan and run in one call (scripts and tests); a server plans first to choose where the run goes."""
    planned = plan(system, k, y0, t_end, samples, method, rtol, atol, estimate, wait_for_compile)
    return run(planned, wall_seconds, events=events)


def run(plan: Plan, wall_seconds: float | None = None, events: Sequence[terminal.EventFunction] = ()) -> Outcome:
    """Run a plan under one deadline, on the caller's thread: start, integrate (continuing with the plan a
    hand-over gives), and finish with the error estimate."""
    stepped = integrate(start(plan, wall_seconds), events)
    if isinstance(stepped, Continued):
        return carried(run(stepped.plan, stepped.wall_seconds(), events), stepped)
    return finish(stepped)


def carried(outcome: Outcome, continued: Continued) -> Outcome:
    """The outcome of the plan a run continued with, counting the compile time of the plan it left."""
    outcome.compile_seconds += continued.compile_seconds
    return outcome


def start(plan: Plan, wall_seconds: float | None = None) -> Started:
    """Load the plan's compiled code (compiling, on first use in this process, before the clock starts),
    set the deadline ``wall_seconds`` from now and pose the problem."""
    wall_seconds = limits.WALL_SECONDS if wall_seconds is None else wall_seconds
    system, y0, analysis = plan.system, plan.y0, plan.analysis
    warnings: list[str] = []
    if analysis.unresolvable and plan.method.implicit:
        warnings.append(
            f"a fast mode (|λ| = {analysis.spectral_radius:.3g}/s) swings at the start by about "
            f"{analysis.fast_amplitude:.2g} times the tolerance; the implicit method damps it, so the samples show "
            "the slow motion without that swing"
        )
    before = time.perf_counter()
    for needed in (plan.method, plan.reference):
        if needed is not None and needed.compiled:
            needed.prepare(system)
    compile_seconds = time.perf_counter() - before
    deadline = time.perf_counter() + wall_seconds
    t = sample_times(plan.t_end, plan.samples)
    atol = np.empty(y0.size)
    atol.fill(plan.atol)  # np.full's numbers without its Python
    problem = Problem(system, plan.k, y0, t, plan.rtol, atol, bounds(system, y0), deadline, _budget_for(plan.name))
    return Started(plan, problem, compile_seconds, warnings)


def integrate(started: Started, events: Sequence[terminal.EventFunction] = ()) -> Stepped | Continued:
    """Step the plan's method over the problem; ``Continued`` when the run goes on with another plan."""
    plan, problem = started.plan, started.problem
    chosen, name = plan.method, plan.name
    options = {"stop_on_stiff": True} if plan.watch_stiffness else {}
    try:
        trajectory = chosen.integrate(problem, **options)
    except TooMuchWork as exc:
        if plan.requested != AUTO:
            raise
        if isinstance(chosen, FixedStep):
            # auto never refuses what another method can do: its symplectic pick past its step limit
            # hands the run to the adaptive default in what is left of the deadline
            return Continued(plan.instead_of_symplectic(_why(exc)), problem.deadline, 0.0)
        if exc.partial is None:
            raise
        # auto's adaptive run out of budget: it answers with the samples it reached, saying how far it got
        trajectory = exc.partial
    if trajectory.stiff_detected and not trajectory.complete and options:
        # the explicit run found h |lambda| at its stability limit for 15 steps in a row: redo it with Radau IIA
        # in what is left of the deadline
        return Continued(plan.handed_over(trajectory.t_reached), problem.deadline, started.compile_seconds)
    warnings = list(started.warnings)
    if trajectory.stiff_detected:
        warnings.append(
            f"{name} detected stiffness (its step size is held at the stability limit): an implicit method "
            "(Radau or BDF) may be much cheaper here"
        )
    # a terminal event (the block at the foot of its ramp) ends the run there: the estimate
    # compares the samples before it, the run keeps them and the state at the event
    hit = terminal.first_hit(plan.system, events, trajectory, plan.k) if events else None
    compared = terminal.before(trajectory, hit) if hit is not None else trajectory
    if not trajectory.complete and hit is None:
        warnings.append(trajectory.stop_reason)
    if hit is not None:
        trajectory = terminal.ended(trajectory, hit)
    return Stepped(started, trajectory, compared, hit, warnings)


def reference_first(started: Started) -> Trajectory:
    """The reference of a run whose reference does not depend on it (``Started.independent_reference``),
    run before or beside the run; it raises ``TooMuchWork`` as the reference in ``finish`` would."""
    assert started.independent_reference
    name, tight = reference_problem(started.problem, stiff=False, compiled=True)
    tight.max_steps = _budget_for(name)
    return METHODS[name].integrate(tight)


def finish(stepped: Stepped, reference: Trajectory | TooMuchWork | None = None) -> Outcome:
    """The outcome: the run's trajectory and its error estimate.  ``reference``: the reference's run when it
    was made already (``reference_first``: its trajectory, or the ``TooMuchWork`` that stopped it); else
    it runs here, in what is left of the budget."""
    started = stepped.started
    plan, problem = started.plan, started.problem
    warnings = list(stepped.warnings)
    compiled = plan.path != "scipy-fallback"
    result = (
        estimate_error(plan.system, problem, plan.method, stepped.compared, plan.stiff, warnings, compiled, reference)
        if plan.reference is not None
        else None
    )
    fixed = isinstance(plan.method, FixedStep)
    if result is not None and (note := above_tolerance(result, stepped.compared, problem.rtol, problem.atol, fixed)):
        warnings.append(note)  # the run did not deliver the tolerance asked for: say so, and why
    trajectory = stepped.trajectory
    return Outcome(
        trajectory, plan.name, plan.reason, plan.analysis, result, warnings, started.compile_seconds, plan.path,
        stepped.hit,
    )  # fmt: skip


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
    reference: Trajectory | TooMuchWork | None = None,
) -> Estimate | None:
    """Run the reference (see ``estimate``) in what is left of the budget, unless it was run already, and compare."""
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
    if reference is None:  # else the same run, made already before or beside the main one (reference_first)
        try:
            reference = METHODS[ref_name].integrate(ref_problem, **options)
        except TooMuchWork as exc:
            reference = exc
    if isinstance(reference, TooMuchWork):
        warnings.append("no error estimate: the reference run did not fit in the time budget")
        return None
    if reference.t.size < trajectory.t.size:
        warnings.append(
            f"the error estimate covers t <= {reference.t_reached:.4g} s only (the reference stopped there)"
        )
    return compare(trajectory, reference, system.coordinates, label, factor)
