"""Products of sines and cosines of two angles merged pair by pair, as the angle-sum formulas read backwards.

A particle at the end of a chain of links moves with

    v² = Σᵢ lᵢ² θ̇ᵢ² + 2 Σᵢ<ⱼ lᵢ lⱼ θ̇ᵢ θ̇ⱼ (sin θᵢ sin θⱼ + cos θᵢ cos θⱼ),

and expanded, each bracket is two terms with the same coefficient.  Written as the one cosine they are,
cos(θᵢ − θⱼ), the kinetic energy is what a textbook prints, and everything derived from it (the
Euler–Lagrange equations, the mass matrix, the momenta, Hamilton's H) starts short instead of carrying
every product through and being recombined for display afterwards, expression by expression.

``merged`` looks only at terms that hold exactly two first-power sines or cosines; it pairs terms whose
other factors are equal and whose numbers agree up to sign, in one pass over the sum (no expansion, no
search: linear in the number of terms, where SymPy's ``TR10i`` tries every pair of terms).
"""

from __future__ import annotations

import sympy as sp

# (the kinds of the two factors, for angles a, b in a fixed order) -> the merged function for each relative sign:
#   c sin a sin b + c cos a cos b = c cos(a − b),   −c sin a sin b + c cos a cos b = c cos(a + b)
#   c sin a cos b − c cos a sin b = c sin(a − b),   c sin a cos b + c cos a sin b = c sin(a + b)
_PAIRS = {
    ("cc", "ss"): {1: lambda a, b: sp.cos(a - b), -1: lambda a, b: sp.cos(a + b)},
    ("sc", "cs"): {-1: lambda a, b: sp.sin(a - b), 1: lambda a, b: sp.sin(a + b)},
}


def _split(term: sp.Expr) -> tuple[sp.Expr, sp.Expr, str, tuple[sp.Expr, sp.Expr]] | None:
    """A term as (number, other factors, kinds, (a, b)) when it holds exactly two first-power sines or
    cosines of different angles; None otherwise."""
    number, rest = term.as_coeff_Mul()
    factors = sp.Mul.make_args(rest)
    trig = [f for f in factors if isinstance(f, (sp.sin, sp.cos))]
    if len(trig) != 2 or trig[0].args[0] == trig[1].args[0]:
        return None
    first, second = sorted(trig, key=lambda f: sp.default_sort_key(f.args[0]))
    others = sp.Mul(*(f for f in factors if f is not first and f is not second))
    kinds = ("s" if isinstance(first, sp.sin) else "c") + ("s" if isinstance(second, sp.sin) else "c")
    return number, others, kinds, (first.args[0], second.args[0])


def merged(expr: sp.Expr) -> sp.Expr:
    """``expr`` with each pair of terms c·sin a sin b and c·cos a cos b (or c·sin a cos b and ∓c·cos a sin b)
    written as the one cosine (sine) of a − b or a + b; an equal expression, never longer."""
    if not isinstance(expr, sp.Add):
        return expr
    terms = list(expr.args)
    splits = [_split(t) for t in terms]
    found: dict[tuple[sp.Expr, tuple[sp.Expr, sp.Expr], str], int] = {}
    for i, split in enumerate(splits):
        if split is not None:
            found.setdefault((split[1], split[3], split[2]), i)
    # each pair found from its first kind (cc, sc), each term in one pair at most
    replaced: dict[int, sp.Expr] = {}
    for i, split in enumerate(splits):
        if split is None or i in replaced:
            continue
        number, others, kinds, (a, b) = split
        for (kind, other), forms in _PAIRS.items():
            j = found.get((others, (a, b), other)) if kinds == kind else None
            if j is None or j in replaced:
                continue
            ratio = terms[j].as_coeff_Mul()[0] / number
            if ratio in forms:
                replaced[i], replaced[j] = number * others * forms[ratio](a, b), sp.Integer(0)
    if not replaced:
        return expr
    return sp.Add(*(replaced.get(i, t) for i, t in enumerate(terms)))
