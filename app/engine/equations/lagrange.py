"""Euler-Lagrange equations and the accelerations they determine.

For each coordinate q_k the engine forms

    dL/dq_k,   p_k = dL/dq_dot_k,   d/dt p_k,
    E_k = d/dt (dL/dq_dot_k) - dL/dq_k - Q_k = 0,

and, since E_k is linear in the accelerations, writes the system as

    W(q, q_dot, t) q_ddot = f(q, q_dot, t),   W_jk = d^2 L / dq_dot_j dq_dot_k,
    f = dL/dq - (d^2 L / dq_dot dq^T) q_dot - d^2 L / dq_dot dt + Q,

then solves it.  W (the mass matrix M when L is at most quadratic in the
velocities) may depend on them (a relativistic particle); it must be invertible
at a generic state and at rest, otherwise the equations do not determine q_ddot.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import numpy as np
import sympy as sp

from app.engine.algebra.fast import Fast, convertible, diff, expand
from app.engine.algebra.simplify import larger_than, pythagoras
from app.engine.display.names import unicode
from app.engine.equations.closed_form import by_cramer
from app.engine.equations.mechanics import Mechanics
from app.engine.errors import DerivationError
from app.engine.parser.symbols import SymbolTable

# Closed forms by Cramer's rule up to this many coordinates; LU elimination beyond.
CRAMER_MAX = 2
# A solved acceleration with more nodes than this is not a closed form worth showing or compiling:
# the document shows M q_ddot = f, and the numerics solve M q_ddot = f by LU at each step.
CLOSED_FORM_MAX_NODES = 400
# From this many coordinates on, the derivatives are taken on symengine (app.engine.algebra.fast).
SYMENGINE_FROM = 3


@dataclass(frozen=True)
class Equations:
    dL_dq: tuple[sp.Expr, ...]
    momenta: tuple[sp.Expr, ...]
    ddt_momenta: tuple[sp.Expr, ...]
    residuals: tuple[sp.Expr, ...]
    mass_matrix: sp.Matrix
    forcing: sp.Matrix
    accelerations: tuple[sp.Expr, ...]
    # whether the accelerations are short enough to show and compile; otherwise they are M⁻¹f, left
    # unexpanded (their tree shares subexpressions: never walk it whole, nor expand it)
    closed_form: bool = True
    # why the accelerations are or are not shown in closed form, with their measured size (empty: no question)
    closed_form_reason: str = ""
    # whether W = ∂²L/∂q̇² depends on the velocities (L not quadratic in them): then p = ∂L/∂q̇ is not
    # linear in q̇, and the members built on M(q, t) q̈ = f say what they leave out
    velocity_dependent: bool = False


# Smallest singular value, relative to the largest, below which an equilibrated M counts as singular.
RANK_TOLERANCE = 1e-10


def _equilibrated(A: np.ndarray, sweeps: int = 30) -> np.ndarray | None:
    """D⁻¹ A D⁻¹ with D positive diagonal such that every row's largest entry is 1 (Ruiz's sweeps).

    Any c S A S (c > 0, S positive diagonal) equilibrates to the same matrix, so what follows does
    not depend on the units of the masses, lengths or coordinates.  None when a row is zero.
    """
    for _ in range(sweeps):
        # r_i = sqrt(max_j |A_ij|); A_ij -> A_ij / (r_i r_j)
        r = np.sqrt(np.max(np.abs(A), axis=1))
        if not np.all(r > 0):
            return None
        A = A / np.outer(r, r)
        if np.max(np.abs(r - 1.0)) < 1e-6:
            break
    return A


def _rank_deficient(A: np.ndarray) -> bool:
    """True when the equilibrated A has a singular value below RANK_TOLERANCE times its largest."""
    E = _equilibrated(A)
    if E is None:
        return True
    s = np.linalg.svd(E, compute_uv=False)
    return bool(s[-1] <= RANK_TOLERANCE * s[0])


def _numerically_singular(M: sp.Matrix, symbols: list[sp.Symbol], trials: int = 4) -> bool:
    """True when M is rank-deficient at every one of a few random real points, judged relative to M itself.

    Scaling every mass by 10⁻⁶, or changing the unit of one coordinate, turns M into c S M S
    (c > 0, S positive diagonal) and must not change the verdict; an absolute threshold on det M
    would.  So at each point M (evaluated to 30 digits) is equilibrated, which removes c and S, and
    its rank read from the singular values with a relative tolerance.  A point where M is not finite
    tells nothing and another is drawn; with no usable point at all M is not called singular.
    """
    rng = random.Random(20261122)
    conclusive = 0
    for _ in range(3 * trials):
        point = {s: sp.Float(rng.uniform(0.3, 1.7), 30) for s in symbols}
        try:
            A = np.array([[complex(x) for x in row] for row in M.xreplace(point).evalf(30).tolist()])
        except (TypeError, ValueError, ArithmeticError):
            continue
        if not np.all(np.isfinite(A)):
            continue
        if not _rank_deficient(A):
            return False
        conclusive += 1
        if conclusive == trials:
            break
    return conclusive > 0


def _roots_expanded(expr: sp.Expr) -> sp.Expr:
    """Each fractional power's base expanded: ((c² − ẋ²)/c²)^{3/2} -> (1 − ẋ²/c²)^{3/2}."""
    return expr.replace(
        lambda e: e.is_Pow and e.exp.is_Rational and not e.exp.is_Integer,
        lambda e: sp.Pow(sp.expand(e.base), e.exp),
    )


def _refuse_singular_at_rest(W: sp.Matrix, qd: tuple[sp.Symbol, ...]) -> None:
    """Refuse a W(q, q̇, t) that is singular at rest, q̇ = 0: there the equations do not give q̈.

    A Lagrangian not quadratic in the velocities is regular where W = ∂²L/∂q̇∂q̇ᵀ is invertible; a
    simulation starts from (and the equilibria are linearised at) states with q̇ = 0, so W(q, 0, t) must
    be invertible too (L = ẋ⁴ has W = 12ẋ², zero at rest).
    """
    # W(q, 0, t): the matrix that multiplies q̈ in a state at rest
    at_rest = W.xreplace(dict.fromkeys(qd, sp.Integer(0)))
    shown = " = ".join(unicode(s.name) for s in qd)
    if at_rest.is_zero_matrix or _numerically_singular(at_rest, sorted(at_rest.free_symbols, key=lambda s: s.name)):
        raise DerivationError(
            f"the matrix ∂²L/∂q̇² depends on the velocities and is singular at rest ({shown} = 0), so there "
            "the Euler–Lagrange equations do not determine the accelerations; a Lagrangian not quadratic in "
            "the velocities needs ∂²L/∂q̇² invertible at q̇ = 0 (−mc²√(1 − ẋ²/c²) has m there)"
        )


def _on_sympy(mech: Mechanics) -> tuple[tuple[sp.Expr, ...], ...]:
    """dL/dq, p, dp/dt, the residuals E, the rows of M and f, in SymPy (any allowed function)."""
    table = mech.table
    L = mech.L
    q, qd, qdd = table.q, table.qd, table.qdd
    # dL/dq_k and p_k = dL/dq_dot_k
    dL_dq = tuple(sp.diff(L, s) for s in q)
    momenta = tuple(sp.diff(L, s) for s in qd)
    # d/dt p_k, a total derivative along the motion
    ddt = tuple(table.dt(p) for p in momenta)
    # E_k = d/dt p_k - dL/dq_k - Q_k  (= 0 on the motion)
    residuals = tuple(d - g - f for d, g, f in zip(ddt, dL_dq, mech.Q, strict=True))
    # M_jk = dp_j/dq_dot_k: the coefficient of q_ddot_k in E_j
    M = tuple(sp.diff(p, s) for p in momenta for s in qd)
    # f = -E|_{q_ddot = 0}, so that M q_ddot = f
    zero_acc = dict.fromkeys(qdd, sp.Integer(0))
    forcing = tuple(-sp.expand(r).xreplace(zero_acc) for r in residuals)
    return dL_dq, momenta, ddt, residuals, M, forcing


def _on_symengine(mech: Mechanics) -> tuple[tuple[sp.Expr, ...], ...]:
    """The same as _on_sympy, each derivative taken by symengine, each result converted back once."""
    table = mech.table
    fast = Fast((*table.q, *table.qd, *table.qdd, *table.params, table.t))
    q, qd, qdd = ([fast.to(s) for s in group] for group in (table.q, table.qd, table.qdd))
    t, L = fast.to(table.t), fast.to(mech.L)

    def dt(e):
        # d/dt e = de/dt + sum_k (de/dq_k) q_dot_k + (de/dq_dot_k) q_ddot_k
        return diff(e, t) + sum((diff(e, a) * b + diff(e, b) * c for a, b, c in zip(q, qd, qdd, strict=True)), 0)

    dL_dq = [diff(L, s) for s in q]
    momenta = [diff(L, s) for s in qd]
    ddt = [dt(p) for p in momenta]
    residuals = [d - g - fast.to(f) for d, g, f in zip(ddt, dL_dq, mech.Q, strict=True)]
    M = [diff(p, s) for p in momenta for s in qd]
    zero_acc = dict.fromkeys(qdd, 0)
    forcing = [-expand(r).subs(zero_acc) for r in residuals]
    return tuple(fast.back_all(x) for x in (dL_dq, momenta, ddt, residuals, M, forcing))


def euler_lagrange(mech: Mechanics) -> Equations:
    table = mech.table
    q, qd = table.q, table.qd
    # the derivatives on symengine for the larger systems, when every function in L and Q is one it
    # differentiates as SymPy does; the small ones (every chapter scene) keep SymPy's forms, which the
    # document shows as they come (symengine's are equal but grouped differently)
    fast = len(q) >= SYMENGINE_FROM and convertible((mech.L, *mech.Q))
    work = _on_symengine if fast else _on_sympy
    dL_dq, momenta, ddt, residuals, entries, forcing_entries = work(mech)
    n = len(q)
    # M_jk = dp_j/dq_dot_k: the coefficient of q_ddot_k in E_j
    M = sp.Matrix(n, n, entries)
    if M.is_zero_matrix:
        raise DerivationError(
            "the mass matrix ∂²L/∂q̇² is zero: L has no term quadratic in the velocities, "
            "so the Euler–Lagrange equations do not determine the accelerations"
        )
    free = sorted(M.free_symbols, key=lambda s: s.name)
    if _numerically_singular(M, free):
        raise DerivationError(
            "the mass matrix ∂²L/∂q̇² is singular: the Euler–Lagrange equations do not determine "
            "every acceleration (is a coordinate missing from T, or are two coordinates redundant?)"
        )
    velocity_dependent = M.has(*qd)
    if velocity_dependent:
        _refuse_singular_at_rest(M, qd)
    forcing = sp.Matrix(forcing_entries)
    if M.shape[0] <= CRAMER_MAX:
        # Cramer's rule, q_ddot = adj(M) f / det M, with sin² + cos² = 1 collected:
        # compact closed forms that display without further simplification
        det = sp.factor_terms(pythagoras(M.det(method="berkowitz")))
        solved = [sp.factor_terms(sp.expand(x)) / det for x in M.adjugate() * forcing]
        if velocity_dependent:
            # W(q̇) brings roots of the velocities (√(1 − ẋ²/c²)): over one denominator, powers of the same
            # base joined, then each root's base expanded: −kx√(1 − ẋ²/c²)/(m(ẋ²/(c² − ẋ²) + 1)) reads
            # −kx(1 − ẋ²/c²)^{3/2}/m
            solved = [_roots_expanded(sp.powsimp(sp.together(x))) for x in solved]
    else:
        # q_ddot = M^-1 f by LU elimination, untidied: a 3x3 adjugate tidied term by term cost more
        # than the whole 4-coordinate elimination (the display tidies what it shows, in its own budget)
        solved = list(M.LUsolve(forcing))
    closed_form = not any(larger_than(a, CLOSED_FORM_MAX_NODES) for a in solved)
    reason = ""
    if not closed_form and M.shape[0] > CRAMER_MAX:
        # LU's forms are too long: Cramer's rule, kept when its forms are short enough to read
        cramer = by_cramer(M, forcing, (*q, *qd, *table.params, table.t))
        reason = cramer.reason
        if cramer.accelerations is not None:
            solved, closed_form = list(cramer.accelerations), True
    elif not closed_form:
        reason = f"one has more than {CLOSED_FORM_MAX_NODES} operations"
    return Equations(
        dL_dq, momenta, ddt, residuals, M, forcing, tuple(solved), closed_form, reason, velocity_dependent
    )


def euler_lagrange_of(t: SymbolTable, k: int, L: sp.Expr) -> sp.Expr:
    """d/dt ∂L/∂q̇_k − ∂L/∂q_k of an expression L (linear in L: for a change of L, the change of the equation)."""
    p = sp.diff(L, t.qd[k])
    # the total time derivative: through every coordinate, velocity and t itself
    dp = sum((sp.diff(p, q) * v + sp.diff(p, v) * a for q, v, a in zip(t.q, t.qd, t.qdd, strict=True)),
             sp.diff(p, t.t))  # fmt: skip
    return sp.expand(dp - sp.diff(L, t.q[k]))
