"""Quotients as a textbook writes them: no fraction inside a denominator, each term over its own denominator.

Three rules, each returning an expression equal to the one given (identically):

* ``cleared``: a denominator holding a fraction is multiplied through by that fraction's denominator,
  g/(m₁ + m₂ + 4m₁m₂/M) = Mg/(4m₁m₂ + M(m₁ + m₂));
* ``grouped``: a constant denominator of three or more terms takes out the parameter most of its terms
  share (not all: a factor of all is taken out anyway), M m₁ + M m₂ + 4 m₁ m₂ = 4m₁m₂ + M(m₁ + m₂);
* ``own_denominators``: a sum over a product of symbols whose terms, each cancelled, have different
  denominators is written as that sum of terms, each over its own denominator, the factor in front of the
  sum distributed, when that factor moves or the sum holds a fraction of its own: r(mθ̇² − k)/m = rθ̇² − (k/m)r,
  and Hamilton's ½(kr² + (p_r² + p_θ²/r²)/m) = p_r²/(2m) + p_θ²/(2mr²) + ½kr²; a constant before a bracket,
  (m/2R)(Rθ̇² + g cos θ), stays.
  A sum over a sum (the pulley's accelerations over 4m₁m₂ + M(m₁ + m₂), the double pendulum's over
  l₁(2m₁ + m₂ − m₂ cos(2θ₁ − 2θ₂))) keeps its one denominator.
"""

from __future__ import annotations

import sympy as sp

from app.engine.display.names import MASS_NAME

MAX_NODES = 300  # larger expressions are left as they are (each term's cancellation is then not cheap)


def _small(expr: sp.Expr) -> bool:
    count = 0
    for _ in sp.preorder_traversal(expr):
        count += 1
        if count > MAX_NODES:
            return False
    return True


def _holds_fraction(base: sp.Expr, monomial: bool = False) -> bool:
    """A sum with a term divided by something not a number: m₁ + m₂ + 4m₁m₂/M (``monomial``: by a product of
    symbols and functions only, not by a sum, as the double pendulum's ṗ over (m₁ + m₂ sin²(θ₁ − θ₂))²)."""
    return isinstance(base, sp.Add) and any(
        sp.denom(t).free_symbols and not (monomial and _has_sum(sp.denom(t))) for t in base.args
    )


def _has_sum(den: sp.Expr) -> bool:
    return any(isinstance(f.as_base_exp()[0], sp.Add) for f in sp.Mul.make_args(den))


def grouped(den: sp.Expr) -> sp.Expr:
    """A constant sum of three or more terms with the symbol most of them share (two at least, not all) taken
    out of those terms: M m₁ + M m₂ + 4 m₁ m₂ -> 4 m₁ m₂ + M (m₁ + m₂)."""
    if not isinstance(den, sp.Add) or len(den.args) < 3 or den.has(sp.Function):
        return den
    if not all(t.as_coeff_Mul()[0].is_Integer for t in den.args):
        return den  # numbers not yet whole (M m₁/2 + …): the printer takes the half out first
    terms = den.args
    counts = {s: sum(1 for t in terms if t.has(s)) for s in sorted(den.free_symbols, key=sp.default_sort_key)}
    best = max(counts, key=lambda s: counts[s], default=None)
    if best is None or not 2 <= counts[best] < len(terms):
        return den
    # the terms linear in the symbol share it as a factor; a term with its square stays as it is
    inside = [t for t in terms if sp.degree(t, best) == 1]
    if len(inside) < 2:
        return den
    rest = [t for t in terms if t not in inside]
    return sp.Add(*rest, best * sp.Add(*(t / best for t in inside)))


def _number_most_masses_carry(den: sp.Expr) -> sp.Integer | None:
    """The whole number most terms of a sum of masses carry (M + 2m₁ + 2m₂: 2), where not all carry it; else None."""
    if not isinstance(den, sp.Add) or not all(
        t.as_coeff_Mul()[0].is_Integer and t.as_coeff_Mul()[0] > 0 and MASS_NAME.fullmatch(str(t.as_coeff_Mul()[1]))
        for t in den.args
    ):
        return None
    numbers = [t.as_coeff_Mul()[0] for t in den.args]
    most = max(sorted(set(numbers), key=sp.default_sort_key), key=numbers.count)
    return most if most != 1 and numbers.count(most) * 2 > len(numbers) and len(set(numbers)) > 1 else None


def cleared(expr: sp.Expr) -> sp.Expr:
    """Every denominator holding a fraction multiplied through: 1/(a + b/c) = c/(ac + b), the new denominator
    ``grouped``."""
    if not isinstance(expr, sp.Expr) or not _small(expr):
        return expr

    def clear(power: sp.Pow) -> sp.Expr:
        num, den = sp.fraction(sp.together(power.base))
        return (grouped(sp.expand(num)) / den) ** power.exp

    # (only a whole power: under a root a fraction stays, as √(1 − ẋ²/c²) is printed)
    out = expr.replace(lambda e: e.is_Pow and e.exp.is_negative and e.exp.is_Integer and _holds_fraction(e.base), clear)
    if out == expr:
        return expr
    # a number common to a sum's terms in front of it: 2(m₁ + m₂), not (2m₁ + 2m₂)
    return out.replace(
        lambda e: e.is_Mul and any(isinstance(f, sp.Add) for f in e.args),
        lambda e: sp.Mul(*(sp.factor_terms(f) if isinstance(f, sp.Add) else f for f in e.args)),
    )


def denominators_grouped(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """Every constant denominator with the factor common to all its terms taken out, then ``grouped``:
    p_r²/(2m + 2mc²) -> p_r²/(2m(1 + c²)), g/(M m₁ + M m₂ + 4 m₁ m₂) -> g/(4 m₁ m₂ + M (m₁ + m₂))."""
    if not isinstance(expr, sp.Expr) or not _small(expr):
        return expr

    def group(e: sp.Pow) -> sp.Expr:
        # 2m + 2mc² = 2m(1 + c²): what every term holds goes in front of the sum
        common, rest = sp.factor_terms(e.base).as_independent(sp.Add, as_Add=False)
        if isinstance(rest, sp.Add) and common != 1:
            return sp.Pow(common * grouped(rest), e.exp)
        most = _number_most_masses_carry(e.base)
        if most is not None:
            # a sum of masses with the number most of them carry in front, so that the inertia reads as it does
            # in T and 𝓜: M + 2m₁ + 2m₂ = 2(m₁ + m₂ + M/2), H = p²/(2(m₁ + m₂ + M/2)) = p²/2𝓜
            return sp.Pow(most, e.exp) * sp.Pow(sp.expand(e.base / most), e.exp)
        return sp.Pow(grouped(e.base), e.exp)

    return expr.replace(
        lambda e: e.is_Pow and e.exp.is_negative and isinstance(e.base, sp.Add) and not (e.base.free_symbols & moving),
        group,
    )


def textbook_quotients(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """The three rules of the module, in turn: each term over its own denominator, no fraction in a
    denominator, constant denominators grouped."""
    return denominators_grouped(cleared(own_denominators(expr, moving)), moving)


def own_denominators(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """``expr`` with each of its terms that is a sum over a product of symbols (a monomial) written as the sum
    of its terms over their own denominators, when those differ; else as it is (see the module's docstring)."""
    if not isinstance(expr, sp.Expr) or not moving or not _small(expr):
        return expr
    return sp.Add(*(_split(term, moving) for term in sp.Add.make_args(expr)))


def _split(term: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    den = sp.denom(term)
    if _has_sum(den):
        return term  # a sum below: one denominator stays
    # a sum holding a fraction, as in ½(kr² + (p_r² + p_θ²/r²)/m): a fraction inside the bracket
    nested = any(_holds_fraction(f, monomial=True) for f in sp.Mul.make_args(term))
    if not nested and not (den.free_symbols and any(isinstance(f, sp.Add) for f in sp.Mul.make_args(sp.numer(term)))):
        return term  # no sum over a denominator: nothing to split
    outside = [f for f in sp.Mul.make_args(term) if not isinstance(f, sp.Add)]
    if not nested and not any(f.free_symbols & moving for f in outside):
        # a constant times a bracket is a textbook's form already: λ₁ = (m/2R)(Rθ̇² + g cos θ)
        return term
    # products distributed over sums, powers of sums kept (½κ(x₂ − x₁)² stays a square); like factors cancel
    # as they are multiplied (r·mθ̇²/m is rθ̇²)
    parts = list(sp.Add.make_args(sp.expand(term, multinomial=False, power_exp=False, power_base=False, log=False)))
    if len(parts) < 2 or len({sp.denom(p).as_coeff_Mul()[1] for p in parts}) < 2:
        return term  # the terms share their denominator: the sum stays over it
    if any(not (p.free_symbols & moving) for p in parts):
        return term  # a constant among the terms: the quotient is no sum of moving pieces
    return sp.Add(*parts)
