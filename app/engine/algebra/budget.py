"""Bounds by work for SymPy work whose cost cannot be known in advance.

Simplification and equation solving are optional refinements: when they use up their bound the engine
keeps the unrefined (still correct) expression, and a member of the document that does is left out with a
note.  Every such bound counts work (app/engine/algebra/work.py: SymPy expressions built), never the clock, so what a
document holds is a function of its input alone: the same on an idle machine and on a loaded one, in the
worker's main thread and in any other.  The one clock is at the edge (``clock_limit``, the worker job's limit
on a user's system): when it fires the request is refused, never answered with a poorer document.
"""

from __future__ import annotations

import signal
import threading
import time
from collections.abc import Callable, Hashable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, TypeVar

from app.engine.algebra import progress
from app.engine.algebra import work as counted
from app.engine.algebra.work import WorkExceeded
from app.limits import MEMBER_RESERVE_WORK

T = TypeVar("T")

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
    """What is left of the shared display budget: at most ``units`` (times the patience in force), no more than
    the budget has left (the units of work before its end; ``deadline`` is the end of the document's share,
    counted in work)."""
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
