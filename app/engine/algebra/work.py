"""The engine's measure of work: SymPy expressions built, counted per thread.

A bound that decides *what* a document holds (a member, a display form, a diagnosis) must end at the same
place for the same input on an idle machine and on a loaded one, so it cannot read a clock.  It reads this
count instead: every sum, product, power and function application SymPy is asked to build (``Add``, ``Mul``,
``Pow``, ``sin(...)``...), counted when it is asked for, whether SymPy's cache answers it or not, plus every
sparse polynomial product and sum (what ``cancel``, ``factor`` and ``solve`` spend their time on between two
expressions).  The count of a piece of work is a function of the work alone; on this machine, idle, about
``WORK_PER_SECOND`` units are done per second (app/limits.py), which is how the bounds were calibrated.

A limit (``limit``) is a count at which the next unit raises ``WorkExceeded`` in the thread that does the
work; limits nest (an inner one never reaches past the outer one).  The counters are installed once, when
this module is imported (app/engine/__init__.py imports it before any SymPy work), by wrapping each
constructor from outside: its result is SymPy's own, unchanged.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from sympy.core.cache import clear_cache
from sympy.core.function import Application
from sympy.core.operations import AssocOp
from sympy.core.power import Pow
from sympy.polys.rings import PolyElement


class WorkExceeded(Exception):
    """Raised in a bounded block when its count of work is reached."""


class _Count(threading.local):
    done = 0  # units of work done in this thread since it started
    limit: int | None = None  # the count at which work raises WorkExceeded (None: no limit)


_count = _Count()


def done() -> int:
    """The units of work done so far in this thread."""
    return _count.done


def left() -> int | None:
    """The units of work left before the innermost limit of this thread (None outside every limit)."""
    return None if _count.limit is None else max(_count.limit - _count.done, 0)


def charge(units: int) -> None:
    """Count ``units`` of work as done now: work remembered from an earlier computation, counted again where its
    result is used again, so that every bound ends where it ended when the work was done twice.  Past the
    innermost limit it raises WorkExceeded, the count standing one past the limit as if the work had run into it."""
    count = _count
    count.done += units
    if count.limit is not None and count.done > count.limit:
        count.done = count.limit + 1
        raise WorkExceeded


@contextmanager
def limit(units: float) -> Iterator[None]:
    """Raise WorkExceeded in the block once ``units`` more units of work are done in this thread.

    An inner limit never reaches past an enclosing one; the enclosing limit holds again when the block
    ends (so work past it raises at the next unit).
    """
    previous = _count.limit
    end = _count.done + max(int(units), 0)
    _count.limit = end if previous is None else min(end, previous)
    try:
        yield
    finally:
        _count.limit = previous


def start_afresh() -> None:
    """Empty SymPy's cache, so that the count of the work that follows depends on that work, not on what ran before.

    SymPy's cache answers a construction it has seen, and a cached ``expand`` or assumption skips every
    construction inside it: a user's double pendulum counted 23,000 units as a worker's first job, 5,600
    right after the same job, and 8,900 ± 50 after an emptied cache whatever ran before (the rest varies
    with hash order and the assumptions kept on long-lived symbols).  A worker calls this before each job
    (app/service/runtime/worker.py), at a price of about a third of a warm job's time.
    """
    clear_cache()


def _counted(build: Callable[..., Any]) -> Callable[..., Any]:
    def counted(*args: Any, **kwargs: Any) -> Any:
        count = _count
        count.done += 1
        if count.limit is not None and count.done > count.limit:
            raise WorkExceeded
        return build(*args, **kwargs)

    counted.__wrapped__ = build  # type: ignore[attr-defined]
    counted.__doc__ = build.__doc__
    return counted


def _install() -> None:
    for cls, name in ((AssocOp, "__new__"), (Pow, "__new__"), (Application, "__new__"),
                      (PolyElement, "__add__"), (PolyElement, "__sub__"), (PolyElement, "__mul__")):  # fmt: skip
        original = cls.__dict__[name]
        static = isinstance(original, staticmethod)  # a class's __new__ is kept as one
        function = original.__func__ if static else original
        if getattr(function, "_work", False):
            continue  # installed already
        wrapped = _counted(function)
        wrapped._work = True  # type: ignore[attr-defined]
        setattr(cls, name, staticmethod(wrapped) if static else wrapped)


_install()
