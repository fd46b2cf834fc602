"""Cyclic coordinates, the Hamiltonian h, the energy E, and whether h = E.

    p_k = dL/dq_dot_k is conserved when q_k is absent from L and Q_k = 0,
    h = sum_k p_k q_dot_k - L,   dh/dt = -dL/dt|explicit + sum_k Q_k q_dot_k.

Writing T = T2 + T1 + T0 by degree in the velocities, Euler's theorem on
homogeneous functions gives sum_k q_dot_k dT/dq_dot_k = 2 T2 + T1, hence

    h = T2 - T0 + U   and   E - h = T1 + 2 T0,

which vanishes exactly when T is a homogeneous quadratic form: the case of
constraints fixed in time.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from app.engine.budget import is_zero, tidy
from app.engine.lagrange import Equations
from app.engine.mechanics import Mechanics


@dataclass(frozen=True)
class Conserved:
    name: str
    latex_name: str
    expr: sp.Expr
    reason: str


@dataclass(frozen=True)
class Energetics:
    cyclic: tuple[str, ...]
    conserved: tuple[Conserved, ...]
    dL_dt: sp.Expr
    hamiltonian: sp.Expr
    energy: sp.Expr
    energy_minus_h: sp.Expr
    h_equals_e: bool
    reason: str
    power: sp.Expr


def velocity_degrees(expr: sp.Expr, velocities: tuple[sp.Symbol, ...]) -> dict[int, sp.Expr]:
    """Split a polynomial in the velocities into its homogeneous parts by degree."""
    parts: dict[int, sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        degree = sum(sp.degree(term, v) for v in velocities) if term.has(*velocities) else 0
        parts[degree] = parts.get(degree, sp.Integer(0)) + term
    return parts


def energetics(mech: Mechanics, eqs: Equations) -> Energetics:
    table = mech.table
    qd = table.qd
    L = mech.L
    forced = any(f != 0 for f in mech.Q)

    cyclic = tuple(name for name, g, f in zip(table.names, eqs.dL_dq, mech.Q, strict=True) if is_zero(g) and f == 0)
    conserved = [
        Conserved(
            f"p_{name}",
            f"p_{{{table.latex_names()[table.q[table.names.index(name)]]}}}",
            eqs.momenta[table.names.index(name)],
            f"{name} does not appear in L and no generalized force acts on it, so dp/dt = ∂L/∂{name} = 0.",
        )
        for name in cyclic
    ]

    # dL/dt at fixed q and q_dot: the explicit time dependence
    dL_dt = sp.diff(L, table.t)
    dL_dt = sp.Integer(0) if is_zero(dL_dt) else dL_dt
    # h = sum_k p_k q_dot_k - L
    h = sp.expand(sum(p * v for p, v in zip(eqs.momenta, qd, strict=True)) - L)
    # dh/dt = -dL/dt|explicit + sum_k Q_k q_dot_k  (the power of the non-conservative forces)
    power = sp.expand(sum(f * v for f, v in zip(mech.Q, qd, strict=True)))

    if mech.T is None:
        E = h
        diff = sp.Integer(0)
        equal = True
        reason = "Only L was given, so T and U cannot be told apart; the energy reported is h itself."
    else:
        parts = velocity_degrees(mech.T, qd)
        unexpected = sorted(d for d in parts if d not in (0, 1, 2))
        # E = T + U
        E = sp.expand(mech.T + mech.U)
        # E - h = T1 + 2 T0
        diff = sp.expand(E - h)
        equal = is_zero(diff)
        diff = sp.Integer(0) if equal else tidy(diff)
        if equal:
            reason = (
                "T is a homogeneous quadratic form in the velocities (no constraint moves with time), "
                "so Σ q̇ ∂T/∂q̇ = 2T and h = 2T − T + U = T + U = E."
            )
        elif unexpected:
            reason = "T is not a polynomial of degree at most two in the velocities, so h differs from E."
        else:
            reason = (
                "The positions depend explicitly on time (a moving constraint), so T has parts of degree "
                "1 and 0 in the velocities and E − h = T₁ + 2T₀ ≠ 0."
            )

    if dL_dt == 0 and not forced:
        name = "E" if equal and mech.T is not None else "h"
        why = "L has no explicit time dependence and no non-conservative force acts, so dh/dt = −∂L/∂t = 0"
        if name == "E":
            why += ", and h = E here."
        else:
            why += "."
        conserved.append(Conserved(name, name, E if name == "E" else h, why))

    return Energetics(cyclic, tuple(conserved), dL_dt, h, E, diff, equal, reason, power)
