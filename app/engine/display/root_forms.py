"""A steady motion's radius as a textbook prints it: r₀ⁿ = C when the root is C^(1/n), not C's pieces under roots.

The equilibrium condition of a reduction is often a monomial equation, U_eff′ = a − b/r³ = 0, whose root
r₀ = (b/a)^(1/3) SymPy prints as a product of cube roots, ∛(1/cot α)|p_φ|^(2/3)/(m^(2/3)∛g).  A textbook
prints r₀³ = p_φ² tan α/(m² g): the least power n (up to MAX_POWER) whose r₀ⁿ has no fractional exponent.
The power form is checked numerically against the root before it is used, so it never states another number.
The frequency about the steady motion is written with r₀ and its trigonometric ratios cancelled:
3g sin²α cot α/r₀ is 3g sin α cos α/r₀.
"""

from __future__ import annotations

import random

import sympy as sp

MAX_POWER = 6  # r₀ⁿ tried for n = 2 … MAX_POWER
_CHECKS = 3  # random points at which r₀ⁿ and the power form must agree


def _fractional(expr: sp.Expr) -> bool:
    return any(p.exp.is_Rational and not p.exp.is_Integer for p in expr.atoms(sp.Pow))


def _even_abs(expr: sp.Expr) -> sp.Expr:
    """|x|^(2k) = x^(2k) for a real x."""
    return expr.replace(
        lambda e: e.is_Pow and isinstance(e.base, sp.Abs) and e.exp.is_Integer and e.exp % 2 == 0,
        lambda e: e.base.args[0] ** e.exp,
    )


def _reciprocal_trig(expr: sp.Expr) -> sp.Expr:
    """1/cot x = tan x and 1/tan x = cot x, the ratio a textbook keeps."""
    return expr.replace(
        lambda e: e.is_Pow and e.exp.is_Integer and e.exp < 0 and isinstance(e.base, (sp.cot, sp.tan)),
        lambda e: (sp.tan if isinstance(e.base, sp.cot) else sp.cot)(e.base.args[0]) ** (-e.exp),
    )


def _agree(a: sp.Expr, b: sp.Expr) -> bool:
    """a = b at a few points with every symbol between 0.3 and 1.2 (a root of positive quantities)."""
    rng = random.Random(0)
    symbols = sorted(a.free_symbols | b.free_symbols, key=str)
    for _ in range(_CHECKS):
        point = {s: sp.Float(rng.uniform(0.3, 1.2), 30) for s in symbols}
        x, y = complex(a.xreplace(point).evalf(30)), complex(b.xreplace(point).evalf(30))
        if abs(x - y) > 1e-12 * max(1.0, abs(x)):
            return False
    return True


def power_form(position: sp.Expr) -> tuple[int, sp.Expr]:
    """(n, C) with r₀ⁿ = C free of fractional exponents, the least such n; (1, position) when there is none."""
    if not _fractional(position):
        return 1, position
    for n in range(2, MAX_POWER + 1):
        # (Π bᵢ^(kᵢ/n))ⁿ = Π bᵢ^kᵢ for the positive bases of a real root
        power = _reciprocal_trig(_even_abs(sp.powdenest(sp.powsimp(position**n, force=True), force=True)))
        if not _fractional(power) and _agree(position**n, power):
            return n, power
    return 1, position


def trig_cancelled(expr: sp.Expr) -> sp.Expr:
    """tan and cot written as sines over cosines and cancelled, kept only where that is shorter:
    3g sin²α cot α/r₀ → 3g sin α cos α/r₀."""
    plain = sp.cancel(expr.replace(sp.cot, lambda x: sp.cos(x) / sp.sin(x)).replace(sp.tan, lambda x: sp.sin(x) / sp.cos(x)))
    return plain if sp.count_ops(plain) < sp.count_ops(expr) else expr
