"""Reduction to one coordinate: effective potential, equilibria, small oscillations.

When every coordinate but one (call it r) is cyclic, each cyclic velocity is
eliminated through its conserved momentum p_c = P_c, giving Routh's function

    R(r, r_dot) = L - sum_c P_c q_dot_c  (with q_dot_c expressed through P_c).

R = 1/2 m_eff(r) r_dot^2 + (terms linear in r_dot) - U_eff(r); the linear terms
are a total derivative in one dimension and drop out of the motion, so the
conserved h reduces to the one-dimensional energy

    E_r = 1/2 m_eff(r) r_dot^2 + U_eff(r),   t(r) = ∫ dr / sqrt(2 (E_r - U_eff) / m_eff).

Equilibria solve U_eff'(r0) = 0, and small oscillations about a minimum have
omega^2 = U_eff''(r0) / m_eff(r0).  A one-coordinate autonomous system is its
own reduction (no cyclic momenta needed).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import sympy as sp

from app.engine.algebra.budget import within_budget
from app.engine.algebra.simplify import pythagoras, tidy
from app.engine.equations.conservation import Energetics
from app.engine.equations.lagrange import Equations
from app.engine.equations.mechanics import Mechanics
from app.limits import SOLVE_WORK


@dataclass(frozen=True)
class Equilibrium:
    position: sp.Expr
    omega_squared: sp.Expr
    stable: bool | None
    # where the position is an inverse cosine or sine arccos(a/b): it exists only while a < b (R ω² > g on the
    # spinning hoop), and ``stable`` is then the verdict wherever it exists
    exists: sp.Relational | None = None
    # where the sign of ω² depends on the parameters: the condition for ω² > 0 (g > R w² at the hoop's bottom)
    stable_when: sp.Relational | None = None


@dataclass(frozen=True)
class Reduction:
    coordinate: str
    momenta: tuple[sp.Symbol, ...]
    cyclic_velocities: dict[sp.Symbol, sp.Expr]
    routhian: sp.Expr
    effective_mass: sp.Expr
    effective_potential: sp.Expr
    radial_energy: sp.Expr
    time_integral: sp.Expr
    equilibrium_condition: sp.Expr
    omega_squared_at: sp.Expr
    equilibria: tuple[Equilibrium, ...]
    equilibria_solved: bool
    # ω² about a steady motion written in terms of the coordinate there, the momentum eliminated (None when
    # the condition U_eff' = 0 does not give the momentum's square as a function of the coordinate)
    omega_squared_steady: sp.Expr | None = None


def _positive_assumptions(mech: Mechanics, positive: set[str]) -> dict[sp.Symbol, sp.Symbol]:
    """Positive stand-ins for the symbols declared positive (masses, lengths, radii)."""
    symbols = (*mech.table.params, *mech.table.q)
    return {
        s: sp.Symbol(s.name, positive=True) if s in mech.table.params else sp.Symbol(s.name, nonnegative=True)
        for s in symbols
        if s.name in positive
    }


def reduce_to_one(
    mech: Mechanics, eqs: Equations, en: Energetics, positive: set[str] | None = None
) -> Reduction | None:
    """The one-coordinate reduction, or None when the system does not admit one."""
    table = mech.table
    free = [n for n in table.names if n not in en.cyclic]
    if len(free) != 1 or any(f != 0 for f in mech.Q) or en.dL_dt != 0:
        return None
    index = table.names.index(free[0])
    r, rd = table.q[index], table.qd[index]
    cyc = [table.names.index(n) for n in en.cyclic]
    P = tuple(sp.Symbol(f"p_{table.names[i]}", real=True) for i in cyc)

    # p_c(r, r_dot, q_dot_c) = P_c, linear in the cyclic velocities: solve for them
    unknowns = [table.qd[i] for i in cyc]
    solution: dict[sp.Symbol, sp.Expr] = {}
    if unknowns:
        system = [sp.Eq(eqs.momenta[i], Pc) for i, Pc in zip(cyc, P, strict=True)]
        # linear in the unknowns, but a large M can still make SymPy slow: bounded, and no reduction without it
        found: list[dict] = within_budget(lambda: sp.solve(system, unknowns, dict=True), [], SOLVE_WORK)
        if len(found) != 1:
            return None
        solution = {k: sp.factor_terms(v) for k, v in found[0].items()}

    # R = L - sum_c P_c q_dot_c, on the level set p_c = P_c
    R = (mech.L - sum(Pc * table.qd[i] for i, Pc in zip(cyc, P, strict=True))).xreplace(solution)
    R = sp.expand(R)
    if R.has(*[table.qd[i] for i in cyc]):
        return None
    # m_eff = d^2 R / d r_dot^2 (independent of r_dot when L is quadratic)
    m_eff = tidy(sp.diff(R, rd, 2))
    # U_eff = -R(r, r_dot = 0)
    U_eff = tidy(-R.xreplace({rd: 0}))
    E_r = sp.Symbol("E_r", real=True)
    energy = sp.Rational(1, 2) * m_eff * rd**2 + U_eff
    # t(r) = ∫ dr / sqrt(2 (E_r - U_eff) / m_eff)
    integrand = 1 / sp.sqrt(2 * (E_r - U_eff) / m_eff)
    time_integral = sp.Integral(integrand, r)

    dU = tidy(sp.diff(U_eff, r))
    d2U = sp.diff(U_eff, r, 2)
    # omega^2 = U_eff''(r0) / m_eff(r0)
    omega_sq = tidy(d2U / m_eff)

    assume = _positive_assumptions(mech, positive or set())
    # a conserved momentum is taken nonzero when solving (p = 0 reduces to the system without rotation)
    assume.update({Pc: sp.Symbol(Pc.name, real=True, nonzero=True) for Pc in P})
    back = {v: k for k, v in assume.items()}
    # U_eff'(r0) = 0, solved under the declared positivity (a radius has no negative root); the roots are
    # printed in their textbook forms, so SymPy's own simplification of each is not asked for (a third of the
    # single pendulum's reduction; every scene's and example's document is the same without it)
    r_assumed = assume.get(r, r)
    roots = within_budget(lambda: sp.solve(dU.xreplace(assume), r_assumed, simplify=False), None, SOLVE_WORK)
    equilibria: list[Equilibrium] = []
    solved = roots is not None
    # an angle's U_eff repeats every 2π: a root 2π − arccos a is the same place as −arccos a, as a textbook writes it
    periodic = sp.expand(U_eff.xreplace({r: r + 2 * sp.pi}) - U_eff) == 0
    for root in roots or []:
        root = root.xreplace(back)
        if root.has(sp.I) or root.is_real is False:
            continue
        if r in assume and root.xreplace(assume).is_negative:
            continue
        if periodic and sp.count_ops(root - 2 * sp.pi) < sp.count_ops(root):
            root = root - 2 * sp.pi
        w2 = tidy(omega_sq.xreplace({r: root}))
        sign = w2.xreplace(assume).is_positive
        stable = True if sign else (False if w2.xreplace(assume).is_nonpositive else None)
        exists = existence(root, assume)
        if exists is not None and stable is None:
            stable = stable_where_it_exists(w2, exists, assume)
        equilibria.append(Equilibrium(root, w2, stable, exists, positive_when(w2, assume) if stable is None else None))
    return Reduction(
        free[0],
        P,
        solution,
        R,
        m_eff,
        U_eff,
        energy,
        time_integral,
        dU,
        omega_sq,
        tuple(equilibria),
        solved,
        _steady_omega_squared(dU, omega_sq, P),
    )


def existence(root: sp.Expr, assume: dict[sp.Symbol, sp.Symbol]) -> sp.Relational | None:
    """a < b for a root built on arccos(a/b) or arcsin(a/b) with a, b positive: |a/b| ≤ 1 is where it exists, and
    a = b is where it meets the equilibrium it branches from (θ = 0 on the spinning hoop), so a < b is where it is
    a separate equilibrium; None for any other root."""
    inverse = list(root.atoms(sp.acos, sp.asin))
    if len(inverse) != 1:
        return None
    a, b = sp.fraction(sp.factor(inverse[0].args[0]))
    # b may vanish (R w² with a real w): b > a > 0 then excludes it, as a/b is not defined there
    if not (a.xreplace(assume).is_positive and b.xreplace(assume).is_nonnegative):
        return None
    return sp.StrictGreaterThan(b, a, evaluate=False)


def _solved_for(equation: sp.Eq, p: sp.Symbol) -> list[sp.Expr]:
    return list(sp.solve(equation, p))


def stable_where_it_exists(w2: sp.Expr, exists: sp.Relational, assume: dict[sp.Symbol, sp.Symbol]) -> bool | None:
    """The sign of ω² wherever ``exists`` (b > a) holds: a parameter of a written as b/(1 + u), u > 0 any."""
    b, a = exists.args
    # where it exists b > a > 0, so a product of powers b (R w²) has none of its letters zero: w ≠ 0 there
    if all(f.is_number or f.is_Symbol or (f.is_Pow and f.base.is_Symbol) for f in sp.Mul.make_args(b)):
        assume = {**{s: sp.Symbol(s.name, real=True, nonzero=True) for s in b.free_symbols}, **assume}
    u = sp.Symbol("u", positive=True)
    for p in sorted(a.free_symbols - b.free_symbols, key=sp.default_sort_key):
        solved: list[sp.Expr] | None = within_budget(partial(_solved_for, sp.Eq(a, b / (1 + u)), p), None, SOLVE_WORK)
        if not solved or len(solved) != 1:
            continue
        on = sp.factor(sp.together(w2.xreplace({p: solved[0]}).xreplace(assume)))
        if on.is_positive:
            return True
        if on.is_nonpositive:
            return False
    return None


def positive_when(w2: sp.Expr, assume: dict[sp.Symbol, sp.Symbol]) -> sp.Relational | None:
    """ω² > 0 as "positive terms > negative terms" of its numerator over a positive denominator: g/R − w² > 0
    is g > R w²; None when the terms' signs are not known from the parameters' positivity."""
    num, den = sp.fraction(sp.together(w2))
    if not den.xreplace(assume).is_positive:
        return None
    terms = sp.Add.make_args(sp.expand(num))
    # a term that may vanish (w² of a real w, zero when the hoop does not turn) still has its side: the condition
    # "plus > minus" is ω² > 0 itself whatever the values
    plus = [t for t in terms if t.xreplace(assume).is_nonnegative]
    minus = [-t for t in terms if t.xreplace(assume).is_nonpositive and not t.xreplace(assume).is_nonnegative]
    if len(plus) + len(minus) != len(terms) or not plus or not minus:
        return None
    return sp.StrictGreaterThan(sp.Add(*plus), sp.Add(*minus), evaluate=False)


def _steady_omega_squared(dU: sp.Expr, omega_sq: sp.Expr, momenta: tuple[sp.Symbol, ...]) -> sp.Expr | None:
    """ω² about a steady motion as a function of its coordinate r₀ alone, as a textbook writes it.

    With one conserved momentum p entering U_eff only through the centrifugal piece, U_eff′ = A(r) p² + B(r);
    the steady motion at r₀ has p² = −B(r₀)/A(r₀), and putting that into ω² = U_eff″/m_eff leaves r₀ and the
    parameters (a bead on a cone: ω² = 3g sin a cos a/r₀)."""
    if len(momenta) != 1:
        return None
    p = momenta[0]
    expanded = sp.expand(dU)
    A, B = expanded.coeff(p, 2), expanded.coeff(p, 0)
    if A == 0 or A.has(p) or B.has(p) or sp.expand(expanded - A * p**2 - B) != 0:
        return None
    # p² from U_eff'(r₀) = 0; cancelled, never simplified at large (SymPy's simplify here costs seconds)
    found = omega_sq.subs(p**2, -B / A)
    if found.has(p):
        return None
    found = sp.factor_terms(pythagoras(sp.cancel(found)))
    # tan written as sin/cos where that is shorter: 3g sin²a/(r₀ tan a) is 3g sin a cos a/r₀
    quotient = sp.factor_terms(sp.cancel(found.replace(sp.tan, lambda x: sp.sin(x) / sp.cos(x))))
    angles = {f.args[0] for f in quotient.atoms(sp.sin, sp.cos)}
    quotient = sp.factor_terms(quotient.xreplace({sp.sin(x) ** 2 + sp.cos(x) ** 2: sp.Integer(1) for x in angles}))
    return quotient if sp.count_ops(quotient) < sp.count_ops(found) else found
