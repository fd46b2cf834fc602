"""Textbook forms: the same expression, rewritten the way a careful textbook prints it.

``textbook_form(expr, names)`` returns an expression equal to ``expr`` (identically, for every
value of its symbols) in the shortest of a few forms a reader recognises:

* trigonometric products recombined.  Every product of sines and cosines is written as a sum of
  single sines and cosines (sin a sin b = ½[cos(a − b) − cos(a + b)], sin² a = ½[1 − cos 2a], …), so
  that sin θ₁ sin θ₂ + cos θ₁ cos θ₂ collapses to cos(θ₁ − θ₂) and sin² + cos² to 1;
* a quotient as one numerator over one denominator, the denominator's numbers made whole and its
  leading term positive: the double pendulum's θ̈₁ over l₁(2m₁ + m₂ − m₂ cos(2θ₁ − 2θ₂));
* terms collected by what moves (accelerations, velocities, coordinates and their functions), each
  with its constant coefficient in its shortest form: ½(m₁ + m₂) l₁² θ̇₁²;
* squares of sums recovered where a parameter multiplies a perfect square: k(x₁ − x₂ + l₀)²/2,
  M(ẏ₁ + ẏ₂)²/8, κ(x₁ − x₂)²/2.

Among the candidates the one with the fewest operations wins (one extra operation charged for each
angle the engine's form did not have, so sin θ cos θ stays unless sin 2θ is really shorter); ties keep
the earlier, more conservative candidate.  The work is bounded: each expression gets FORM_WORK
(no more than the shared display budget has left; a small one at least LATE_WORK) and keeps the best
form found within it; with none found, or beyond NODE_BUDGET nodes, the
engine's own cheap display form (sin² + cos² = 1 collapsed, SymPy's ``simplify`` when small) is kept.
"""

from __future__ import annotations

import itertools
import re
import threading
from collections.abc import Iterator, Mapping
from functools import partial
from typing import Any

import sympy as sp
from sympy.polys.polyerrors import BasePolynomialError
from sympy.simplify.fu import TR8, TR10i

from app.engine.algebra import budget
from app.engine.algebra.budget import memoized, within_budget
from app.engine.algebra.simplify import pythagoras, tidy
from app.engine.display.names import MASS_NAME
from app.engine.display.quotients import textbook_quotients
from app.limits import FALLBACK_WORK, FORM_WORK, LATE_WORK

ENGINE_BONUS = 1.5
# a quotient with sines or cosines below is shown linearised (``Linearised``) when that has at most this many
# times the operations of the shortest other form: the double pendulum's θ̈₁ (39 against 38), not Hamilton's
# ṗ₁ of the double pendulum, whose products multiplied out run to three times the length
LINEARISED_SLACK = 1.1
SMALL = 120  # nodes below which expanding first is cheap
NODE_BUDGET = 1500
# products of at most this many sines and cosines are turned to sums here; TR8 takes longer ones (where it
# leaves powers of its own sums unexpanded: cos⁸(x/2), sin²a sin²2a cos b)
MAX_SUM_DEGREE = 3
_CACHE: dict[tuple[sp.Expr, frozenset[sp.Symbol]], sp.Expr] = {}
_CACHE_SIZE = 4096
_SETTLED: dict[sp.Expr, sp.Expr] = {}  # forms settled as they stand (``settle``), by the form itself
_local = threading.local()
_LATE_LIMIT = ("forms", "late limit")  # in the document's memo: the smallest size whose late search ran out
# a Lagrange multiplier's name (app/engine/document/multipliers.py): an unknown of the motion, never collected as a parameter
_MULTIPLIER = re.compile(r"lambda_\d+")


def use_names(names: Mapping[sp.Symbol, str]) -> None:
    """The names ``textbook_form`` reads coordinates from when it is given none (the last printer made in
    this thread: a derivation's steps are formed with its own table's names)."""
    _local.names = names


def _remember(store: dict, key: Any, form: sp.Expr) -> None:
    """``form`` stored for ``key``; when the store is full, its oldest entry gives way, so that a form just
    settled is always found again (a long-lived process fills the store)."""
    while key not in store and len(store) >= _CACHE_SIZE:
        try:
            del store[next(iter(store))]
        except (KeyError, RuntimeError, StopIteration):  # another thread took it first
            break
    store[key] = form


def settle(form: sp.Expr, names: Mapping[sp.Symbol, str] | None = None) -> sp.Expr:
    """Declare ``form`` a textbook form as it stands (h and E built from T's and U's forms): forming it
    again returns it unchanged. Settled forms have a store of their own, which only this writes and which
    ``textbook_form`` reads first: a search of the same expression finishing in another thread (the warm-up
    derives scenes side by side) cannot put its own form over one settled (the tabletop's d/dt ∂L/∂θ̇ was
    printed m r(r θ̈ + 2 ṙ θ̇) by one server and m r² θ̈ + 2 m r ṙ θ̇ by another)."""
    if isinstance(form, sp.Expr):
        _remember(_SETTLED, form, form)
    return form


def moving_symbols(expr: Any, names: Mapping[sp.Symbol, str] | None = None) -> set[sp.Symbol]:
    """The symbols of ``expr`` that change along a motion: coordinates (those with a velocity), rates and t."""
    free: set[Any] = getattr(expr, "free_symbols", set())
    known = {s.name for s in (names or {})} | {s.name for s in free}
    rates = {n for n in known if n.endswith("_dot")}
    stems = {n[: -len("_dot")] for n in rates}
    # a coordinate, its rates, time, and a coordinate's momentum in Hamilton's equations (p_θ₁)
    return {
        s for s in free if s.name == "t" or s.name in stems or s.name.endswith(("_dot", "_ddot"))
        or (s.name.startswith("p_") and s.name[2:] in stems)
    }  # fmt: skip


def _nodes(expr: sp.Basic, limit: int) -> int:
    count = 0
    for _ in sp.preorder_traversal(expr):
        count += 1
        if count > limit:
            break
    return count


def _angles(expr: sp.Expr) -> set[sp.Expr]:
    return {f.args[0] for f in expr.atoms(sp.sin, sp.cos, sp.tan)}


def _ops(form: sp.Expr) -> tuple[float, frozenset[sp.Expr]]:
    """The operations of ``form`` and its angles, once per document."""
    return memoized("ops", form, lambda: (float(sp.count_ops(form)), frozenset(_angles(form))))


def _score(form: sp.Expr, angles: set[sp.Expr]) -> float:
    # operations, and one more for every angle the engine's form did not have (cos 2θ for sin² θ)
    ops, own = _ops(form)
    return ops + len(own - angles)




def mass_out(expr: sp.Expr) -> sp.Expr:
    """A sum every term of which holds one mass, with one term the mass alone, written as that mass times
    (1 + …), as a textbook writes it: m + mα²R² is m(1 + α²R²), 4mα²ρ² + m is m(1 + 4α²ρ²). Anything else as it
    is, its products' and its sums' members taken the same way: (4mα²ρ² + m) ρ̈ + 8mα²ρρ̇² is
    m(1 + 4α²ρ²) ρ̈ + 8mα²ρρ̇²."""
    if isinstance(expr, sp.Mul):
        # each constant bracket of a product too: (m + mα²R²) z̈ is m(1 + α²R²) z̈
        held = [mass_out(f) for f in expr.args]
        if all(h is f for h, f in zip(held, expr.args, strict=True)):
            return expr
        return sp.Mul(*(a for h in held for a in sp.Mul.make_args(h)), evaluate=False)
    if not isinstance(expr, sp.Add):
        return expr
    # m + m a = m (1 + a): the common factor taken out of every term
    content, inner = sp.factor_terms(expr).as_coeff_Mul()
    common, bracket = inner.as_independent(sp.Add, as_Add=False) if inner.is_Mul else (sp.Integer(1), inner)
    if not (isinstance(bracket, sp.Add) and common.is_Symbol and MASS_NAME.fullmatch(common.name)) or (
        sp.Integer(1) not in bracket.args
    ):
        # not itself a mass times (1 + …): each of its terms taken the same way
        terms = [mass_out(t) for t in expr.args]
        if all(h is t for h, t in zip(terms, expr.args, strict=True)):
            return expr
        return sp.Add(*terms, evaluate=False)
    return sp.Mul(content, common, bracket, evaluate=False) if content != 1 else sp.Mul(common, bracket, evaluate=False)


def _simplest(const: sp.Expr) -> sp.Expr:
    """A constant coefficient in its shortest form: as it is, common factors out, or cancelled; a mass times
    (1 + …) taken out (mass_out) where the sum holds it."""
    if not isinstance(const, sp.Add):
        return const

    def shortest() -> sp.Expr:
        held = mass_out(const)
        if held is not const:
            return held
        forms = [const, sp.factor_terms(const), sp.factor(const)]
        # the number most terms carry taken out, the others left over it: M/4 + m₁/2 + m₂/2 is ½(m₁ + m₂ + M/2),
        # the massive pulley's T, where taking out all of them gives (M + 2m₁ + 2m₂)/4
        numbers = [t.as_coeff_Mul()[0] for t in const.args]
        most = max(sorted(set(numbers), key=sp.default_sort_key), key=numbers.count)
        if most.is_Rational and most not in (1, -1):
            forms.append(sp.Mul(most, sp.expand(const / most), evaluate=False))
        return min(forms, key=lambda e: (sp.count_ops(e), forms.index(e)))

    # a document meets the same coefficient in many candidates (m₁ + m₂ in every row of the double pendulum)
    return memoized("simplest", const, shortest)


def collected(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """Terms with the same moving part added, each coefficient in its shortest form (½(m₁ + m₂) l₁² θ̇₁²)."""
    return memoized("collected", (expr, frozenset(moving)), lambda: _collected(expr, moving))


def _collected(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    groups: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        const, part = term.as_independent(*moving, as_Add=False) if moving else (term, sp.Integer(1))
        groups[part] = groups.get(part, sp.Integer(0)) + const
    return sp.Add(*(_simplest(c) * part for part, c in groups.items()))


def linearised(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """Products of sines and cosines as sums of single ones, over one denominator made whole.

    sin a sin b + cos a cos b = cos(a − b) and sin² a + cos² a = 1 follow from the product-to-sum
    rules (SymPy's ``TR8``); the denominator's rational numbers are cleared by multiplying above and
    below by their common denominator, and its sign chosen so that it reads positively.
    """
    return memoized("linearised", (expr, frozenset(moving)), lambda: _linearised(expr, moving))


def _linearised(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    num, den = lowest_terms(expr)
    num, den = _products_to_sums(num), _products_to_sums(den)
    # the numbers in the denominator made whole: l₁(m₁ + m₂/2 − m₂ cos 2Δ/2) -> l₁(2m₁ + m₂ − m₂ cos 2Δ)
    scale = sp.ilcm(1, *(sp.fraction(t.as_coeff_Mul()[0])[1] for t in sp.Add.make_args(den)))
    num, den = sp.expand(num * scale), sp.expand(den * scale)
    if den.could_extract_minus_sign():
        num, den = -num, -den
    top, bottom = collected(num, moving), sp.factor_terms(collected(den, moving))
    if bottom != 1 or _factorable(top, moving):
        top = sp.factor_terms(top)
    return _angles_expanded(top / bottom if bottom != 1 else top)


SMALL_DENOMINATOR = 60  # nodes up to which a denominator is factored rather than a gcd taken


def lowest_terms(expr: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Numerator and denominator of ``expr`` with no common factor: ``sp.cancel``'s, up to a constant factor.

    Any common factor of the two is a product of irreducible factors of the denominator; for a small
    denominator (the accelerations' l₁(m₁ + m₂ sin²(θ₁ − θ₂))) factoring it and dividing the numerator by
    each factor is about half the time of the gcd that ``cancel`` takes of the whole numerator with it.
    Sines and cosines are independent generators in both, as in ``cancel``."""
    together = sp.together(expr)
    num, den = sp.fraction(together)
    if not den.free_symbols or _nodes(den, SMALL_DENOMINATOR) >= SMALL_DENOMINATOR:
        return sp.fraction(sp.cancel(together))
    try:
        constant, factors = sp.factor_list(den)
        kept = []
        for factor, power in factors:
            left = power
            while left and factor.free_symbols:
                quotient, remainder = sp.div(num, factor)
                if remainder != 0:
                    break
                num, left = quotient, left - 1
            kept.append(factor**left)
    except (BasePolynomialError, NotImplementedError):
        return sp.fraction(sp.cancel(together))
    return num, constant * sp.Mul(*kept)


def _products_to_sums(expr: sp.Expr) -> sp.Expr:
    """Every product of sines and cosines as a sum of single ones (SymPy's TR8), expanded.

    TR8 works term by term on a sum, and a term's product of sines and cosines turns into the same sum
    whatever it multiplies; so each distinct product is turned once per document (a chain's terms share a
    handful: sin θ₁ sin θ₂, cos θ₁ cos θ₂, …) and multiplied back, and the expanded result is the one TR8
    gives on the whole (both are sums of single sines and cosines of the same angles: one such sum only).
    """
    return memoized("products", expr, lambda: sp.expand(sp.Add(*map(_term_to_sums, sp.Add.make_args(sp.expand(expr))))))


def _trig_factor(f: sp.Expr) -> bool:
    """sin a or cos a, or a positive whole power of one, with an angle free of sines and cosines."""
    base = f.base if f.is_Pow and f.exp.is_Integer and f.exp > 0 else f
    return isinstance(base, (sp.sin, sp.cos)) and not base.args[0].has(sp.sin, sp.cos)


def _term_to_sums(term: sp.Expr) -> sp.Expr:
    factors = sp.Mul.make_args(term)
    trig = [f for f in factors if _trig_factor(f)]
    rest = [f for f in factors if not _trig_factor(f)]
    if any(f.has(sp.sin, sp.cos) for f in rest):
        return memoized("tr8", term, lambda: TR8(term))  # sines inside another factor: the term as a whole
    if not trig or (len(trig) == 1 and not trig[0].is_Pow):
        return term
    product = sp.Mul(*trig)
    return sp.Mul(*rest) * memoized("tr8", product, lambda: _product_to_sum(product, trig))


def _linear_angle(angle: sp.Expr) -> bool:
    """A sum of symbols with rational coefficients (θ₁ − θ₂, 2θ): no number or constant of its own."""
    terms = sp.Add.make_args(angle)
    return all(
        t.is_Symbol or (t.is_Mul and len(t.args) == 2 and t.args[0].is_Rational and t.args[1].is_Symbol) for t in terms
    )


def _times(trig: sp.Expr | None, factor: sp.Expr) -> sp.Expr:
    """A single sine or cosine (or 1) times another, as a sum of single ones."""
    if trig is None:
        return factor
    a, b = trig.args[0], factor.args[0]
    if isinstance(trig, sp.sin):
        # sin a sin b = ½[cos(a − b) − cos(a + b)],  sin a cos b = ½[sin(a + b) + sin(a − b)]
        if isinstance(factor, sp.sin):
            return (sp.cos(a - b) - sp.cos(a + b)) / 2
        return (sp.sin(a + b) + sp.sin(a - b)) / 2
    # cos a sin b = ½[sin(a + b) − sin(a − b)],  cos a cos b = ½[cos(a − b) + cos(a + b)]
    if isinstance(factor, sp.sin):
        return (sp.sin(a + b) - sp.sin(a - b)) / 2
    return (sp.cos(a - b) + sp.cos(a + b)) / 2


def _product_to_sum(product: sp.Expr, factors: list[sp.Expr]) -> sp.Expr:
    """A product of sines and cosines of linear angles as a sum of single ones, one factor at a time.

    Expanded, a sum of single sines and cosines of distinct linear angles is one expression only (they are
    linearly independent), so this is what TR8 gives, without its gcd_terms between the steps; any other
    angle (a number, π in it) is left to TR8.
    """
    degree = sum(int(f.exp) if f.is_Pow else 1 for f in factors)
    if degree > MAX_SUM_DEGREE or not all(_linear_angle((f.base if f.is_Pow else f).args[0]) for f in factors):
        return TR8(product)  # TR8 leaves powers of its own sums unexpanded there (cos⁸(x/2) gives cos⁴ x)
    result: sp.Expr = sp.Integer(1)
    for f in factors:
        base, power = (f.base, int(f.exp)) if f.is_Pow else (f, 1)
        for _ in range(power):
            terms = []
            for term in sp.Add.make_args(result):
                trig = [g for g in sp.Mul.make_args(term) if isinstance(g, (sp.sin, sp.cos))]
                if (
                    len(trig) > 1
                    or term.has(sp.Pow)
                    and any(isinstance(p.base, (sp.sin, sp.cos)) for p in term.atoms(sp.Pow))
                ):
                    return TR8(product)  # not a sum of single ones (cannot happen with linear angles)
                one = trig[0] if trig else None
                terms.append((term / one if one is not None else term) * _times(one, base))
            result = sp.expand(sp.Add(*terms))
    return result


def _angles_expanded(expr: sp.Expr) -> sp.Expr:
    """cos 2(θ₁ − θ₂) written cos(2θ₁ − 2θ₂), as the textbooks print it (pulling factors out reaches the angles)."""
    return expr.replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)) and isinstance(e.args[0], sp.Mul),
        lambda e: e.func(sp.expand(e.args[0])),
    )


def squares(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """Perfect squares recovered under each parameter that multiplies one: k(x₂ − x₁ − l₀)²/2.

    For each parameter c, the terms linear in c are split by their degree in the velocities, and each
    part is factored; a part that factors with a squared sum replaces its terms.
    """
    return memoized("squares", (expr, frozenset(moving)), lambda: _squares(expr, moving))


def _squares(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    if not moving:
        return expr
    velocities = sorted((s for s in moving if s.name.endswith("_dot")), key=sp.default_sort_key)
    params = sorted(expr.free_symbols - moving, key=sp.default_sort_key)
    out = sp.expand(expr)
    split = _by_power(out)
    for c in params:
        # the terms linear in c (c times a part free of c) and the rest, read from each term's powers
        linear, others = [], []
        for term, powers, inside in split:
            if powers.get(c) == 1 and c not in inside:
                linear.append(term / c)
            else:
                others.append(term)
        if not linear:
            continue
        terms = sp.Add.make_args(sp.Add(*linear))  # already expanded: each is a term of ``out`` over c
        if not all(t.is_polynomial(*velocities) for t in terms):
            continue  # a speed under a root (sqrt(ρ̇² + ω²ρ²)): no degrees to split by
        by_degree: dict[int, sp.Expr] = {}
        for term in terms:
            degree = _degree_in(term, velocities)
            by_degree[degree] = by_degree.get(degree, sp.Integer(0)) + term
        found = False
        pieces = []
        for part in by_degree.values():
            # a squared sum needs three terms at least: one term has none, and two, m₁ + m₂ = m₁(1 + m₂/m₁),
            # are square-free up to a monomial (1 + cxⁿ has no repeated root, its derivative none but 0)
            if len(sp.Add.make_args(part)) < 3:
                pieces.append(part)
                continue
            factored = memoized("factor", part, partial(_squared_factors, part))
            if any(isinstance(b, sp.Add) and e == 2 for b, e in (f.as_base_exp() for f in sp.Mul.make_args(factored))):
                pieces.append(factored)
                found = True
            else:
                pieces.append(part)
        if found:
            out = sp.Add(*others, *(c * p for p in pieces))
            split = _by_power(out)
    return out


def _by_power(expr: sp.Expr) -> list[tuple[sp.Expr, dict[sp.Expr, Any], set[sp.Symbol]]]:
    """Each term of ``expr`` with its powers (base -> exponent) and the symbols inside a base that is not a
    symbol itself (sin(ωt) holds ω): a term is linear in c when c has exponent 1 and is in no other base."""
    out = []
    for term in sp.Add.make_args(expr):
        powers = term.as_powers_dict()
        inside: set[sp.Symbol] = set()
        for base in powers:
            if not base.is_Symbol:
                inside |= base.free_symbols
        out.append((term, powers, inside))
    return out


def _squared_factors(part: sp.Expr) -> sp.Expr:
    """``part`` factored when a factor of it is repeated, else ``part`` itself.

    A squared sum in the factorisation is a repeated factor, which the square-free decomposition (a gcd with
    the derivatives, far cheaper than factoring) finds; with none repeated, factoring cannot give a square
    and ``part`` stays as it is (as it would after factoring: ``squares`` keeps only squared sums).
    """
    if _square_free_at_a_point(part):
        return part
    try:
        _, factors = sp.sqf_list(part)
    except (BasePolynomialError, NotImplementedError):
        return sp.factor(part)
    if not any(k >= 2 and f.free_symbols for f, k in factors):
        return part
    return sp.factor(part)


def _square_free_at_a_point(part: sp.Expr) -> bool:
    """True when ``part`` (a polynomial in its symbols, sines and cosines) provably has no repeated factor.

    A factor A² with A containing x survives setting the other generators to numbers that keep the leading
    coefficient in x, as a repeated root of one variable (a gcd with the derivative); so a point where every
    variable of degree ≥ 2 gives a square-free polynomial proves it.  False: not shown (the full test decides).
    The degrees are read term by term and each test is a polynomial in one variable: no polynomial in all
    the generators is built (that was most of the time of a chain's squares).
    """
    degrees: dict[sp.Expr, int] = {}
    for term in sp.Add.make_args(part):
        for base, exp in term.as_powers_dict().items():
            if base.is_Number:
                if not base.is_Rational:
                    return False  # a float or a root among the numbers: the full test
                continue
            if not (exp.is_Integer and exp > 0 and (base.is_Symbol or isinstance(base, (sp.sin, sp.cos)))):
                return False
            degrees[base] = max(degrees.get(base, 0), int(exp))
    gens = sorted(degrees, key=sp.default_sort_key)
    point = {g: sp.Rational(13 + 5 * i, 7 + 3 * i) for i, g in enumerate(gens)}
    for x in gens:
        if degrees[x] < 2:
            continue  # A² would give degree 2 at least
        try:
            one = sp.Poly(part.xreplace({g: point[g] for g in gens if g != x}), x)
        except (BasePolynomialError, NotImplementedError):
            return False
        if not one.get_domain().is_QQ and not one.get_domain().is_ZZ:
            return False
        if one.degree() != degrees[x] or one.gcd(one.diff()).degree() > 0:
            return False
    return True


def _factorable(expr: sp.Expr, moving: set[sp.Symbol]) -> bool:
    """Whether a textbook pulls the common factors out of this sum: an equation's terms (R m (R θ̈ + g sin θ)),
    or a kinetic energy's (½ m R² (θ̇² + sin² θ φ̇²)); never across kinetic and potential terms, nor out of a
    potential's, which a reader compares term by term."""
    velocities = [s for s in moving if s.name.endswith(("_dot", "_ddot"))]
    if any(s.name.endswith("_ddot") for s in velocities):
        return True
    if not velocities:
        return False
    terms = sp.Add.make_args(expr)
    # a term that is no polynomial in the velocities (a speed, sqrt(ρ̇² + ω²ρ²)) has no degree to share
    if not all(t.is_polynomial(*velocities) for t in terms):
        return False
    degrees = {_degree_in(t, velocities) for t in terms}
    return len(degrees) == 1 and 0 not in degrees


def _degree_in(term: sp.Expr, velocities: list[sp.Symbol]) -> int:
    """The total degree of a term (a polynomial in the velocities) in them: read from its powers when each
    factor is a velocity or free of them, else from its polynomial."""
    powers = term.as_powers_dict()
    if all(b in velocities or not b.has(*velocities) for b in powers):
        return sum(int(e) for b, e in powers.items() if b in velocities)
    return sp.Poly(term, *velocities).total_degree()


def recombined(expr: sp.Expr) -> sp.Expr:
    """Sums of products recombined where they stand, without expanding anything (cheap on any size):
    sin a sin b + cos a cos b -> cos(a − b) (SymPy's ``TR10i``), and a bracket raised to a power
    (a denominator's square) linearised when that shortens it."""

    def shorter(base: sp.Expr) -> sp.Expr:
        # the numbers made whole, the half taken out: (2m₁ + m₂ − m₂ cos 2Δ)/2
        lin = _angles_expanded(sp.factor_terms(sp.expand(TR8(sp.expand(base))), clear=True))
        return lin if sp.count_ops(lin) < sp.count_ops(base) else base

    out = TR10i(expr).replace(
        lambda e: e.is_Pow and isinstance(e.base, sp.Add) and e.base.has(sp.sin, sp.cos) and _nodes(e.base, 200) < 200,
        lambda e: sp.Pow(shorter(e.base), e.exp),
    )
    # a denominator's numbers made whole: 1/(m₁ + m₂/2 − m₂ cos 2Δ/2) -> 2/(2m₁ + m₂ − m₂ cos 2Δ)
    out = out.replace(
        lambda e: e.is_Pow and e.exp.is_negative and isinstance(e.base, sp.Add)
        and any(not t.as_coeff_Mul()[0].is_Integer for t in e.base.args),
        lambda e: sp.Pow(sp.factor_terms(e.base, clear=True), e.exp),
    )  # fmt: skip
    return _angles_expanded(out)


def _candidates(expr: sp.Expr, moving: set[sp.Symbol]) -> Iterator[sp.Expr | Linearised]:
    """The engine's form first (ties keep it), then the rewritten ones, cheapest first."""
    yield expr
    moving_denominator = any(p.exp.is_negative and p.base.free_symbols & moving for p in expr.atoms(sp.Pow))
    if _nodes(expr, SMALL) < SMALL and not moving_denominator:
        # a small expression expanded and collected: what cancels goes first (a checker's difference)
        yield collected(expr, moving)
    # a sum of terms with one sine or cosine each at most has no product to turn into a sum or recombine
    trig = bool(expr.atoms(sp.sin, sp.cos)) and not _trig_linear(expr)
    big = _nodes(expr, 4 * SMALL) >= 4 * SMALL
    if trig and big:
        # cheap on any size: first for a large expression, whose other candidates may not finish in time
        yield recombined(expr)
    yield from _rewritten(expr, moving, trig)
    if trig and not big:
        yield recombined(expr)


class Linearised:
    """A quotient whose denominator holds sines or cosines of what moves, with every product of them written as
    a sum of single ones over a whole-number denominator: the form a textbook prints such a quotient in
    (the double pendulum's θ̈₁ over l₁(2m₁ + m₂ − m₂ cos(2θ₁ − 2θ₂))), taken when it is found and not much
    longer (LINEARISED_SLACK), even where sin²(θ₁ − θ₂) below counts a few operations fewer: both accelerations
    then share one denominator."""

    def __init__(self, form: sp.Expr):
        self.form = form


def _den_moves(expr: sp.Expr, moving: set[sp.Symbol]) -> bool:
    """Whether the denominator of ``expr`` holds a sine or cosine of something that moves."""
    return any(
        p.exp.is_negative and any(f.free_symbols & moving for f in p.base.atoms(sp.sin, sp.cos)) for p in expr.atoms(sp.Pow)
    )


def _squared_trig_sum(den: sp.Expr) -> bool:
    """Whether ``den`` has a factor (a + b cos θ + …)ⁿ with n ≥ 2: a sum with sines or cosines, raised to a power."""
    return any(
        f.is_Pow and f.exp.is_Integer and f.exp >= 2 and isinstance(f.base, sp.Add) and f.base.has(sp.sin, sp.cos)
        for f in sp.Mul.make_args(den)
    )


def _trig_linear(expr: sp.Expr) -> bool:
    """True when no product or power of sines and cosines can appear on expanding ``expr``: no product holds
    two factors with sines or cosines in them, and no sine or cosine is raised to a power (nor divided by).

    Then the product-to-sum rules and their inverse (``linearised``, ``recombined``) find nothing to do, and
    sin² + cos² = 1 nothing to collapse: the candidates that try them would only repeat the plain ones."""

    def trig(e: sp.Basic) -> bool:
        return e.has(sp.sin, sp.cos)

    for node in sp.preorder_traversal(expr):
        if node.is_Mul and sum(1 for f in node.args if trig(f)) > 1:
            return False
        if node.is_Pow and trig(node.base):
            return False
    return True


def _rewritten(expr: sp.Expr, moving: set[sp.Symbol], trig: bool) -> Iterator[sp.Expr | Linearised]:
    """The candidates that expand, put over one denominator or factor."""
    if isinstance(expr, sp.Add):
        # a sum of a quotient and plain terms (Hamilton's H = kinetic part over its denominator − the potential):
        # the quotients over one denominator, the plain terms as they are
        over = [t for t in expr.args if sp.denom(t).free_symbols & moving]
        if over and len(over) < len(expr.args):
            rest = sp.Add(*(t for t in expr.args if t not in over))
            quotient = sp.Add(*over)
            # over a squared trigonometric sum (Hamilton's ṗ, over det M²) the quotient stays as it is (below)
            squared = any(_squared_trig_sum(sp.denom(t)) for t in over)
            shown = linearised(quotient, moving) if trig and not squared else quotient
            yield shown + collected(pythagoras(rest) if trig else rest, moving)
            return
    num, den = sp.fraction(sp.together(expr))
    if den.free_symbols:
        # a quotient: one numerator over one denominator, products of sines and cosines linearised
        if trig:
            # a squared denominator (Hamilton's ṗ, over det M²) multiplied out runs to several times the length:
            # textbooks keep it as a power (the double pendulum's ṗ over l₁²l₂²(m₁ + m₂ sin²(θ₁ − θ₂))²)
            if not _squared_trig_sum(den):
                yield Linearised(linearised(expr, moving))
            return
        num, den = sp.fraction(sp.cancel(sp.together(expr)))
        yield sp.factor_terms(collected(num, moving)) / sp.factor_terms(den)
        return
    grouped = collected(pythagoras(expr) if trig else expr, moving)
    yield grouped
    if _factorable(grouped, moving):
        yield sp.factor_terms(grouped)
    if trig:
        yield linearised(expr, moving)
    yield squares(grouped, moving)


def textbook_form(expr: Any, names: Mapping[sp.Symbol, str] | None = None, units: float = FORM_WORK) -> Any:
    """``expr`` in its textbook form (an equal expression; see the module's docstring).

    ``names``: the symbol table's names (coordinates are recognised by having a velocity there).
    Bounded by ``units`` of work and by the shared display budget; beyond them the engine's cheap display
    form is returned.
    """
    if not isinstance(expr, sp.Expr) or not expr.free_symbols or isinstance(expr, sp.Symbol):
        return expr
    settled = _SETTLED.get(expr)
    if settled is not None:
        return settled
    names = names if names is not None else getattr(_local, "names", None)
    moving = moving_symbols(expr, names)
    key = (expr, frozenset(moving))
    if key in _CACHE:
        return _CACHE[key]
    nodes = _nodes(expr, NODE_BUDGET)
    # once the shared budget is spent, a small expression still gets LATE_WORK; a large one only its fallback
    shared = budget.display_work_left(units)
    late = shared < min(units, LATE_WORK)
    left = max(shared, min(units, LATE_WORK) if nodes < 4 * SMALL else 0.0)
    memo = budget.document_memo()
    # a late search that ran out of time at this size in this document would again at any larger size
    if nodes > NODE_BUDGET or left <= budget.SPENT or (late and memo is not None and nodes >= memo.get(_LATE_LIMIT, nodes + 1)):
        return _fallback(expr)
    angles = _angles(expr)

    # the best form so far: what a timeout leaves (the engine's form, often the declaration's own, stays
    # unless another is shorter by two operations; ties keep the earlier)
    best: list[Any] = [expr, _score(expr, angles) - ENGINE_BONUS]

    def search() -> bool:
        for form in _candidates(expr, moving):
            if isinstance(form, Linearised):
                # within a tenth of the operations of the best so far (the angle charge aside), it is the form
                if _den_moves(expr, moving) and _ops(form.form)[0] <= LINEARISED_SLACK * _ops(best[0])[0]:
                    # nothing scores below it: the candidates still to come are not worked out
                    best[:] = [form.form, float("-inf")]
                    break
                form = form.form
            score = _score(form, angles)
            if score < best[1]:
                best[:] = [form, score]
        return True

    finished = within_budget(search, False, left)
    if finished is False and late and memo is not None:
        memo[_LATE_LIMIT] = min(nodes, memo.get(_LATE_LIMIT, nodes))
    if finished is False and best[0] is expr:
        fallback = _fallback(expr)
        if left < units:  # the shared budget ran out, not this expression's own time: try again another time
            return fallback
        best[0] = fallback
    # quotients as a textbook writes them: each term over its own denominator, no fraction in a denominator
    found = mass_out(textbook_quotients(like_terms_added(best[0], moving), moving))
    _remember(_CACHE, key, found)
    return settle(found, names)  # a form, formed again, stays as it is


def one_denominator(exprs: list[Any], names: Mapping[sp.Symbol, str] | None = None) -> list[Any]:
    """The explicit accelerations of one system in their textbook forms, over one denominator when they have one.

    By Cramer's rule every q̈ₖ is a numerator over det ℳ; each is formed on its own (``textbook_form``), and two
    forms of one system may then print that denominator differently: the cart on a spring's Ẍ over M + m sin² φ
    and φ̈, linearised, over l(2M + m − m cos 2φ).  A careful text prints them over the same one, in sines and
    cosines of single angles.  So each acceleration is also written as the engine derived it: its numerator and
    denominator in lowest terms, the numerator's terms collected by what moves ((M + m) g sin φ), the
    denominator's numbers made whole and its leading term positive,
    φ̈ = [kX cos φ − (M + m) g sin φ − m l φ̇² sin φ cos φ]/[l(M + m sin² φ)].  These single-angle forms are
    taken when they share one denominator, unless the formed ones share one too and are shorter on the whole
    (double angles only where they are shorter): the double pendulum's single-angle forms, over
    l₁(m₁ + m₂ sin²(θ₁ − θ₂)), count 35 and 37 operations against 39 and 39 over l₁(2m₁ + m₂ − m₂ cos(2θ₁ − 2θ₂))."""
    formed = [_whole_denominator(textbook_form(e, names)) for e in exprs]
    quotients = [e for e in exprs if isinstance(e, sp.Expr)]
    if len(formed) < 2 or len(quotients) < len(formed):
        return formed
    names = names if names is not None else getattr(_local, "names", None)
    moving = set().union(*(moving_symbols(e, names) for e in exprs))
    if not all(_den_moves(e, moving) for e in formed):
        return formed
    plain = within_budget(lambda: [_single_angle_quotient(e, moving) for e in exprs], None, FORM_WORK)
    if plain is None or not _same_denominator(plain, moving):
        return formed
    # double angles only where they share the denominator and are shorter on the whole
    if _same_denominator(formed, moving) and sum(_ops(f)[0] for f in formed) < sum(_ops(p)[0] for p in plain):
        return formed
    return [settle(p, names) for p in plain]


def _whole_denominator(expr: Any) -> Any:
    """A quotient whose denominator is a sum with two or more fractions in it, written with whole numbers there, as a
    textbook does: a rolling cylinder's s̈ = 2(M + m) g sin α/(3M + m + 2m sin² α), not (M + m) g sin α/(3M/2 + m/2 + m sin² α).
    Anything else is returned as it is."""
    if not isinstance(expr, sp.Expr) or not expr.free_symbols:
        return expr
    num, den = sp.fraction(expr)
    # the sum may stand beside other factors: m(3M/2 + m/2 + m sin² α), the rolling cylinder's ṡ from its momenta
    sums = [f for f in sp.Mul.make_args(den) if isinstance(f, sp.Add)]
    if len(sums) != 1:
        return expr
    # the least common multiple of the denominators of the sum's numbers: (3M/2 + m/2 + m sin² α) × 2
    below = [sp.fraction(t.as_coeff_Mul()[0])[1] for t in sums[0].args]
    scale = sp.ilcm(1, *below)
    # one fraction among whole terms is an added inertia a textbook keeps in sight: the massive pulley's
    # (m₁ − m₂) g/(m₁ + m₂ + M/2), as its T = ½(m₁ + m₂ + M/2) ẏ² and its equation print it
    if scale == 1 or sum(b != 1 for b in below) < 2:
        return expr
    rest = sp.Mul(*(f for f in sp.Mul.make_args(den) if f is not sums[0]))
    # the numerator times the same number, its own fractions cleared too (3 p_X/2 − p_s cos α → 3 p_X − 2 p_s cos α)
    top = sp.expand(num * scale) if isinstance(num, sp.Add) else num * scale
    return sp.Mul(top, sp.Pow(rest * sp.expand(sums[0] * scale), -1))


def whole_denominator(expr: Any) -> Any:
    """A quotient with the fractions in its denominator's sum cleared, where two or more terms carry one (the
    accelerations' rule, read by Hamilton's velocities too)."""
    return _whole_denominator(expr)


def _differ_by_a_parameter(total: sp.Expr) -> bool:
    """Whether the terms of a sum are one common factor times a number and a single symbol each: M g + m g,
    m₁g − m₂g, Mg/2 − m₁g."""
    brackets = [f for f in sp.Mul.make_args(sp.factor_terms(total)) if isinstance(f, sp.Add)]
    return len(brackets) == 1 and all(t.as_coeff_Mul()[1].is_Symbol for t in brackets[0].args)


def _moving_denominator(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """The factors of ``expr``'s denominator that hold something that moves (M + m sin² φ of l(M + m sin² φ))."""
    den = sp.factor_terms(sp.denom(sp.together(expr)))
    return sp.Mul(*(f for f in sp.Mul.make_args(den) if f.free_symbols & moving))


def _same_denominator(forms: list[sp.Expr], moving: set[sp.Symbol]) -> bool:
    """Whether the forms print one denominator: their moving factors equal up to a constant factor."""
    first = _moving_denominator(forms[0], moving)
    return all(not (sp.cancel(_moving_denominator(f, moving) / first).free_symbols & moving) for f in forms[1:])


def _single_angle_quotient(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """A quotient as the engine derived it, in single angles: lowest terms, the numerator collected by what moves,
    the denominator's numbers made whole and its leading term positive (l(M + m sin² φ))."""
    num, den = lowest_terms(expr)
    # the numbers in the denominator made whole, as ``linearised`` makes them
    scale = sp.ilcm(1, *(sp.fraction(t.as_coeff_Mul()[0])[1] for t in sp.Add.make_args(sp.expand(den))))
    num, den = num * scale, sp.factor_terms(sp.expand(den * scale))
    if den.could_extract_minus_sign():
        num, den = -num, -den
    top = collected(num, moving)
    if _factorable(top, moving):
        top = sp.factor_terms(top)
    return textbook_quotients(like_terms_added(top / den, moving), moving)


def _fallback(expr: sp.Expr) -> sp.Expr:
    """The engine's own display form: sin² + cos² = 1 collapsed, then SymPy's simplification when small."""
    plain = within_budget(lambda: tidy(pythagoras(expr), FALLBACK_WORK), expr, FALLBACK_WORK)
    # like terms added and quotients as a textbook writes them here too (bounded by size: cheap)
    moving = moving_symbols(plain, getattr(_local, "names", None))
    return textbook_quotients(like_terms_added(plain, moving), moving)


def like_terms_added(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """Terms of a sum that differ only by a constant factor written as one term, in every sum of ``expr``:
    M Ẋ + m Ẋ → (M + m)Ẋ, M p_φ² + m p_φ² → (M + m)p_φ², the coefficients added in their shortest form.

    The one rule for every member a document prints (momenta, velocities from momenta, H, Hamilton's
    equations, conserved quantities), applied to whichever form won: the engine's own form is kept when it is
    short (ENGINE_BONUS), and may hold such pairs.  Terms free of what moves are left as they stand, and so is
    a Lagrange multiplier's term (λ₂z₁ − Mgz₁ in L′: λ₂ is an unknown of the motion, not a parameter)."""
    if not isinstance(expr, sp.Expr) or _nodes(expr, NODE_BUDGET) >= NODE_BUDGET:
        return expr
    moving = moving | {s for s in expr.free_symbols if _MULTIPLIER.fullmatch(s.name)}

    def added(total: sp.Expr) -> sp.Expr:
        # c₁ P + c₂ P = (c₁ + c₂) P, for each moving part P (a product of coordinates, rates and their functions)
        groups: dict[sp.Expr, list[sp.Expr]] = {}
        constants: list[sp.Expr] = []
        for term in total.args:
            const, part = term.as_independent(*moving, as_Add=False) if moving else (term, sp.Integer(1))
            if part == 1:
                constants.append(term)
            else:
                groups.setdefault(part, []).append(const)
        # the terms free of what moves as one where they differ only by a parameter and that is shorter:
        # M g + m g → (M + m) g, m₁g − m₂g → (m₁ − m₂)g; a discriminant (m₁ + m₂)²(l₁ − l₂)² + 4(m₁ + m₂)m₂l₁l₂ stays
        rest = sp.Add(*constants)
        lump = _simplest(rest) if len(constants) > 1 and _differ_by_a_parameter(rest) else rest
        # never longer, and never a sign taken out of the whole: −ω² − g/R stays, not −(ω² + g/R)
        if lump is not rest and (
            sp.count_ops(lump) >= sp.count_ops(rest) or (lump.could_extract_minus_sign() and isinstance(-lump, sp.Add))
        ):
            lump = rest
        if lump is rest and all(len(consts) == 1 for consts in groups.values()):
            return total
        return sp.Add(*(_simplest(sp.Add(*consts)) * part for part, consts in groups.items()), lump)

    def walk(e: sp.Expr) -> sp.Expr:
        if e.is_Atom:
            return e
        args = [walk(a) for a in e.args]
        rebuilt = e if args == list(e.args) else e.func(*args)
        if isinstance(e, sp.Mul) and not isinstance(rebuilt, sp.Mul):
            # a sign or number before a bracket stays there: −((M + m)g l sin φ + …), not multiplied in
            rebuilt = sp.Mul(*args, evaluate=False)
        return added(rebuilt) if isinstance(rebuilt, sp.Add) else rebuilt

    return walk(expr)


def roots_compacted(expr: sp.Expr, signs: Mapping[sp.Symbol, sp.Symbol]) -> sp.Expr:
    """A closed form holding square roots as a textbook prints it (the same value).

    Three rules, applied from the inside out, each kept only where it is shorter by ``sp.count_ops``:

    * a product of square roots, all but one of quantities that are never negative (under ``signs``, the
      stand-ins carrying the declared signs), is one root, √a √b = √(ab);
    * a polynomial under a root in its shortest grouped form: as it is, factored, or, for each factor f of it,
      the rest divided by f, R = q f + r, so that f R = f(q f + r): the double pendulum's
      √((m₁ + m₂)((m₁ + m₂)(l₁ + l₂)² − 4m₁l₁l₂));
    * a sum whose terms share a factor has it taken out, (m₁ + m₂)l₁ + (m₁ + m₂)l₂ = (m₁ + m₂)(l₁ + l₂).
    """
    if not any(_square_root(p) for p in expr.atoms(sp.Pow)):
        return expr
    return _compacted(expr, signs)


def _shortest(forms: list[sp.Expr]) -> sp.Expr:
    # fewest operations; ties keep the earlier (the form as it stands first)
    return min(forms, key=lambda e: (sp.count_ops(e), forms.index(e)))


def _compacted(expr: sp.Expr, signs: Mapping[sp.Symbol, sp.Symbol]) -> sp.Expr:
    if expr.is_Atom:
        return expr
    args = [_compacted(a, signs) for a in expr.args]
    if isinstance(expr, sp.Mul):
        roots = [a for a in args if _square_root(a)]
        # √a √b = √(ab) when a ≥ 0, whatever b (SymPy splits √(ab) whenever a factor is known positive): so
        # when all the radicands but one are known never to be negative
        unsure = [r for r in roots if not r.base.xreplace(dict(signs)).is_nonnegative]
        if len(roots) > 1 and len(unsure) <= 1:
            rest = [a for a in args if a not in roots]
            joined = sp.sqrt(_radicand(sp.Mul(*(r.base for r in roots))))
            return sp.Mul(*rest, joined)
    rebuilt = expr.func(*args)
    if _square_root(rebuilt):
        return sp.sqrt(_radicand(rebuilt.base))
    if isinstance(rebuilt, sp.Add):
        # shared factors out of a sum, sums among them: (m₁ + m₂)l₁ + (m₁ + m₂)l₂ = (m₁ + m₂)(l₁ + l₂); the
        # terms free of roots on their own too, beside the root ((m₁ + m₂)(l₁ + l₂) − √(…))
        plain = [t for t in rebuilt.args if not any(_square_root(p) for p in t.atoms(sp.Pow))]
        whole = _grouped(rebuilt)
        if 1 < len(plain) < len(rebuilt.args):
            rooted = [t for t in rebuilt.args if t not in plain]
            return _shortest([whole, sp.Add(_grouped(sp.Add(*plain)), *rooted)])
        return whole
    return rebuilt


def _grouped(total: sp.Expr) -> sp.Expr:
    # the same sums come back in both roots of an equilibrium and at the paired equilibria (K and −K): grouped
    # once per document, each later use charged the work of the first, so every bound ends where it did
    return memoized(
        "grouped", total, lambda: _shortest([total, sp.factor_terms(total), sp.gcd_terms(total)]), charged=True
    )


def _square_root(e: sp.Expr) -> bool:
    return isinstance(e, sp.Pow) and e.exp == sp.S.Half


def _radicand(base: sp.Expr) -> sp.Expr:
    """A polynomial under a root in its shortest form: as it is, factored, or grouped in one of its factors."""
    if not base.free_symbols or not base.is_polynomial(*base.free_symbols):
        return base
    # the same radicand comes back at every equilibrium of a pair (K and −K) and in both roots of each: worked
    # out once per document
    return memoized("radicand", base, lambda: _radicand_forms(base), charged=True)


def _radicand_forms(base: sp.Expr) -> sp.Expr:
    factored = sp.factor(base)
    forms = [base, factored]
    _, factors = sp.factor_list(base)
    for f, _power in factors:
        if not isinstance(f, sp.Add):
            continue
        rest = sp.cancel(base / f)
        if not rest.is_polynomial(*base.free_symbols):
            continue
        # f R = f(q f + r), R divided by f in each symbol f holds to the first power
        for x in sorted(f.free_symbols, key=str):
            if sp.degree(f, x) != 1:
                continue
            try:
                q, r = sp.div(rest, f, x)
            except BasePolynomialError:
                continue
            whole = q.is_polynomial(*base.free_symbols) and r.is_polynomial(*base.free_symbols)
            if q == 0 or not whole or sp.expand(q * f + r - rest) != 0:
                continue
            forms.append(f * (sp.factor(q) * f + sp.factor(r)))
    return _shortest(forms)


def gathered(expr: sp.Expr) -> sp.Expr:
    """A force or a coefficient of the multipliers' steps as a textbook prints it, where ``textbook_form``
    keeps the bracket as built: a number or factor common to a bracket's terms taken out of it, term by term
    (λ₁(2R − 2z) − mg → 2λ₁(R − z) − mg; −2(gz − ẋ² − gR) → 2(ẋ² + gR − gz)), never a sign out of the whole
    sum (−2λ₁η − λ₂ cos αζ stays); and a numerator's terms beyond its number collected where that shortens them
    (1 + α²ξ² cos² αζ + 2α²ξη sin αζ cos αζ + α²η² sin² αζ → 1 + α²(ξ cos αζ + η sin αζ)²)."""
    if not isinstance(expr, sp.Expr) or not expr.free_symbols:
        return expr
    # a perfect square among a bracket's terms written as one: x² + z² − 2Rz + R² → x² + (z − R)²
    expr = expr.replace(lambda e: isinstance(e, sp.Add), _squares_collected)
    terms = sp.Add.make_args(expr)
    outside = [_out_of_brackets(t) for t in terms]
    # rebuilt only where a term changed: a number times a sum, rebuilt, is multiplied out again (2(ẋ² + gR))
    out = expr if outside == list(terms) else sp.Add(*outside)
    numerator, denominator = sp.fraction(out)
    collected = _collected_numerator(numerator)
    return out if denominator == 1 or collected is numerator else collected / denominator


# the most terms of a sum searched for three that make a perfect square (a² ± 2ab + b²): 56 triples at most
SQUARE_TERMS = 8


def _squares_collected(total: sp.Expr) -> sp.Expr:
    """Three terms of a sum that are a constant times a perfect square, (z − R)², written so; the rest as it is."""
    terms = sp.Add.make_args(total)
    if not 3 <= len(terms) <= SQUARE_TERMS:
        return total
    for triple in itertools.combinations(terms, 3):
        try:
            factored = sp.factor(sp.Add(*triple))
        except (BasePolynomialError, NotImplementedError):
            continue
        _, rest = factored.as_coeff_Mul()
        if isinstance(rest, sp.Pow) and rest.exp == 2 and isinstance(rest.base, sp.Add):
            others = [t for t in terms if t not in triple]
            return sp.Add(factored, _squares_collected(sp.Add(*others)) if others else sp.Integer(0))
    return total


def _out_of_brackets(term: sp.Expr) -> sp.Expr:
    """factor_terms on one term: its brackets' common factors before them (2λ₁(R − z))."""
    out = sp.factor_terms(term)
    # a term's own sign stays before it: −(2λ₁η + λ₂ cos αζ) is longer to read than the sum it came from
    return term if out.could_extract_minus_sign() and isinstance(-out, sp.Add) else out


def _collected_numerator(numerator: sp.Expr) -> sp.Expr:
    """A number plus a sum, the sum factored when that has fewer operations: 1 + α²(ξ cos αζ + η sin αζ)²."""
    if not isinstance(numerator, sp.Add):
        return numerator
    number, rest = numerator.as_coeff_Add()
    if number == 0 or not isinstance(rest, sp.Add):
        return numerator
    try:
        factored = sp.factor(rest)
    except (BasePolynomialError, NotImplementedError):
        return numerator
    return number + factored if sp.count_ops(factored) < sp.count_ops(rest) else numerator
