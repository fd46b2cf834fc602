"""Time budgets for SymPy work whose cost cannot be known in advance.

Simplification and equation solving are optional refinements: when they run out
of time the engine keeps the unrefined (still correct) expression.  The budget
uses an interval timer, which only works in a process's main thread; that is
where derivations run (the start-up cache builder and the worker processes that
serve user systems).  Elsewhere the budget degrades to a size gate alone.
"""

from __future__ import annotations

import signal
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TypeVar

import sympy as sp

T = TypeVar("T")

SIMPLIFY_SECONDS = 0.5
SIMPLIFY_MAX_OPS = 300


class BudgetExceeded(Exception):
    """Raised inside a budgeted block when its time is up."""


@contextmanager
def time_limit(seconds: float) -> Iterator[None]:
    """Raise BudgetExceeded in the block after ``seconds`` (main thread only).

    Limits nest: an inner block gets at most the time the outer one has left,
    and the outer limit is re-armed with what remains when the inner block ends
    (at once, if it ran out meanwhile), so a whole derivation can have a budget
    while its optional refinements have smaller ones.
    """
    # sp.simplify imports sympy.physics.units on its first call (0.4 s, more on a busy machine). The
    # outermost limit imports it before arming its timer, so that no budget ever interrupts that import
    # halfway (leaving every later simplification to retry it and be cut short again); a process that
    # never simplifies (the web process serving from the caches) never pays for it.
    import sympy.physics.units  # noqa: F401

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    outer, _ = signal.getitimer(signal.ITIMER_REAL)
    started = time.monotonic()
    seconds = min(seconds, outer) if outer > 0 else seconds

    def _expire(signum: int, frame: object) -> None:
        # A signal landing in an interpreter callback (a gc callback, a finaliser)
        # would raise there and be lost: try again in a millisecond instead.
        module = getattr(frame, "f_globals", {}).get("__name__", "")
        if not module.startswith(("sympy", "app.", "mpmath")):
            signal.setitimer(signal.ITIMER_REAL, 0.001)
            return
        raise BudgetExceeded

    previous = signal.signal(signal.SIGALRM, _expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if outer > 0:
            signal.setitimer(signal.ITIMER_REAL, max(outer - (time.monotonic() - started), 0.001))


def within_budget(work: Callable[[], T], fallback: T, seconds: float) -> T:
    """Run ``work``; on timeout (or a SymPy failure) return ``fallback``."""
    try:
        with time_limit(seconds):
            return work()
    except (BudgetExceeded, NotImplementedError, RecursionError, TypeError, ValueError):
        return fallback


_local = threading.local()
_TIDY_CACHE: dict[sp.Expr, sp.Expr] = {}
_TIDY_CACHE_SIZE = 2048


@contextmanager
def display_budget(seconds: float) -> Iterator[None]:
    """Share one time budget among all display simplifications in the block."""
    previous = getattr(_local, "deadline", None)
    _local.deadline = time.monotonic() + seconds
    try:
        yield
    finally:
        _local.deadline = previous


@contextmanager
def unbudgeted() -> Iterator[None]:
    """Work in the block (display printing) does not count against the shared display budget."""
    started = time.monotonic()
    try:
        yield
    finally:
        if getattr(_local, "deadline", None) is not None:
            _local.deadline += time.monotonic() - started


def _remaining(seconds: float) -> float:
    deadline = getattr(_local, "deadline", None)
    return seconds if deadline is None else min(seconds, deadline - time.monotonic())


def tidy(expr: sp.Expr, seconds: float = SIMPLIFY_SECONDS) -> sp.Expr:
    """A display form: cheap normalisation always, full simplify when small and quick.

    Results reached within budget are remembered (derivations repeat many
    expressions); once a shared display budget is spent, expressions are shown
    as they are.
    """
    if expr in _TIDY_CACHE:
        return _TIDY_CACHE[expr]
    left = _remaining(seconds)
    if left <= 0.01:
        return expr
    cheap = within_budget(lambda: sp.factor_terms(sp.cancel(expr)), None, left)
    if cheap is None:
        return expr
    result = cheap
    if sp.count_ops(cheap) <= SIMPLIFY_MAX_OPS:
        left = _remaining(seconds)
        full = within_budget(lambda: sp.simplify(cheap), None, left) if left > 0.01 else None
        if full is None:
            # simplify failed or ran out of its own time (not a shared budget's rest): it would again, so the
            # cheap form is remembered (a derivation shows its accelerations twice, and the double
            # pendulum's document spent 0.5 s on each attempt)
            if left >= seconds and len(_TIDY_CACHE) < _TIDY_CACHE_SIZE:
                _TIDY_CACHE[expr] = cheap
            return cheap
        # Keep the angles the reader wrote: reject forms that trade sin θ cos θ for sin 2θ.
        if not (_angles(full) - _angles(cheap)) and sp.count_ops(full) <= sp.count_ops(cheap):
            result = full
    if len(_TIDY_CACHE) < _TIDY_CACHE_SIZE:
        _TIDY_CACHE[expr] = result
    return result


def _angles(expr: sp.Expr) -> set[sp.Expr]:
    return {f.args[0] for f in expr.atoms(sp.sin, sp.cos, sp.tan)}


def pythagoras(expr: sp.Expr) -> sp.Expr:
    """Collapse sin²a + cos²a = 1 for every angle a, cheaply and deterministically.

    For each angle both rewritings (sin² → 1 − cos², cos² → 1 − sin²) are tried
    and the shorter result kept, so a kinetic energy keeps its natural form.
    """
    angles = sorted({f.args[0] for f in expr.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
    best = sp.expand(expr)
    for a in angles:
        # only the terms with sin a or cos a change: rewrite and expand those, keep the rest as it is
        # (the same result as rewriting the whole expanded sum, at a fraction of the cost for long sums)
        touched: list[sp.Expr] = []
        rest: list[sp.Expr] = []
        for term in sp.Add.make_args(best):
            (touched if term.has(sp.sin(a), sp.cos(a)) else rest).append(term)
        if not touched:
            continue
        part, others = sp.Add(*touched), sp.Add(*rest)
        options = [
            best,
            others + sp.expand(part.subs(sp.sin(a) ** 2, 1 - sp.cos(a) ** 2)),
            others + sp.expand(part.subs(sp.cos(a) ** 2, 1 - sp.sin(a) ** 2)),
        ]
        best = min(options, key=sp.count_ops)
    return best


def is_zero(expr: sp.Expr) -> bool:
    """Decide expr == 0: exact cancellation first, then a budgeted simplification."""
    expanded = sp.expand(expr)
    if expanded == 0:
        return True
    if pythagoras(expanded) == 0:
        return True
    return tidy(expanded) == 0
