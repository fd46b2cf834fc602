"""Simplification for display and for deciding zero, within the bounds of work of app/engine/algebra/budget.py.

``tidy`` is the display form of an expression (a cheap normalisation, then a full simplification when it is
small and quick); ``pythagoras`` collapses sin²a + cos²a = 1 for every angle a; ``is_zero`` decides
expr = 0, by exact cancellation first, then a value at a random point, then a bounded simplification.
"""

from __future__ import annotations

import math
import random

import sympy as sp

from app.engine.algebra.budget import SPENT, display_work_left, within_budget
from app.limits import SIMPLIFY_WORK

SIMPLIFY_MAX_OPS = 300
# pythagoras expands its argument; above this many nodes (counted before expanding) it leaves it as it is:
# an LU-solved acceleration of the triple pendulum (a few thousand nodes) did not expand in 300 s
PYTHAGORAS_MAX_NODES = 600
# below this many nodes it always runs (milliseconds), even once a shared display budget is spent
PYTHAGORAS_SMALL_NODES = 150

_TIDY_CACHE: dict[sp.Expr, sp.Expr] = {}
_TIDY_CACHE_SIZE = 2048
_PYTHAGORAS_CACHE: dict[sp.Expr, sp.Expr] = {}


def tidy(expr: sp.Expr, units: float = SIMPLIFY_WORK) -> sp.Expr:
    """A display form: cheap normalisation always, full simplify when small and quick.

    Results reached within their bound of work are remembered (derivations repeat many
    expressions); once a shared display budget is spent, expressions are shown
    as they are.
    """
    if expr in _TIDY_CACHE:
        return _TIDY_CACHE[expr]
    left = display_work_left(units)
    if left <= SPENT:
        return expr
    cheap = within_budget(lambda: sp.factor_terms(sp.cancel(expr)), None, left)
    if cheap is None:
        return expr
    result = cheap
    if sp.count_ops(cheap) <= SIMPLIFY_MAX_OPS and not _product(cheap):
        left = display_work_left(units)
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
        larger_than(expr, PYTHAGORAS_SMALL_NODES) and display_work_left(SPENT + 1) <= SPENT
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
        if display_work_left(SPENT + 1) <= SPENT and larger_than(best, PYTHAGORAS_SMALL_NODES):
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
