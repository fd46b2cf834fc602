"""Piecewise-smooth expressions (``Abs``, ``sign``) evaluated away from their kinks.

d|u|/du = sign(u) and d sign(u)/du = 2 δ(u): a derivative of a piecewise-smooth
expression carries Dirac deltas at the kinks.  Numbers are only ever asked for
at points off the kinks (a set of measure zero that a random sample point, a
root finder's iterate or a Newton step lands on almost never), where every
delta is 0; so before an expression becomes numeric code its deltas are dropped.
"""

from __future__ import annotations

import sympy as sp


def away_from_kinks(expr: sp.Expr) -> sp.Expr:
    """The expression with every DiracDelta replaced by 0 (its value off the kinks)."""
    expr = sp.sympify(expr)
    if not expr.has(sp.DiracDelta):
        return expr
    return expr.replace(lambda e: isinstance(e, sp.DiracDelta), lambda e: sp.S.Zero)
