"""Closed forms of the accelerations by Cramer's rule for three or more coordinates, kept when short enough to read.

LU elimination (``app.engine.equations.lagrange``) gives M⁻¹f for any number of coordinates, but untidied; for a
chain its forms are thousands of characters long and nobody reads them.  Some systems with many
coordinates have short accelerations all the same: a double-double Atwood machine's three are 63 to 89
characters.  So the decision is made on the result's length, not on the number of coordinates:

    q̈_k = det M_k / det M   (M_k: M with its k-th column replaced by f),

each determinant expanded on symengine (one past EXPANDED_MAX_CHARS is not tidied), brought back to SymPy with sin² + cos² = 1 collected and common
factors taken out, and the closed form kept when every acceleration's plain form is at most
CLOSED_FORM_MAX_CHARS characters.  Before anything is expanded, the number of terms det M can have is
bounded by the product over M's rows of the terms in each row (each term of the determinant takes one
term of one entry from every row); beyond DET_TERMS_MAX the closed form is not tried, since a denominator
of that many terms cannot be short (a four-link chain's bound is in the thousands).
"""

from __future__ import annotations

from dataclasses import dataclass
from math import prod

import symengine as se
import sympy as sp

from app.engine.algebra.fast import Fast, convertible, expand
from app.engine.algebra.simplify import pythagoras

# The longest acceleration, in characters of its plain form, still shown as a closed form (the double
# pendulum's longer one is 306).
CLOSED_FORM_MAX_CHARS = 400
# Longest expanded numerator or det M (symengine's plain form) that is tidied and measured.
EXPANDED_MAX_CHARS = 3 * CLOSED_FORM_MAX_CHARS
# At most this many terms in the expanded det M before Cramer's rule is tried at all.
DET_TERMS_MAX = 200


@dataclass(frozen=True)
class ClosedForms:
    """The accelerations when short enough, else none; and the reason, with the measured length."""

    accelerations: tuple[sp.Expr, ...] | None
    reason: str


def _terms(expr: se.Basic) -> int:
    return len(expr.args) if isinstance(expr, se.Add) else 1


def by_cramer(M: sp.Matrix, forcing: sp.Matrix, symbols: tuple[sp.Symbol, ...]) -> ClosedForms:
    """q̈ = (det M_k / det M)_k when every one is at most CLOSED_FORM_MAX_CHARS long, with the reason otherwise."""
    if not convertible((*M, *forcing)):
        return ClosedForms(None, "M or f has a function that is not solved symbolically for three or more coordinates")
    fast = Fast(symbols)
    A = se.Matrix([[expand(fast.to(x)) for x in row] for row in M.tolist()])
    n = A.rows
    # every term of det M is ± a product of one term from each row's entries
    bound = prod(sum(_terms(A[i, j]) for j in range(n)) for i in range(n))
    if bound > DET_TERMS_MAX:
        return ClosedForms(
            None, f"det M, the common denominator, can expand to as many as {bound} terms (more than {DET_TERMS_MAX})"
        )
    f = [expand(fast.to(x)) for x in forcing]
    det = expand(A.det())
    if det == 0:
        return ClosedForms(None, "det M expands to 0 symbolically")
    # Cramer: M_k is M with its k-th column replaced by f
    numerators = [
        expand(se.Matrix([[f[i] if j == k else A[i, j] for j in range(n)] for i in range(n)]).det()) for k in range(n)
    ]
    # tidying (sin² + cos² = 1, common factors) shortens a form by a third at most on the systems measured; an
    # expanded form past EXPANDED_MAX_CHARS is not tidied at all (tidying a three-link chain's took seconds)
    expanded = max(len(str(x)) for x in (det, *numerators))
    if expanded > EXPANDED_MAX_CHARS:
        return ClosedForms(
            None,
            f"expanded, a numerator or det M is {expanded} characters (more than {CLOSED_FORM_MAX_CHARS} are too "
            "long to read)",
        )
    denominator = sp.factor_terms(pythagoras(fast.back(det)))
    solved = [sp.factor_terms(pythagoras(fast.back(x))) / denominator for x in numerators]
    longest = max(len(str(a)) for a in solved)
    if longest > CLOSED_FORM_MAX_CHARS:
        return ClosedForms(
            None, f"the longest one is {longest} characters (more than {CLOSED_FORM_MAX_CHARS} are too long to read)"
        )
    return ClosedForms(tuple(solved), f"the longest one is {longest} characters")
