"""Where a simulation's pieces run in a server: its cores, its throttle, its worker process.

``app.numerics.simulate`` runs a plan on the caller's thread and knows nothing of a server; this module
composes the same pieces (``start``, ``integrate``, ``reference_first``, ``finish``) and decides where
each one runs:

* a plan that steps in Python (a scipy method, asked for, chosen or handed over to) holds the GIL for its
  whole run: it may go to another process (``elsewhere``), and a hand-over to one takes the one slot for a
  Python step loop (``throttle``) first;
* the reference of a non-stiff adaptive compiled run does not depend on the run: it starts in another thread
  while the run steps, when this process has a core free (``Cores``);
* the caller's work on the final trajectory (``alongside``: the series of the result document) runs on this
  thread while that reference finishes on the other.

The numbers are those of ``app.numerics.simulate.run`` whatever runs where.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from concurrent.futures import Future
from contextlib import AbstractContextManager, nullcontext
from functools import partial
from typing import TypeVar

from app.numerics import events as terminal
from app.numerics.errors import TooMuchWork
from app.numerics.methods import Trajectory
from app.numerics.plan import Plan
from app.numerics.simulate import Continued, Outcome, carried, finish, integrate, reference_first, start
from app.service.runtime.cores import Cores

T = TypeVar("T")

# runs a plan in another process and returns its outcome: (plan, wall_seconds) -> Outcome
Elsewhere = Callable[[Plan, float], Outcome]


def steps_in_python(plan: Plan) -> bool:
    """True when the run or its reference steps in Python (scipy), holding the GIL throughout."""
    return not plan.method.compiled or (plan.reference is not None and not plan.reference.compiled)


def run_served(
    plan: Plan,
    wall_seconds: float,
    events: Sequence[terminal.EventFunction],
    cores: Cores,
    *,
    throttle: Callable[[], AbstractContextManager] | None = None,
    elsewhere: Elsewhere | None = None,
    alongside: Callable[[Trajectory], T] | None = None,
) -> tuple[Outcome, T | None]:
    """Run a plan under one deadline, as ``app.numerics.simulate.run`` does, and what ``alongside`` made of
    its final trajectory (None when it was not called: the run went ``elsewhere``).

    ``throttle()`` is entered around a plan that steps in Python which the run hands over to (the caller
    holds it already for a first plan that does); ``elsewhere(plan, wall_seconds)`` runs a plan that steps in
    Python in another process, except scipy's fallback while the kernels compile (short runs, and a worker
    would first have to start)."""
    if elsewhere is not None and steps_in_python(plan) and plan.path != "scipy-fallback":
        return elsewhere(plan, wall_seconds), None
    started = start(plan, wall_seconds)
    with cores.own():  # this run's own core
        ahead = cores.submit(partial(reference_first, started)) if started.independent_reference else None
        stepped = integrate(started, events)
    if isinstance(stepped, Continued):
        # the run goes on with another plan (the reference started beside it is dropped)
        then = stepped.plan
        with throttle() if throttle is not None and steps_in_python(then) else nullcontext():
            outcome, done = run_served(
                then, stepped.wall_seconds(), events, cores, throttle=throttle, elsewhere=elsewhere, alongside=alongside
            )
        return carried(outcome, stepped), done
    # the caller's work on the final trajectory, on this core while the reference finishes on the other
    done = alongside(stepped.trajectory) if alongside is not None else None
    return finish(stepped, _made(ahead)), done


def _made(ahead: Future | None) -> Trajectory | TooMuchWork | None:
    """The reference run beside the run, when one was: its trajectory, or the TooMuchWork that stopped it."""
    if ahead is None:
        return None
    try:
        return ahead.result()
    except TooMuchWork as exc:
        return exc
