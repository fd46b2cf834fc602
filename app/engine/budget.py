"""Bounds by work for SymPy work whose cost cannot be known in advance.

Simplification and equation solving are optional refinements: when they use up their bound the engine
keeps the unrefined (still correct) expression, and a member of the document that does is left out with a
note.  Every such bound counts work (app/engine/work.py: SymPy expressions built), never the clock, so what a
document holds is a function of its input alone: the same on an idle machine and on a loaded one, in the
worker's main thread and in any other.  The one clock is at the edge (``clock_limit``, the worker job's limit
on a user's system): when it fires the request is refused, never answered with a poorer document.
"""

from __future__ import annotations

import math
import random
import signal
import threading
import time
from collections.abc import Callable, Hashable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, TypeVar

import sympy as sp

from app.engine import progress
from app.engine import work as counted
from app.engine.work import WorkExceeded
from app.limits import MEMBER_RESERVE_WORK, SIMPLIFY_WORK

T = TypeVar("T")

SIMPLIFY_MAX_OPS = 300
# pythagoras expands its argument; above this many nodes (counted before expanding) it leaves it as it is:
# an LU-solved acceleration of the triple pendulum (a few thousand nodes) did not expand in 300 s
PYTHAGORAS_MAX_NODES = 600
# below this many nodes it always runs (milliseconds), even once a shared display budget is spent
PYTHAGORAS_SMALL_NODES = 150
# what is left of a bound below which no refinement starts (units of work: about 0.01 s on this machine)
SPENT = 200


class OutOfTime(Exception):
    """Raised inside a ``clock_limit`` block when its wall-clock time is up: the request is refused.

    Not a ``WorkExceeded``: no bound inside the engine catches it, so a fired clock never turns into a
    member left out or a plainer form (a poorer document that a busy machine would cause)."""


@contextmanager
def clock_limit(seconds: float) -> Iterator[None]:
    """Raise OutOfTime in the block after ``seconds`` of wall-clock time (main thread only; elsewhere no limit).

    The one clock of a user's request, at its edge: what it cuts short is refused, never shown.  Clocks
    nest: an inner block gets at most the time the outer one has left, and the outer clock is re-armed with
    what remains when the inner block ends (at once, if it ran out meanwhile).
    """
    # sp.simplify imports sympy.physics.units on its first call (0.4 s, more on a busy machine): imported
    # before the timer starts, so that the clock never interrupts that import halfway
    import sympy.physics.units  # noqa: F401

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def _expire(signum: int, frame: object) -> None:
        # A signal landing in an interpreter callback (a gc callback, a finaliser)
        # would raise there and be lost: try again in a millisecond instead.
        module = getattr(frame, "f_globals", {}).get("__name__", "")
        if not module.startswith(("sympy", "app.", "mpmath")):
            signal.setitimer(signal.ITIMER_REAL, 0.001)
            return
        raise OutOfTime

    outer, _ = signal.getitimer(signal.ITIMER_REAL)
    started = time.monotonic()
    seconds = min(seconds, outer) if outer > 0 else seconds
    previous = signal.signal(signal.SIGALRM, _expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if outer > 0:
            signal.setitimer(signal.ITIMER_REAL, max(outer - (time.monotonic() - started), 0.001))


@contextmanager
def work_limit(units: float) -> Iterator[None]:
    """Raise WorkExceeded in the block after ``units`` units of work (times the patience in force).

    Limits nest: an inner block gets at most the work the outer one has left, so a whole step can have a
    bound while its optional refinements have smaller ones.
    """
    with counted.limit(units * _patience()):
        yield


def within_budget(work: Callable[[], T], fallback: T, units: float) -> T:
    """Run ``work`` within ``units`` of work; past it (or on a SymPy failure) return ``fallback``."""
    try:
        with work_limit(units):
            return work()
    except (WorkExceeded, NotImplementedError, RecursionError, TypeError, ValueError):
        return fallback


@dataclass(frozen=True)
class Skipped:
    """A member of the document left out, and why (shown in its place; never a refusal of the system)."""

    member: str
    reason: str


def bounded(member: str, what: str, units: float, work: Callable[[], T], fallback: T, skipped: list[Skipped]) -> T:
    """``work()`` within its own bound of work; past it, ``fallback`` and a note in ``skipped``.

    The bound never reaches into an enclosing bound's last MEMBER_RESERVE_WORK, so a costly member leaves
    work for the rest of the step instead of using it all.  ``what`` names the part in the note
    ("Hamilton's equations").
    """
    progress.now(what)
    units *= _patience()
    outer = counted.left()
    if outer is not None:
        units = min(units, outer - MEMBER_RESERVE_WORK)
    if units <= 0:
        skipped.append(Skipped(member, f"{what} left out: the work allowed for this document was used up by the parts above."))
        return fallback
    try:
        with counted.limit(units):
            return work()
    except WorkExceeded:
        skipped.append(
            Skipped(member, f"{what} left out: working it out needs more than the bound of work the engine allows it. "
                    "The rest of the derivation is complete; this is a limit of the engine, not of the system.")
        )  # fmt: skip
        return fallback


_local = threading.local()
_TIDY_CACHE: dict[sp.Expr, sp.Expr] = {}
_TIDY_CACHE_SIZE = 2048
_PYTHAGORAS_CACHE: dict[sp.Expr, sp.Expr] = {}


@contextmanager
def display_budget(units: float) -> Iterator[None]:
    """Share one bound of work among all display simplifications in the block, and one memo (``memoized``):
    the outermost block is one document, and what it remembers ends with it."""
    previous, memo = getattr(_local, "deadline", None), getattr(_local, "memo", None)
    _local.deadline = counted.done() + units * _patience()
    if memo is None:
        _local.memo = {}
    try:
        yield
    finally:
        _local.deadline, _local.memo = previous, memo


def document_memo() -> dict[Any, Any] | None:
    """The current document's memo (None outside any ``display_budget`` block)."""
    memo: dict[Any, Any] | None = getattr(_local, "memo", None)
    return memo


def memoized(kind: str, key: Hashable, compute: Callable[[], T], charged: bool = False) -> T:
    """``compute()``, remembered under (kind, key) for the rest of the current document (the outermost
    ``display_budget`` block); outside any document, computed every time.  Only for pure work: a result that
    depends on a bound must not be remembered here.

    ``charged``: each later use counts the work the computation counted (``work.charge``), so every bound
    around it ends where it did when the work was done at each use: the document is the same, only faster."""
    memo: dict[tuple[str, Hashable], Any] | None = getattr(_local, "memo", None)
    if memo is None:
        return compute()
    if (kind, key) in memo:
        if not charged:
            return memo[(kind, key)]
        value, units = memo[(kind, key)]
        counted.charge(units)
        return value
    started = counted.done()
    value = compute()
    memo[(kind, key)] = (value, counted.done() - started) if charged else value
    return value


@contextmanager
def unbudgeted() -> Iterator[None]:
    """Work in the block (display printing) does not count against the shared display budget."""
    started = counted.done()
    try:
        yield
    finally:
        if getattr(_local, "deadline", None) is not None:
            _local.deadline += counted.done() - started


def display_work_left(units: float) -> float:
    """What is left of the shared display budget (at most ``units``, times the patience in force)."""
    return _remaining(units)


def _remaining(units: float) -> float:
    """At most ``units`` (times the patience), no more than the shared display budget has left (the units of
    work before its end; the name ``deadline`` is the end of the document's share, counted in work)."""
    deadline = getattr(_local, "deadline", None)
    units *= _patience()
    return units if deadline is None else min(units, deadline - counted.done())


def _patience() -> float:
    return getattr(_local, "patience", 1.0)


@contextmanager
def patience(factor: float) -> Iterator[None]:
    """Every bound of work in the block (limits, members, the display budget) is ``factor`` times as large.

    For the chapter's scenes: their documents are derived once per version of the program and kept on disk,
    and the book prints each of them whole; a user's system keeps the bounds as they are."""
    previous = _patience()
    _local.patience = previous * factor
    try:
        yield
    finally:
        _local.patience = previous


def tidy(expr: sp.Expr, units: float = SIMPLIFY_WORK) -> sp.Expr:
    """A display form: cheap normalisation always, full simplify when small and quick.

    Results reached within their bound of work are remembered (derivations repeat many
    expressions); once a shared display budget is spent, expressions are shown
    as they are.
    """
    if expr in _TIDY_CACHE:
        return _TIDY_CACHE[expr]
    left = _remaining(units)
    if left <= SPENT:
        return expr
    cheap = within_budget(lambda: sp.factor_terms(sp.cancel(expr)), None, left)
    if cheap is None:
        return expr
    result = cheap
    if sp.count_ops(cheap) <= SIMPLIFY_MAX_OPS and not _product(cheap):
        left = _remaining(units)
        full = within_budget(lambda: sp.simplify(cheap), None, left) if left > SPENT else None
        if full is None:
            # simplify failed or used up its own bound (not a shared budget's rest): it would again, so the
            # cheap form is remembered (a derivation shows its accelerations twice, and the double
            # pendulum's document spent 0.5 s on each attempt)
            if left >= units and len(_TIDY_CACHE) < _TIDY_CACHE_SIZE:
                _TIDY_CACHE[expr] = cheap
            return cheap
        # Keep the angles the reader wrote: reject forms that trade sin θ cos θ for sin 2θ.
        if not (_angles(full) - _angles(cheap)) and sp.count_ops(full) <= sp.count_ops(cheap):
            result = full
    if len(_TIDY_CACHE) < _TIDY_CACHE_SIZE:
        _TIDY_CACHE[expr] = result
    return result


def _product(expr: sp.Expr) -> bool:
    """A product of integer powers with at most one function in it and no sum anywhere (m l², g cos θ/l):
    simplify has nothing to combine there, and costs ~10 ms to say so (it returned every such form of every
    scene and example unchanged); a single pendulum's reduction tidies six of them."""
    return (
        not expr.atoms(sp.Add)
        and len(expr.atoms(sp.Function)) <= 1
        and all(p.exp.is_Integer for p in expr.atoms(sp.Pow))
    )


def _merge_pairs(expr: sp.Expr, a: sp.Expr) -> sp.Expr:
    """expr with every pair c sin²a + c cos²a (the same c) replaced by c."""
    sin2, cos2 = sp.sin(a) ** 2, sp.cos(a) ** 2
    by_sin: dict[sp.Expr, int] = {}
    terms = list(sp.Add.make_args(expr))
    for i, term in enumerate(terms):
        if term.as_powers_dict().get(sp.sin(a)) == 2:
            by_sin.setdefault(term / sin2, i)
    if not by_sin:
        return expr
    merged = False
    for i, term in enumerate(terms):
        if term.as_powers_dict().get(sp.cos(a)) == 2:
            j = by_sin.pop(term / cos2, None)
            if j is not None:
                terms[j], terms[i], merged = term / cos2, sp.Integer(0), True
    return sp.Add(*terms) if merged else expr


def _even_power(term: sp.Expr, a: sp.Expr) -> bool:
    """Whether the product ``term`` has sin(a) or cos(a) to an even power (what sin² → 1 − cos² rewrites)."""
    return any(
        isinstance(base, (sp.sin, sp.cos)) and base.args[0] == a and e.is_Integer and e % 2 == 0
        for base, e in term.as_powers_dict().items()
    )


def _angles(expr: sp.Expr) -> set[sp.Expr]:
    return {f.args[0] for f in expr.atoms(sp.sin, sp.cos, sp.tan)}


def larger_than(expr: sp.Basic, nodes: int) -> bool:
    """True when the expression tree has more than ``nodes`` nodes, found without walking past that many.

    Solved accelerations share their subexpressions (LU elimination reuses each pivot's row), so a
    full walk (count_ops, has, free_symbols, printing) of a six-link chain visits millions of nodes;
    this walk stops at the limit.
    """
    for seen, _ in enumerate(sp.preorder_traversal(expr), start=1):
        if seen > nodes:
            return True
    return False


def pythagoras(expr: sp.Expr) -> sp.Expr:
    """Collapse sin²a + cos²a = 1 for every angle a, cheaply and deterministically.

    For each angle both rewritings (sin² → 1 − cos², cos² → 1 − sin²) are tried
    and the shorter result kept, so a kinetic energy keeps its natural form.
    An expression larger than PYTHAGORAS_MAX_NODES is returned as it is (expanding it is the
    cost, and it can exceed any bound: SymPy's expand of a large sum builds few expressions per term).
    """
    if expr in _PYTHAGORAS_CACHE:
        return _PYTHAGORAS_CACHE[expr]
    if larger_than(expr, PYTHAGORAS_MAX_NODES) or (
        larger_than(expr, PYTHAGORAS_SMALL_NODES) and _remaining(SPENT + 1) <= SPENT
    ):
        return expr  # too large to expand, or not small once the shared display budget is spent: as it is
    result, complete = _pythagoras(expr)
    if complete and len(_PYTHAGORAS_CACHE) < _TIDY_CACHE_SIZE:
        _PYTHAGORAS_CACHE[expr] = result  # the document shows each residual and force two or three times
    return result


def _pythagoras(expr: sp.Expr) -> tuple[sp.Expr, bool]:
    angles = sorted({f.args[0] for f in expr.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
    best = sp.expand(expr)
    for a in angles:
        # c sin²a + c cos²a = c, pair by pair: what particles' speeds are made of, found without expanding
        best = _merge_pairs(best, a)
        # only the terms with sin a or cos a change: rewrite and expand those, keep the rest as it is
        # (the same result as rewriting the whole expanded sum, at a fraction of the cost for long sums)
        touched: list[sp.Expr] = []
        rest: list[sp.Expr] = []
        for term in sp.Add.make_args(best):
            (touched if term.has(sp.sin(a), sp.cos(a)) else rest).append(term)
        # only even powers of sin a or cos a change under the rewriting: none, nothing to try
        if not touched or not any(_even_power(term, a) for term in touched):
            continue
        if _remaining(SPENT + 1) <= SPENT and larger_than(best, PYTHAGORAS_SMALL_NODES):
            return best, False  # the shared display budget ran out: what is collapsed so far
        part, others = sp.Add(*touched), sp.Add(*rest)
        options = [
            best,
            others + sp.expand(part.subs(sp.sin(a) ** 2, 1 - sp.cos(a) ** 2)),
            others + sp.expand(part.subs(sp.cos(a) ** 2, 1 - sp.sin(a) ** 2)),
        ]
        best = min(options, key=sp.count_ops)
    return best, True


def is_zero(expr: sp.Expr) -> bool:
    """Decide expr == 0: exact cancellation first, then a budgeted simplification."""
    if larger_than(expr, PYTHAGORAS_MAX_NODES):
        return not nonzero_somewhere(expr) and tidy(expr) == 0
    expanded = sp.expand(expr)
    if expanded == 0:
        return True
    if nonzero_somewhere(expanded):
        return False
    if pythagoras(expanded) == 0:
        return True
    return tidy(expanded) == 0


def nonzero_somewhere(expr: sp.Expr, digits: int = 30) -> bool:
    """True when expr is certainly not identically zero: its value at a random point is clearly nonzero.

    The value is computed to ``digits`` digits and compared with the size of the terms it sums, so
    rounding in a sum that cancels exactly (about 10⁻³⁰ of its terms) is never taken for a nonzero
    value.  False says nothing (the point may be a zero, or outside the domain): the caller goes on
    to simplify.  This spares the simplification of every derivative that is plainly nonzero.
    """
    rng = random.Random(20261126)
    point = {s: sp.Float(rng.uniform(0.3, 1.7), digits) for s in expr.free_symbols}
    try:
        if larger_than(expr, PYTHAGORAS_MAX_NODES):
            # too large to expand into terms: its value to ``digits`` digits against an absolute floor far
            # above the rounding (about 10^-digits of the intermediate values, which are of order one here)
            value = abs(complex(sp.N(expr.xreplace(point), digits)))
            return bool(math.isfinite(value) and value > 10.0 ** (8 - digits // 2))
        terms = [complex(sp.N(term.xreplace(point), digits)) for term in sp.Add.make_args(expr)]
    except (TypeError, ValueError, ArithmeticError):
        return False
    scale = sum(abs(x) for x in terms)
    value = abs(sum(terms))
    return bool(math.isfinite(scale) and scale > 0 and value > 1e-12 * scale)
