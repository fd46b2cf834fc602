"""Expressions that are real nowhere: refused before anything is derived from them.

A kinetic energy, potential or Lagrangian such as sqrt(-1 - x^2), log(-1 - x^2),
acos(2 + x^2), asin(2 + cos x) or (-1 - x^2)^(1/3) is not a real number at any
configuration, so no motion can be derived from it (SymPy would happily return
the imaginary acceleration -i x / sqrt(x^2 + 1)).  The test samples the
expression at random points of the configuration space (coordinates,
velocities and t, parameters at their defaults), in complex arithmetic so that
a square root of a negative number is imaginary, not NaN.  If the expression is
non-real at every sampled point where it is finite, it is refused, naming a
point where it is not real.  Non-real at a random point means non-real on an
open set around it (the value is continuous there); real at even one sampled
point means the declaration has a real region (sqrt(l^2 - x^2) for |x| < l) and
is allowed.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

import numpy as np
import sympy as sp

from app.engine.errors import excerpt
from app.engine.parser.parse import ExpressionError

SAMPLES = 40
SCALES = (0.3, 1.0, 3.0, 10.0)  # sizes of the sampled coordinates and velocities
REAL = 1e-9  # |Im| relative to |value| below which a value counts as real


def _value(f, point: list[complex]) -> complex | None:
    with np.errstate(all="ignore"):
        try:
            v = complex(f(*point))
        except (ValueError, ZeroDivisionError, OverflowError, TypeError):
            return None
    return v if math.isfinite(v.real) and math.isfinite(v.imag) else None


# functions that take real numbers to real numbers (where they are finite)
_REAL_FUNCTIONS = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc, sp.exp, sp.sinh, sp.cosh, sp.tanh, sp.Abs, sp.sign)


def _real_wherever_finite(expr: sp.Basic) -> bool:
    """Built of symbols, real numbers, sums, products, whole powers and the functions above only: real at
    every real point where it is finite, so the sampling (a lambdified function, a few ms for each of T, U
    and L) can only find it real.  Anything else (a root, a logarithm, asin, i, ∞) is sampled."""
    for node in sp.preorder_traversal(expr):
        if node.is_Symbol or (node.is_Number and node.is_extended_real and node.is_finite) or node in (sp.pi, sp.E):
            continue
        if node.is_Add or node.is_Mul or isinstance(node, _REAL_FUNCTIONS):
            continue
        if node.is_Pow and node.exp.is_Integer:
            continue
        return False
    return True


def nowhere_real(
    expr: sp.Expr, free: Iterable[sp.Symbol], fixed: Mapping[sp.Symbol, float] | None = None, seed: int = 3
) -> dict[str, float] | None:
    """A point where ``expr`` is not real, when it is real at none of the sampled points; else None.

    ``free`` are the symbols sampled (coordinates, velocities, t); ``fixed`` the parameters' values
    (1 for any symbol neither lists).
    """
    expr = sp.sympify(expr)
    if _real_wherever_finite(expr):
        return None
    fixed = dict(fixed or {})
    free = [s for s in free if s not in fixed]
    rest = sorted(expr.free_symbols - set(free) - set(fixed), key=lambda s: s.name)
    fixed.update(dict.fromkeys(rest, 1.0))
    symbols = [*free, *fixed]
    f = sp.lambdify(symbols, expr, modules=["numpy"], dummify=True)
    rng = np.random.default_rng(seed)
    witness: dict[str, float] | None = None
    finite = 0
    for i in range(SAMPLES):
        scale = SCALES[i % len(SCALES)]
        xs = [float(x) for x in rng.uniform(-scale, scale, len(free))]
        v = _value(f, [complex(x) for x in xs] + [complex(fixed[s]) for s in fixed])
        if v is None:
            continue
        finite += 1
        if abs(v.imag) <= REAL * max(abs(v), 1e-300):
            return None
        if witness is None:
            witness = {s.name: round(x, 3) for s, x in zip(free, xs, strict=True)}
            # the rounded point must still show it (it is an open set: a nearby point does)
            if _value(f, [complex(x) for x in witness.values()] + [complex(fixed[s]) for s in fixed]) is None:
                witness = {s.name: x for s, x in zip(free, xs, strict=True)}
    return witness if finite else None


def refuse_if_nowhere_real(
    text: str, expr: sp.Expr, free: Iterable[sp.Symbol], fixed: Mapping[sp.Symbol, float] | None = None
) -> None:
    """Raise ExpressionError naming the expression and a point, when it is real nowhere."""
    point = nowhere_real(expr, free, fixed)
    if point is None:
        return
    shown = {s.name for s in sp.sympify(expr).free_symbols}
    where = ", ".join(f"{name} = {value:g}" for name, value in point.items() if name in shown)
    at = f" (at {where}, for one)" if where else ""
    raise ExpressionError(
        f"{excerpt(text)} is not a real number anywhere{at}: energies and Lagrangians must be real, "
        "so check the signs under square roots and logarithms and the arguments of asin and acos",
        excerpt(text),
    )


def real_somewhere(text: str, expr: sp.Expr) -> sp.Expr:
    """``expr`` itself, once it is known to be real somewhere (else ExpressionError): for checked answers.

    Every symbol is sampled (parameters too, on both signs), so only an answer that no values can make
    real is refused: sqrt(-1 - theta_dot**2), not sqrt(m).
    """
    refuse_if_nowhere_real(text, expr, sorted(sp.sympify(expr).free_symbols, key=lambda s: s.name))
    return expr
