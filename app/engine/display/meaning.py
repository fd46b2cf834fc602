"""Forms by meaning: an expression written the way its meaning splits it, not the way it is shortest.

``app.engine.display.forms`` picks, among forms of an expression, the one with the fewest operations.  Some
quantities have a form a textbook prints whatever its length, because its pieces mean something:

* a momentum, grouped by velocity with each coefficient factored: p_X = (M + m)Ẋ + mḊ cos α, not
  MẊ + mẊ + mḊ cos α;
* an effective potential, its centrifugal piece (the terms holding a conserved momentum) apart from
  the potential's: U_eff = p_θ²/(2mr²) + ½kr², not (mkr⁴ + p_θ²)/(2mr²);
* a conserved energy, as the document's E: the sum of its bodies' and springs' pieces
  (½m₁ẋ₁² + ½m₂ẋ₂² + ½k(x₂ − x₁ − l₀)²), never multiplied out (``springs`` where only the expanded
  expression is at hand, as after a change of coordinates).

Each returns an expression equal to the one given (identically); the printers then keep it, since
``textbook_form`` keeps the engine's form unless another is clearly shorter.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Iterable

import sympy as sp

from app.engine.algebra.budget import memoized, within_budget
from app.engine.display.forms import moving_symbols, squares
from app.limits import FORM_WORK  # one rewriting gets the work of one expression's textbook form

MAX_NODES = 400  # larger expressions are left as they are (factoring each coefficient is then not cheap)


def _terms(expr: sp.Expr, moving: set[sp.Symbol]) -> sp.Expr:
    """expr as a sum of monomials in what moves, each with its coefficient cancelled (k l₀² m₁/(2m₁ + 2m₂) +
    k l₀² m₂/(2m₁ + 2m₂) is k l₀²/2); multiplied out as it is where it is no polynomial in them."""
    expanded = sp.expand(expr)
    symbols = sorted(moving & expanded.free_symbols, key=str)
    if not symbols:
        return sp.cancel(expanded)
    try:
        poly = sp.Poly(expanded, *symbols)
    except sp.PolynomialError:
        return expanded
    if any(c.has(*symbols) for c in poly.coeffs()):
        return expanded
    return sp.Add(*(sp.cancel(c) * sp.Mul(*(s**e for s, e in zip(symbols, m, strict=True))) for m, c in poly.terms()))


def _small(expr: sp.Expr) -> bool:
    return sp.count_ops(expr) <= MAX_NODES


def _held(expr: sp.Expr, velocities: Iterable[sp.Symbol]) -> list[sp.Symbol]:
    """The velocities ``expr`` holds, in their order; none when it is too large to split."""
    v = [s for s in velocities if expr.has(s)]
    return v if v and _small(expr) else []


def _split(expr: sp.Expr, v: list[sp.Symbol]) -> tuple[list[sp.Expr], sp.Expr] | None:
    expanded = sp.expand(expr)
    # p = Σ_k (∂p/∂q̇_k) q̇_k + p(q̇ = 0) when p is linear in the velocities
    coefficients = [sp.diff(expanded, s) for s in v]
    if any(c.has(*v) for c in coefficients):
        return None  # not linear in the velocities: not a momentum of this kind
    return coefficients, sp.expand(expanded - sum(c * s for c, s in zip(coefficients, v, strict=True)))


def linear_split(expr: sp.Expr, velocities: Iterable[sp.Symbol]) -> tuple[list[sp.Symbol], list[sp.Expr], sp.Expr] | None:
    """(v, c, rest) with expr = Σ_k c_k v_k + rest, each c_k and rest free of the velocities ``v`` (those of
    ``velocities`` that ``expr`` holds, in their order); None when it holds none, is too large, or is not
    linear in them."""
    v = _held(expr, velocities)
    split = _split(expr, v) if v else None
    return (v, *split) if split is not None else None


def by_velocity(expr: sp.Expr, velocities: Iterable[sp.Symbol]) -> sp.Expr:
    """A momentum (linear in the velocities) as Σ c_k q̇_k + rest, each coefficient c_k factored."""
    v = _held(expr, velocities)
    if not v:
        return expr

    def work() -> sp.Expr:
        split = _split(expr, v)
        if split is None:
            return expr
        coefficients, rest = split
        return sp.Add(*(sp.factor(c) * s for c, s in zip(coefficients, v, strict=True)), sp.factor(rest))

    return within_budget(work, expr, FORM_WORK)


def pieces(expr: sp.Expr, momenta: Iterable[sp.Symbol], coordinates: Iterable[sp.Symbol]) -> sp.Expr:
    """An effective potential as its centrifugal piece (the terms with a conserved momentum, over one
    denominator) plus the rest, its springs' squares recovered (``springs``)."""
    p = [s for s in momenta if expr.has(s)]
    if not p or not _small(expr):
        return expr

    def work() -> sp.Expr:
        expanded = sp.expand(expr)
        centrifugal = sp.Add(*(t for t in sp.Add.make_args(expanded) if t.has(*p)))
        rest = _terms(expanded - centrifugal, set(coordinates))
        # the potential's piece with its springs' squares recovered: ½k(x − l₀)²
        rest = springs(rest, coordinates)
        return sp.Add(sp.factor(centrifugal), rest)

    return within_budget(work, expr, FORM_WORK)


def springs(expr: sp.Expr, coordinates: Iterable[sp.Symbol]) -> sp.Expr:
    """An energy with each spring's square recovered (``forms.squares``), its extension written as a textbook
    does, the natural length subtracted: ½k(x₂ − x₁ − l₀)², not ½k(l₀ + x₁ − x₂)²."""
    if not _small(expr):
        return expr
    moving = moving_symbols(expr) | set(coordinates)

    def work() -> sp.Expr:
        found = squares(_terms(expr, moving), moving)

        def extension(base: sp.Expr) -> sp.Expr:
            fixed = sp.Add(*(t for t in sp.Add.make_args(base) if not t.free_symbols & moving))
            return -base if fixed != 0 and not fixed.could_extract_minus_sign() and base.free_symbols & moving else base

        return found.replace(
            lambda e: e.is_Pow and e.exp.is_even and isinstance(e.base, sp.Add),
            lambda e: sp.Pow(extension(e.base), e.exp),
        )

    return within_budget(work, expr, FORM_WORK)


def varies(expr: sp.Expr, moving: set[sp.Symbol]) -> bool:
    """Whether ``expr`` takes two different values at two points that differ only in the symbols of ``moving``:
    then it depends on them, and so does every form of it (a False says nothing: the values agreed, or one of
    them could not be computed)."""
    inside = sorted(expr.free_symbols & moving, key=str)
    if not inside:
        return False
    # fixed points (the answer never depends on a random draw): every symbol a rational of its own, then
    # each moving one another
    others = sorted(expr.free_symbols - set(inside), key=str)
    fixed = {s: sp.Rational(7 + 2 * k, 5 + 3 * k) for k, s in enumerate(others)}
    first = {**fixed, **{s: sp.Rational(3 + 5 * k, 11 + 4 * k) for k, s in enumerate(inside)}}
    second = {**fixed, **{s: sp.Rational(13 + 3 * k, 17 + 7 * k) for k, s in enumerate(inside)}}
    a, b = (expr.xreplace(point).evalf(30) for point in (first, second))
    try:
        # the difference taken at thirty digits, then rounded: one far above their rounding is a true one
        difference, size = complex(a - b), 1 + abs(complex(a)) + abs(complex(b))
    except TypeError:  # a value that is no number (a pole, 0/0): nothing said
        return False
    return cmath.isfinite(difference) and math.isfinite(size) and abs(difference) > 1e-12 * size


def by_coordinate(expr: sp.Expr, coordinates: Iterable[sp.Symbol]) -> sp.Expr:
    """A force or an acceleration linear in the coordinates with constant coefficients, as a textbook groups it:
    Σ c_k q_k + rest, each coefficient factored and a denominator they all share taken out,
    ẍ₁ = [−(k + κ)x₁ + κx₂]/m, not (κx₂ − kx₁ − κx₁)/m."""
    q = [s for s in coordinates if expr.has(s)]
    if not q or not _small(expr):
        return expr

    def work() -> sp.Expr:
        # linear: each ∂/∂q_k is free of every coordinate, and what is left holds none
        # constant coefficients: free of every coordinate, rate and t (r̈ = r(θ̇² − k/m) stays as it is)
        moving = moving_symbols(expr) | set(q)
        # a ∂/∂q_k whose value changes with what moves is no constant coefficient, whatever form factoring would
        # give it: told at once from the expression as it stands, without expanding or factoring (the costly
        # part for a pendulum's accelerations)
        if any(varies(sp.diff(expr, s), moving) for s in q):
            return expr
        expanded = sp.expand(expr)
        coefficients = [sp.factor(sp.diff(expanded, s)) for s in q]
        if any(c.free_symbols & moving for c in coefficients):
            return expr
        rest = sp.factor(sp.expand(expanded - sum(c * s for c, s in zip(coefficients, q, strict=True))))
        if rest.free_symbols & moving:
            return expr
        parts = [c for c in coefficients if c != 0] + ([rest] if rest != 0 else [])
        shared = {sp.fraction(sp.together(c))[1] for c in parts}
        if len(shared) == 1 and (den := shared.pop()) != 1:
            # the common denominator outside: [−(k + κ)x₁ + κx₂]/m
            inside = sp.Add(*(sp.factor(c * den) * s for c, s in zip(coefficients, q, strict=True)), sp.factor(rest * den))
            return sp.Mul(inside, sp.Pow(den, -1), evaluate=False)
        return sp.Add(*(c * s for c, s in zip(coefficients, q, strict=True)), rest)

    # the same acceleration is grouped for the results box and for its step: once per document
    return within_budget(lambda: memoized("by-coordinate", (expr, tuple(q)), work, charged=True), expr, FORM_WORK)
