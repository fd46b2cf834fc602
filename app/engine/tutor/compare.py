"""Compare a student's expression with the engine's: equal, equal up to a constant or a factor, or not.

Each comparison runs numerically at random points (so any correct form passes,
however it is written) and, for an agreement, symbolically within a time budget.
The points are nested so that "constant" and "factor" can be told apart from
"different":

    for each of 2 draws of the constants (parameters, conserved momenta),
      for each of 2 draws of the positions (coordinates and t),
        for each of 3 draws of the rates (velocities and accelerations).

Two expressions differ by an additive constant when a − b takes one value
within each draw of the constants; an equation is the engine's times a nonzero
factor when a / b is nonzero and takes one value within each draw of the
constants and positions (the factor may depend on the coordinates, never on
the rates). The draws are seeded, so a verdict never changes between runs.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import sympy as sp
from sympy.simplify.fu import TR10i

from app.engine.algebra.budget import within_budget, work_limit
from app.engine.algebra.kinks import away_from_kinks
from app.engine.algebra.simplify import pythagoras
from app.engine.algebra.work import WorkExceeded
from app.limits import SYMBOLIC_WORK

CONSTANT_DRAWS, POSITION_DRAWS, RATE_DRAWS = 2, 2, 3
RTOL = 1e-9
MISTAKE_ONLY_MAX_OPS = 300
TRIGSIMP_MAX_OPS = 40
SEED = 20261123


@dataclass(frozen=True)
class Groups:
    """The symbols of a comparison, by how they vary between the nested draws."""

    constants: tuple[sp.Symbol, ...]
    positions: tuple[sp.Symbol, ...]
    rates: tuple[sp.Symbol, ...]

    @property
    def symbols(self) -> tuple[sp.Symbol, ...]:
        return (*self.constants, *self.positions, *self.rates)

    def dynamic(self) -> frozenset[sp.Symbol]:
        return frozenset((*self.positions, *self.rates))


def points(groups: Groups) -> list[list[list[tuple[float, ...]]]]:
    """Nested sample points: [constant draw][position draw][rate draw] -> values in ``groups.symbols`` order."""
    rng = random.Random(SEED)
    out = []
    for _ in range(CONSTANT_DRAWS):
        constants = tuple(rng.uniform(0.6, 1.7) for _ in groups.constants)
        block = []
        for _ in range(POSITION_DRAWS):
            # angles in (0.25, 1.3) rad keep sin and cos away from zero
            positions = tuple(rng.uniform(0.25, 1.3) for _ in groups.positions)
            block.append(
                [
                    constants + positions + tuple(rng.choice((-1, 1)) * rng.uniform(0.3, 1.6) for _ in groups.rates)
                    for _ in range(RATE_DRAWS)
                ]
            )
        out.append(block)
    return out


Values = list[list[list[float | None]]]


def values(expr: sp.Expr, groups: Groups) -> Values:
    """The expression at every sample point (None where it is undefined or not real)."""
    # lambdify prints only declared symbol names and the parser's allowlisted functions
    function = _numeric(expr, groups.symbols)
    return [[[_call(function, point) for point in block] for block in draw] for draw in points(groups)]


def _numeric(expr: sp.Expr, symbols: Sequence[sp.Symbol]) -> Callable[..., float]:
    expr = away_from_kinks(expr)
    if not expr.free_symbols:
        constant = complex(sp.N(expr))
        return lambda *_: constant.real if abs(constant.imag) < 1e-12 else math.nan
    return sp.lambdify(symbols, expr, modules="math")


def _call(function: Callable[..., float], point: tuple[float, ...]) -> float | None:
    try:
        value = float(function(*point))
    except (ValueError, ZeroDivisionError, OverflowError, TypeError):
        return None
    return value if math.isfinite(value) else None


def close(a: float, b: float) -> bool:
    return abs(a - b) <= RTOL * max(1.0, abs(a), abs(b))


def _flat(v: Values) -> list[float | None]:
    return [x for draw in v for block in draw for x in block]


def usable(a: Values, b: Values) -> int:
    return sum(x is not None and y is not None for x, y in zip(_flat(a), _flat(b), strict=True))


def equal(a: Values, b: Values) -> bool:
    pairs = [(x, y) for x, y in zip(_flat(a), _flat(b), strict=True) if x is not None and y is not None]
    return bool(pairs) and all(close(x, y) for x, y in pairs)


def _same_within(groups: list[list[float]]) -> bool:
    return all(all(close(x, g[0]) for x in g) for g in groups if g)


def differ_by_constant(a: Values, b: Values) -> bool:
    """a − b takes one value within each draw of the constants."""
    groups = []
    for da, db in zip(a, b, strict=True):
        groups.append(
            [x - y for ba, bb in zip(da, db, strict=True) for x, y in zip(ba, bb, strict=True) if None not in (x, y)]  # type: ignore[operator]
        )
    return any(len(g) > 1 for g in groups) and _same_within(groups)


def ratio_groups(a: Values, b: Values) -> list[list[float]]:
    """a / b within each draw of the constants and positions (points where b is not small)."""
    groups = []
    for da, db in zip(a, b, strict=True):
        for ba, bb in zip(da, db, strict=True):
            groups.append([x / y for x, y in zip(ba, bb, strict=True) if None not in (x, y) and abs(y) > 1e-9])  # type: ignore[arg-type,operator]
    return groups


def differ_by_factor(a: Values, b: Values) -> bool:
    """a / b is nonzero and free of the rates: the same equation wherever the factor is not zero."""
    groups = ratio_groups(a, b)
    if not any(len(g) > 1 for g in groups):
        return False
    return _same_within(groups) and all(abs(x) > 1e-9 for g in groups for x in g)


def factor_is_constant(a: Values, b: Values) -> bool:
    """The factor a / b does not change with the positions either (it depends on parameters at most)."""
    per_constants = []
    groups = ratio_groups(a, b)
    for i in range(CONSTANT_DRAWS):
        per_constants.append([x for g in groups[i * POSITION_DRAWS : (i + 1) * POSITION_DRAWS] for x in g])
    return _same_within(per_constants)


def symbolically_zero(expr: sp.Expr, units: float = SYMBOLIC_WORK) -> bool | None:
    """True when expr simplifies to 0 within its bound of work; None when undecided (never a proof of nonzero)."""
    try:
        with work_limit(units):
            expanded = sp.expand(expr)
            if expanded == 0 or pythagoras(expanded) == 0:
                return True
            return sp.simplify(expanded) == 0 or None
    except (WorkExceeded, RecursionError, TypeError, ValueError, NotImplementedError):
        return None


def without_constant(expr: sp.Expr, dynamic: frozenset[sp.Symbol]) -> tuple[sp.Expr, sp.Expr]:
    """(the part of expr that varies with the dynamic symbols, the constant part), after expansion."""
    varying, constant = sp.Integer(0), sp.Integer(0)
    for term in sp.Add.make_args(sp.expand(expr)):
        if term.free_symbols & dynamic:
            varying += term
        else:
            constant += term
    return varying, constant


def mistake_only(expr: sp.Expr, units: float) -> sp.Expr:
    """expr with whatever cancels identically gone, and its trigonometry recombined where that is shorter.

    Expanding every sine and cosine of a sum into products of single angles makes a
    difference's cancellation exact (θ̈₁ [cos(θ₁ − θ₂) − sin θ₁ sin θ₂ − cos θ₁ cos θ₂]
    is 0), and sin² + cos² = 1 is collected; products are then recombined
    (Fu's TR10i, then trigsimp) within the budget, keeping the shortest form.
    """

    if sp.count_ops(expr) > MISTAKE_ONLY_MAX_OPS or any(
        p.exp.is_negative and p.base.has(sp.sin, sp.cos) for p in expr.atoms(sp.Pow)
    ):
        # a long difference, or one over a trigonometric denominator (an acceleration's): expanding it would
        # only make it longer, and the display's own simplification has it
        return expr

    def canonical() -> sp.Expr:
        return pythagoras(sp.expand(sp.expand_trig(expr)))

    # the canonical form is cheap and decides what is shown at all: it gets most of the budget
    flat = within_budget(canonical, expr, units * 0.7)

    if not flat.free_symbols:
        return flat

    def shorter(best: sp.Expr, tried: sp.Expr) -> sp.Expr:
        return tried if sp.count_ops(tried) < sp.count_ops(best) else best

    # sums of products into sines and cosines of sums (Fu's TR10i: cheap and targeted), then trigsimp
    best = within_budget(lambda: shorter(flat, sp.factor_terms(TR10i(flat))), flat, units * 0.15)
    if sp.count_ops(best) > TRIGSIMP_MAX_OPS:
        return best  # trigsimp on a long sum seldom finishes within the budget: the work would be lost
    return within_budget(lambda: shorter(best, sp.factor_terms(sp.trigsimp(best))), best, units * 0.15)
