"""Forces of constraint by Lagrange multipliers (chapter § 4.2).

A scene posed in generalized coordinates hides its constraints: the positions
r_i(q, t) satisfy them identically.  Declared again in Cartesian form,
g_a(r_1, ..., r_N, t) = 0, each constraint pushes particle i along its normal,

    m_i r_i'' = -grad_i U + sum_a lambda_a grad_i g_a  (+ forces along the motion),

so along the true motion the vector b = (m_i r_i'' + grad_i U)_i of all 3N
components lies in the span of the constraint normals G = (grad g_a).  The
engine's accelerations give r_i'' as a function of q, q_dot and t, and

    G^T G lambda = G^T b

determines the multipliers (normal equations of a consistent system; a
generalized force Q acting along the motion is tangent to the constraint
surfaces, orthogonal to every grad g_a, and drops out).  The force a constraint
exerts on its particle i has size lambda_a |grad_i g_a| along grad_i g_a, which
does not depend on how g_a is scaled: that is the number reported.

Checks guard the declaration: every g_a must vanish on the positions r_i(q, t),
the Cartesian potential must equal U up to a constant, and b - G lambda must be
tangent to the motion (else a constraint whose force matters was left out).
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import sympy as sp

from app.engine.algebra.simplify import is_zero, pythagoras, tidy
from app.engine.equations.lagrange import Equations
from app.engine.equations.mechanics import Mechanics, positive_names
from app.engine.errors import DerivationError
from app.engine.parser.parse import ExpressionError, parse_expression
from app.engine.parser.symbols import SymbolTable
from app.scenes.types import Constraint, System

AXES = ("x", "y", "z")


@dataclass(frozen=True)
class ConstraintForce:
    """One constraint's force on its particle, as a function of q, q_dot, t and parameters."""

    constraint: Constraint
    g: sp.Expr
    gradient: tuple[sp.Expr, sp.Expr, sp.Expr]
    multiplier: sp.Expr
    force: sp.Expr
    # grad_i g on the motion for every particle i (index from 0): the force on particle i is multiplier * grad_i g
    gradients: tuple[tuple[sp.Expr, sp.Expr, sp.Expr], ...] = ()


def cartesian_symbols(count: int) -> tuple[tuple[sp.Symbol, sp.Symbol, sp.Symbol], ...]:
    """x, y, z for one particle; x1, y1, z1, x2, ... for several."""
    suffix = (lambda i: "") if count == 1 else (lambda i: str(i + 1))
    return tuple(tuple(sp.Symbol(f"{a}{suffix(i)}", real=True) for a in AXES) for i in range(count))


def _namespace(table: SymbolTable, cart) -> dict[str, sp.Symbol]:
    names = {s.name: s for s in (*table.params, table.t)}
    for triple in cart:
        for s in triple:
            if s.name in names:
                raise DerivationError(
                    f"the parameter {s.name!r} clashes with a Cartesian coordinate name used in constraints "
                    "(x, y, z for one particle; x1, y1, z1, ... for several)"
                )
            names[s.name] = s
    return names


def _parse(text: str, names: dict[str, sp.Symbol], where: str) -> sp.Expr:
    try:
        return parse_expression(text, names)
    except ExpressionError as exc:
        raise ExpressionError(f"{where}: {exc}", exc.part) from None


def positive(system: System, table: SymbolTable) -> dict[sp.Symbol, sp.Symbol]:
    """Positive stand-ins for the parameters and coordinates the system declares positive."""
    wanted = positive_names(system)
    return {s: sp.Symbol(s.name, positive=True) for s in (*table.params, *table.q) if s.name in wanted}


def display(expr: sp.Expr, positive: dict[sp.Symbol, sp.Symbol]) -> sp.Expr:
    """A compact form under the declared positivity (sqrt(R^2) = R for a length)."""
    back = {v: k for k, v in positive.items()}
    return tidy(pythagoras(sp.together(expr.xreplace(positive)))).xreplace(back)


def _random_point(symbols, seed: int) -> dict[sp.Symbol, sp.Float]:
    rng = random.Random(seed)
    return {s: sp.Float(rng.uniform(0.4, 1.3)) for s in symbols}


def _tangent_residual(residual: sp.Matrix, J: sp.Matrix, scale: sp.Matrix, symbols) -> bool:
    """True when, at a few generic points, the residual lies in the span of the columns of J."""
    for seed in range(3):
        point = _random_point(symbols, seed)
        r = residual.xreplace(point).evalf()
        Jn = J.xreplace(point).evalf()
        size = max(1.0, *(abs(float(v)) for v in scale.xreplace(point).evalf()))
        # least squares: r ≈ J c with (J^T J) c = J^T r
        c = (Jn.T * Jn).LUsolve(Jn.T * r)
        if max(abs(float(v)) for v in (r - Jn * c)) > 1e-8 * size:
            return False
    return True


def constraint_forces(system: System, mech: Mechanics, eqs: Equations) -> tuple[ConstraintForce, ...]:
    """The force of each declared constraint, with the engine's accelerations (``eqs``) substituted."""
    if not system.constraints:
        return ()
    table = mech.table
    if not mech.positions:
        raise DerivationError("constraint forces need the particles form (Cartesian positions of each mass)")
    if system.cartesian_potential is None:
        raise DerivationError("constraint forces need cartesian_potential: U in the particles' Cartesian coordinates")
    cart = cartesian_symbols(len(mech.positions))
    names = _namespace(table, cart)
    # r_i = r_i(q, t): the Cartesian coordinates in terms of the generalized ones
    on_motion = {s: c for triple, r in zip(cart, mech.positions, strict=True) for s, c in zip(triple, r, strict=True)}
    flat = [s for triple in cart for s in triple]

    U_c = _parse(system.cartesian_potential, names, "cartesian potential")
    # U_c(r(q, t)) - U(q, t) must not depend on q
    for q in table.q:
        if not is_zero(sp.diff(U_c.xreplace(on_motion) - mech.U, q)):
            raise DerivationError(f"the Cartesian potential differs from U by more than a constant (along {q.name})")

    gs = []
    for k, c in enumerate(system.constraints, start=1):
        if not 1 <= c.on <= len(mech.positions):
            raise DerivationError(f"constraint {c.name!r}: 'on' must number a particle from 1 to {len(mech.positions)}")
        g = _parse(c.expression, names, f"constraint {k}")
        # g(r(q, t), t) = 0 identically: the generalized coordinates already obey it
        if not is_zero(g.xreplace(on_motion)):
            raise DerivationError(f"constraint {c.name!r} does not hold on the declared positions: g(r(q, t)) ≠ 0")
        gs.append(g)

    # r_i'' = d/dt v_i, with q_ddot from the Euler-Lagrange equations
    accelerations = dict(zip(table.qdd, eqs.accelerations, strict=True))
    r_ddot = [table.dt(v).xreplace(accelerations) for vel in mech.velocities for v in vel]
    masses = [m for m in mech.masses for _ in AXES]
    # b = m_i r_i'' + grad_i U  (the part of m a that the applied forces do not explain)
    b = sp.Matrix([m * a + sp.diff(U_c, s).xreplace(on_motion) for m, a, s in zip(masses, r_ddot, flat, strict=True)])
    # G: one column grad g_a per constraint, on the motion
    G = sp.Matrix([[sp.diff(g, s).xreplace(on_motion) for g in gs] for s in flat])
    # G^T G lambda = G^T b
    GtG = (G.T * G).applyfunc(lambda e: pythagoras(sp.expand(e)))
    multipliers = GtG.LUsolve(G.T * b)

    # b - G lambda must be tangent to the motion: in the span of dr/dq_k
    J = sp.Matrix([[sp.diff(c, q) for q in table.q] for c in (c for r in mech.positions for c in r)])
    symbols = sorted((b.free_symbols | G.free_symbols | J.free_symbols), key=lambda s: s.name)
    if not _tangent_residual(b - G * multipliers, J, b, symbols):
        raise DerivationError(
            "the declared constraints do not account for the motion: some force perpendicular to the motion "
            "is missing (declare every constraint whose force is not zero, and the full Cartesian potential)"
        )

    held = positive(system, table)
    forces = []
    for a, (c, g) in enumerate(zip(system.constraints, gs, strict=True)):
        grad_on = tuple(G[3 * (c.on - 1) + i, a] for i in range(3))
        # the force on particle `on` is lambda_a grad g_a; its signed size along grad g_a
        norm = sp.sqrt(sum(e**2 for e in grad_on))
        lam = display(multipliers[a], held)
        force = display(multipliers[a] * norm, held)
        if force.has(*table.qdd):
            raise DerivationError(f"constraint {c.name!r}: accelerations remained in the force")
        every = tuple(tuple(G[3 * i + j, a] for j in range(3)) for i in range(len(mech.positions)))
        forces.append(ConstraintForce(c, g, grad_on, lam, force, every))
    return tuple(forces)
