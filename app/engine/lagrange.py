"""Euler-Lagrange equations and the accelerations they determine.

For each coordinate q_k the engine forms

    dL/dq_k,   p_k = dL/dq_dot_k,   d/dt p_k,
    E_k = d/dt (dL/dq_dot_k) - dL/dq_k - Q_k = 0,

and, since E_k is linear in the accelerations, writes the system as

    M(q, t) q_ddot = f(q, q_dot, t),   M_jk = d^2 L / dq_dot_j dq_dot_k,

then solves it.  M must not depend on the velocities (L at most quadratic in
them) and must be invertible; otherwise the equations do not determine q_ddot.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import sympy as sp

from app.engine.budget import pythagoras
from app.engine.errors import DerivationError
from app.engine.mechanics import Mechanics

# Closed forms by Cramer's rule up to this many coordinates; LU elimination beyond.
CRAMER_MAX = 2


@dataclass(frozen=True)
class Equations:
    dL_dq: tuple[sp.Expr, ...]
    momenta: tuple[sp.Expr, ...]
    ddt_momenta: tuple[sp.Expr, ...]
    residuals: tuple[sp.Expr, ...]
    mass_matrix: sp.Matrix
    forcing: sp.Matrix
    accelerations: tuple[sp.Expr, ...]


def _numerically_singular(M: sp.Matrix, symbols: list[sp.Symbol], trials: int = 4) -> bool:
    """True when det M vanishes at every one of a few random real points."""
    rng = random.Random(20261122)
    det = M.det(method="berkowitz") if M.shape[0] <= 4 else None
    for _ in range(trials):
        point = {s: sp.Float(rng.uniform(0.3, 1.7)) for s in symbols}
        if det is not None:
            value = complex(det.xreplace(point).evalf())
            if abs(value) > 1e-9:
                return False
        else:
            numeric = M.xreplace(point).evalf()
            if numeric.rank(iszerofunc=lambda x: abs(complex(x)) < 1e-9) == M.shape[0]:
                return False
    return True


def euler_lagrange(mech: Mechanics) -> Equations:
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
    M = sp.Matrix([[sp.diff(p, s) for s in qd] for p in momenta])
    if any(M.has(s) for s in (*qd, *qdd)):
        raise DerivationError(
            "the mass matrix d²L/dq̇² depends on the velocities, so L is not quadratic in them; "
            "the engine handles L = (quadratic in q̇) + (linear in q̇) + (no q̇)"
        )
    if M.is_zero_matrix:
        raise DerivationError(
            "the mass matrix d²L/dq̇² is zero: L has no term quadratic in the velocities, "
            "so the Euler-Lagrange equations do not determine the accelerations"
        )
    free = sorted(M.free_symbols, key=lambda s: s.name)
    if _numerically_singular(M, free):
        raise DerivationError(
            "the mass matrix d²L/dq̇² is singular: the Euler-Lagrange equations do not determine "
            "every acceleration (is a coordinate missing from T, or are two coordinates redundant?)"
        )
    # f = -E|_{q_ddot = 0}, so that M q_ddot = f
    zero_acc = dict.fromkeys(qdd, sp.Integer(0))
    forcing = sp.Matrix([-sp.expand(r).xreplace(zero_acc) for r in residuals])
    if M.shape[0] <= CRAMER_MAX:
        # Cramer's rule, q_ddot = adj(M) f / det M, with sin² + cos² = 1 collected:
        # compact closed forms that display without further simplification
        det = sp.factor_terms(pythagoras(M.det(method="berkowitz")))
        solved = [sp.factor_terms(sp.expand(x)) / det for x in M.adjugate() * forcing]
    else:
        # q_ddot = M^-1 f by LU elimination, untidied: a 3x3 adjugate tidied term by term cost more
        # than the whole 4-coordinate elimination (the display tidies what it shows, in its own budget)
        solved = list(M.LUsolve(forcing))
    return Equations(dL_dq, momenta, ddt, residuals, M, forcing, tuple(solved))
