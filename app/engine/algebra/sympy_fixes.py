"""One slow path inside SymPy stepped around, without changing any answer.

``sympy.core.exprtools.Factors(d)`` begins with ``d in (None, S.One)``.  For a dict ``d`` that compares
``S.One == d``; SymPy's ``Integer.__eq__`` then sympifies ``d`` into a ``Dict`` (every key and value
converted, hashed and sorted) only to find that a ``Dict`` is not a number.  ``gcd_terms``, under every
``factor_terms``, builds a ``Factors`` from a dict (a ``defaultdict`` from ``Term``) for each term it
touches: that conversion was a sixth of a user's double pendulum's whole document (0.54 s → 0.46 s).

The fix hands ``Factors`` the same dict marked as one SymPy must not convert (``CantSympify``): the
comparison fails at once and ``Factors`` takes its dict branch, as before.  tests/engine/algebra/test_sympy_fixes.py
checks that the result is the same and that the conversion no longer happens.
"""

from __future__ import annotations

from collections import defaultdict
from typing import Any

from sympy.core.exprtools import Factors
from sympy.core.sympify import CantSympify


class _Plain(dict, CantSympify):
    """A dict that SymPy refuses to sympify (so ``S.One == it`` is False without converting it)."""


class _PlainDefault(defaultdict, CantSympify):
    """The same for the ``defaultdict(int)`` that ``Term`` hands over."""


_sympy_init = Factors.__init__


def _init(self: Factors, factors: Any = None) -> None:
    if type(factors) is dict:
        _sympy_init(self, _Plain(factors))  # its dict branch keeps a copy: a plain dict
    elif type(factors) is defaultdict:
        _sympy_init(self, _PlainDefault(factors.default_factory, factors))
        # the copy it keeps is of the marked type: hand back the type it was given
        self.factors = defaultdict(factors.default_factory, self.factors)
    else:
        _sympy_init(self, factors)


def install() -> None:
    """Put the fix in place (once; installing again changes nothing)."""
    if Factors.__init__ is not _init:
        Factors.__init__ = _init


install()
