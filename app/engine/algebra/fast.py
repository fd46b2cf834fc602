"""The heavy algebra of a derivation on symengine (C++): derivatives, the mass matrix and the forcing.

SymPy builds every intermediate expression in Python and asks each for its
assumptions; differentiating the Lagrangian of a six-link chain that way takes
seconds.  symengine does the same differentiation in milliseconds.  Expressions
go to symengine once and come back to SymPy once, where display,
simplification and the checker need them; the results are the same
expressions (SymPy canonicalises what it is given), so nothing downstream
notices where they were computed.

Only expressions built from functions symengine differentiates as SymPy does
go this way (``convertible``); anything else (Abs, sign, atan2, piecewise
forms) stays on SymPy.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

import symengine as se
import sympy as sp

# Functions whose derivatives symengine and SymPy write alike (one smooth argument each).
SMOOTH = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc, sp.asin, sp.acos, sp.atan, sp.sinh, sp.cosh, sp.tanh,
          sp.exp, sp.log)  # fmt: skip


def convertible(exprs: Iterable[sp.Expr]) -> bool:
    """Whether every function in the expressions is one of SMOOTH (and every number exact or a float)."""
    for e in exprs:
        for f in e.atoms(sp.Function):
            if not isinstance(f, SMOOTH):
                return False
        if e.has(sp.Derivative, sp.Integral, sp.Piecewise):
            return False
    return True


class Fast:
    """Conversions between SymPy and symengine for one set of symbols (which keep their SymPy assumptions)."""

    def __init__(self, symbols: Iterable[sp.Symbol]):
        # symengine symbols carry only a name: map each name back to the SymPy symbol it came from
        self._symbols = {s.name: s for s in symbols}
        # each distinct subexpression is converted once (derivatives share many)
        self._done: dict[Any, sp.Expr] = {}

    @staticmethod
    def to(expr: sp.Expr) -> Any:
        return se.sympify(expr)

    def back(self, expr: Any) -> sp.Expr:
        """The SymPy expression, its symbols those given (with their assumptions), built bottom-up once."""
        done = self._done.get(expr)
        if done is not None:
            return done
        kind = type(expr).__name__
        if kind == "Symbol":
            result = self._symbols.get(expr.name) or sp.Symbol(expr.name)
        elif not expr.args:
            result = sp.sympify(expr)  # a number or a constant
        else:
            args = [self.back(a) for a in expr.args]
            make = _COMBINE.get(kind) or (getattr(sp, kind, None) if kind in _FUNCTIONS else None)
            result = make(*args) if make is not None else expr.func(*expr.args)._sympy_().func(*args)
        self._done[expr] = result
        return result

    def back_all(self, exprs: Sequence[Any]) -> tuple[sp.Expr, ...]:
        return tuple(self.back(e) for e in exprs)


_COMBINE = {"Add": sp.Add, "Mul": sp.Mul, "Pow": sp.Pow}
_FUNCTIONS = frozenset(f.__name__ for f in SMOOTH)


def diff(expr: Any, symbol: Any) -> Any:
    return se.diff(expr, symbol)


def expand(expr: Any) -> Any:
    return se.expand(expr)
