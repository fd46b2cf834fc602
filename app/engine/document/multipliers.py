"""The multipliers of the constraints derived as a student derives them (chapter § 4.2).

The constraints 𝒞_a(r, t) = 0 join the Lagrangian written in Cartesian coordinates with one unknown
multiplier each,

    L′ = Σ ½ m_i |ṙ_i|² − U(r) + Σ λ_a 𝒞_a,

whose Euler–Lagrange equations are Newton's law with the constraints' pushes along their normals,

    m_i r̈_i = −∇_i U + Σ_a λ_a ∇_i 𝒞_a  (+ F_i, a force along the motion when the scene has one).

Each constraint holds at every instant, so its second time derivative vanishes:

    𝒞̈_a = Σ_i ∇_i 𝒞_a · r̈_i + c_a = 0,  c_a = the terms of 𝒞̈_a without accelerations.

Putting r̈_i from Newton's law into it takes the component of the equations along the normals and leaves
a linear system for the multipliers alone,

    Σ_b (Σ_i ∇_i 𝒞_a · ∇_i 𝒞_b / m_i) λ_b = Σ_i ∇_i 𝒞_a · (∇_i U − F_i) / m_i − c_a,

solved here and then written on the motion (r_i = r_i(q, t), ṙ_i from the velocities).  The engine's
multipliers (app.engine.equations.constraints) come from the same Newton law with its accelerations put in; the two
agree, and the tests check it scene by scene.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from app.engine.algebra.simplify import pythagoras
from app.engine.derivation.derive import Derivation
from app.engine.equations.constraints import AXES, ConstraintForce, cartesian_symbols
from app.engine.parser.parse import parse_expression


@dataclass(frozen=True)
class Multipliers:
    """The Cartesian derivation of the multipliers, every piece an expression in Cartesian symbols."""

    positions: tuple[sp.Symbol, ...]  # x, y, z (x1, y1, z1, ... for several bodies)
    velocities: tuple[sp.Symbol, ...]
    accelerations: tuple[sp.Symbol, ...]
    masses: tuple[sp.Expr, ...]  # the mass of each component's body
    multipliers: tuple[sp.Symbol, ...]  # λ_1, λ_2, ...
    constraints: tuple[sp.Expr, ...]
    lagrangian: sp.Expr  # L′ = T − U + Σ λ_a 𝒞_a
    newton: tuple[sp.Expr, ...]  # the right side of m r̈ for each component
    applied: tuple[sp.Expr, ...]  # the force along the motion of each component, on the motion (0 without one)
    twice: tuple[sp.Expr, ...]  # 𝒞̈_a with the accelerations as symbols
    normal: sp.Matrix  # Σ_i ∇_i𝒞_a · ∇_i𝒞_b / m_i
    right: sp.Matrix  # Σ_i ∇_i𝒞_a · (∇_i U − F_i)/m_i − c_a
    on_motion: dict[sp.Symbol, sp.Expr]  # every Cartesian position and velocity as a function of q, q̇, t
    solved: tuple[sp.Expr, ...]  # λ_a on the motion


def derived_multipliers(d: Derivation, forces: tuple[ConstraintForce, ...]) -> Multipliers:
    """The multipliers by the Cartesian Lagrangian with the constraints, for the forces the engine found."""
    mech, table = d.mechanics, d.table
    count = len(mech.positions)
    cart = cartesian_symbols(count)
    positions = tuple(s for triple in cart for s in triple)
    velocities = tuple(sp.Symbol(f"{s.name}_dot", real=True) for s in positions)
    accelerations = tuple(sp.Symbol(f"{s.name}_ddot", real=True) for s in positions)
    masses = tuple(m for m in mech.masses for _ in AXES)
    lams = tuple(sp.Symbol(f"lambda_{a + 1}", real=True) for a in range(len(forces)))
    names = {s.name: s for s in (*table.params, table.t, *positions)}
    U = parse_expression(d.system.cartesian_potential or "0", names)
    gs = tuple(f.g for f in forces)
    t = table.t

    # L′ = Σ ½ m_i |ṙ_i|² − U + Σ λ_a 𝒞_a
    T = sum((m * v**2 / 2 for m, v in zip(masses, velocities, strict=True)), sp.Integer(0))
    lagrangian = T - U + sum((lam * g for lam, g in zip(lams, gs, strict=True)), sp.Integer(0))
    # m r̈ = ∂L′/∂r: −∂U/∂r + Σ λ_a ∂𝒞_a/∂r
    newton = tuple(sp.diff(lagrangian, s) for s in positions)

    on_motion = {s: c for s, c in zip(positions, (c for r in mech.positions for c in r), strict=True)}
    on_motion |= {v: c for v, c in zip(velocities, (c for r in mech.velocities for c in r), strict=True)}
    applied = _applied(d)

    # 𝒞̇ = Σ ∂𝒞/∂s ṡ + ∂𝒞/∂t, and 𝒞̈ the same rule once more (ṡ → s̈)
    def dot(e: sp.Expr) -> sp.Expr:
        return (
            sum((sp.diff(e, s) * v for s, v in zip(positions, velocities, strict=True)), sp.Integer(0))
            + sum((sp.diff(e, v) * a for v, a in zip(velocities, accelerations, strict=True)), sp.Integer(0))
            + sp.diff(e, t)
        )

    twice = tuple(sp.expand(dot(dot(g))) for g in gs)
    rest = [e.xreplace({a: 0 for a in accelerations}) for e in twice]
    grads = [[sp.diff(g, s) for s in positions] for g in gs]
    gradU = [sp.diff(U, s) for s in positions]
    k = len(gs)
    # the normal component: Σ_i ∇_i𝒞_a · ∇_i𝒞_b / m_i
    normal = sp.Matrix(k, k, lambda a, b: sum(ga * gb / m for ga, gb, m in zip(grads[a], grads[b], masses, strict=True)))
    # Σ_i ∇_i𝒞_a · (∇_i U − F_i)/m_i − c_a
    # the force along the motion is tangent to every constraint: its share Σ_i ∇_i𝒞_a · F_i / m_i
    # is zero on the motion (kept in the equation if ever it were not)
    along = [
        sp.simplify(sum((g.xreplace(on_motion) * f / m for g, f, m in zip(grads[a], applied, masses, strict=True)), sp.Integer(0)))
        for a in range(k)
    ]
    right = sp.Matrix(
        [
            sum((g * u / m for g, u, m in zip(grads[a], gradU, masses, strict=True)), sp.Integer(0)) - rest[a]
            - along[a]
            for a in range(k)
        ]
    )
    solved = normal.xreplace(on_motion).LUsolve(right.xreplace(on_motion))
    return Multipliers(
        positions, velocities, accelerations, masses, lams, gs, lagrangian, newton, applied, twice,
        normal.applyfunc(lambda e: sp.factor(pythagoras(sp.expand(e)))), right.applyfunc(sp.factor), on_motion, tuple(solved),
    )  # fmt: skip


def _applied(d: Derivation) -> tuple[sp.Expr, ...]:
    """The Cartesian force of the scene's generalized forces Q_k, along the motion: F = J (JᵀJ)⁻¹ Q with
    J = ∂r/∂q (zero when the scene has none).  It is tangent to every constraint surface."""
    mech, table = d.mechanics, d.table
    flat = [c for r in mech.positions for c in r]
    Q = sp.Matrix(list(mech.Q))
    if all(e == 0 for e in Q):
        return tuple(sp.Integer(0) for _ in flat)
    J = sp.Matrix([[sp.diff(c, q) for q in table.q] for c in flat])
    F = J * (J.T * J).applyfunc(sp.simplify).LUsolve(Q)
    return tuple(sp.simplify(e) for e in F)
