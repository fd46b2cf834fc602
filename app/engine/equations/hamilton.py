"""Hamilton's equations: the Legendre transform of L and the first-order equations in (q, p).

L is at most quadratic in the velocities (the engine checks it), so

    L = 1/2 q_dot . M(q, t) q_dot + b(q, t) . q_dot + L0(q, t),
    p = dL/dq_dot = M q_dot + b     (b: the momenta at q_dot = 0),

and the velocities follow from the momenta: q_dot = M^-1 (p - b).  Then

    H(q, p, t) = p . q_dot - L = 1/2 (p - b) . M^-1 (p - b) - L0,

the same quantity as h, written in (q, p).  Hamilton's equations are

    q_dot = dH/dp,    p_dot = -dH/dq + Q,

with the generalized forces Q (written through q_dot(q, p)) on the right.
Since H(q, p) = p . q_dot(q, p) - L(q, q_dot(q, p)), the chain rule gives
dH/dq at fixed p = -dL/dq at fixed q_dot (the terms through dq_dot/dq cancel
because p = dL/dq_dot), so -dH/dq is the engine's dL/dq with q_dot(q, p) put in:
the same function, without differentiating M^-1.
The momentum of coordinate q is the symbol ``p_q``.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from app.engine.algebra.simplify import pythagoras
from app.engine.equations.lagrange import Equations
from app.engine.equations.mechanics import Mechanics


@dataclass(frozen=True)
class Hamilton:
    momenta: tuple[sp.Symbol, ...]  # p_q, one per coordinate
    offsets: tuple[sp.Expr, ...]  # b = p at q_dot = 0
    velocities: tuple[sp.Expr, ...]  # q_dot(q, p) = M^-1 (p - b) = dH/dp
    hamiltonian: sp.Expr  # H(q, p, t)
    p_dot: tuple[sp.Expr, ...]  # -dH/dq + Q(q, q_dot(q, p))


def momentum_symbols(names: tuple[str, ...]) -> tuple[sp.Symbol, ...]:
    """The canonical momentum of coordinate ``q`` is the real symbol ``p_q``."""
    return tuple(sp.Symbol(f"p_{name}", real=True) for name in names)


def _inverse(M: sp.Matrix) -> tuple[sp.Matrix, sp.Expr]:
    """M^-1 as (A, D) with M^-1 = A / D; for up to three coordinates A = adj M, D = det M (sin² + cos² = 1 collected)."""
    if M.is_diagonal():
        return sp.diag(*[1 / M[i, i] for i in range(M.shape[0])]), sp.Integer(1)
    if M.shape[0] <= 3:
        return M.adjugate(), sp.factor_terms(pythagoras(M.det(method="berkowitz")))
    return M.inv(method="LU"), sp.Integer(1)


def hamilton(mech: Mechanics, eqs: Equations) -> Hamilton:
    """H(q, p, t) and Hamilton's equations from L's mechanics and its Euler-Lagrange equations."""
    table = mech.table
    zero_v = dict.fromkeys(table.qd, sp.Integer(0))
    P = momentum_symbols(table.names)
    M = eqs.mass_matrix
    # b = dL/dq_dot at q_dot = 0, so that p = M q_dot + b
    b = sp.Matrix([p.xreplace(zero_v) for p in eqs.momenta])
    # L0 = L at q_dot = 0
    L0 = mech.L.xreplace(zero_v)
    A, D = _inverse(M)
    r = sp.Matrix(P) - b
    # q_dot = M^-1 (p - b)
    Ar = A * r
    v = sp.Matrix([sp.factor_terms(pythagoras(x)) / D for x in Ar])
    # H = 1/2 (p - b) . M^-1 (p - b) - L0, the kinetic part over one denominator, the quadratic form built in
    # u = p - b and each u_k then written back as (p_k - b_k): where L has terms linear in the velocities the
    # squares stay completed, [(p_x + eBy/2)^2 + (p_y - eBx/2)^2]/(2m) for a charge in a magnetic field, as a
    # textbook prints them, not multiplied out into p_x^2 + eB p_x y + ...
    u = sp.Matrix([sp.Dummy(f"u_{name}") for name in table.names])
    quadratic = sp.factor_terms(pythagoras((u.T * A * u)[0, 0]))
    shifted = {uk: P[k] - sp.factor_terms(pythagoras(b[k])) for k, uk in enumerate(u)}
    H = quadratic.xreplace(shifted) / (2 * D) - L0
    to_p = dict(zip(table.qd, v, strict=True))
    # p_dot = -dH/dq + Q = dL/dq + Q, at q_dot(q, p)
    p_dot = tuple((g + Q).xreplace(to_p) for g, Q in zip(eqs.dL_dq, mech.Q, strict=True))
    return Hamilton(P, tuple(b), tuple(v), H, p_dot)
