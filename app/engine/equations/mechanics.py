"""From a declaration to T, U and L (the first steps of every derivation)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import sympy as sp

from app.engine.algebra.simplify import pythagoras
from app.engine.algebra.trig import merged
from app.engine.equations.bodies import BodyMotion, body_motion
from app.engine.errors import DerivationError
from app.engine.parser.parse import ExpressionError, parse_expression
from app.engine.parser.symbols import SymbolTable
from app.scenes.types import System


@dataclass(frozen=True)
class Mechanics:
    """Parsed mechanics: optional particle and rigid-body kinematics, then T, U (or only L).

    ``positions``, ``masses``, ``velocities`` and ``speeds_squared`` are the particles' (one each, in the
    declared order); ``bodies`` holds each rigid body's motion and its two pieces of T."""

    table: SymbolTable
    positions: tuple[tuple[sp.Expr, ...], ...]
    masses: tuple[sp.Expr, ...]
    velocities: tuple[tuple[sp.Expr, ...], ...]
    speeds_squared: tuple[sp.Expr, ...]
    T: sp.Expr | None
    U: sp.Expr | None
    L: sp.Expr
    Q: tuple[sp.Expr, ...]
    bodies: tuple[BodyMotion, ...] = ()


def _parse(
    text: str, names: dict[str, sp.Symbol], where: str, allow_velocity: bool, built: Mapping[str, sp.Expr]
) -> sp.Expr:
    if text in built:  # built from this text once already (System.built: docs/parsing.md)
        return built[text]
    allowed = names if allow_velocity else {k: v for k, v in names.items() if not k.endswith("_dot")}
    try:
        return parse_expression(text, allowed)
    except ExpressionError as exc:
        raise ExpressionError(f"{where}: {exc}", exc.part) from None


def build_mechanics(system: System) -> Mechanics:
    """Parse a System and form T, U and L = T - U."""
    table = SymbolTable(tuple(system.coordinates), tuple(p.name for p in system.parameters))
    names = table.namespace()
    forms = [bool(system.particles or system.bodies), system.kinetic is not None, system.lagrangian is not None]
    if sum(forms) != 1:
        raise DerivationError(
            "give exactly one of: particles or bodies (with a potential), kinetic and potential, or lagrangian"
        )
    if system.lagrangian is None and system.potential is None:
        raise DerivationError(
            "a potential U is needed with particles, bodies or with a kinetic energy (write 0 if none)"
        )

    positions: list[tuple[sp.Expr, ...]] = []
    masses: list[sp.Expr] = []
    velocities: list[tuple[sp.Expr, ...]] = []
    speeds: list[sp.Expr] = []
    for i, particle in enumerate(system.particles, start=1):
        if len(particle.position) != 3:
            raise DerivationError(f"particle {i}: a position has three components (x, y, z)")
        mass = _parse(particle.mass, names, f"particle {i} mass", False, system.built)
        r = tuple(_parse(c, names, f"particle {i} position", False, system.built) for c in particle.position)
        # v = dr/dt = dr/dt|_q + sum_k (dr/dq_k) q_dot_k
        v = tuple(table.dt(c) for c in r)
        masses.append(mass)
        positions.append(r)
        velocities.append(v)
        # v^2 = v . v, with sin^2 + cos^2 = 1 applied and sin a sin b + cos a cos b = cos(a - b) (app/engine/algebra/trig.py)
        speeds.append(merged(pythagoras(sum(c**2 for c in v))))

    bodies = tuple(
        body_motion(i, body, table, lambda text, where: _parse(text, names, where, False, system.built))
        for i, body in enumerate(system.bodies, start=1)
    )

    Q = tuple(
        _parse(system.forces[name], names, f"force on {name}", True, system.built)
        if name in system.forces
        else sp.Integer(0)
        for name in table.names
    )
    unknown = set(system.forces) - set(table.names)
    if unknown:
        raise DerivationError(f"forces are given for {sorted(unknown)}, which are not coordinates")

    if system.lagrangian is not None:
        L = _parse(system.lagrangian, names, "lagrangian", True, system.built)
        return Mechanics(table, (), (), (), (), None, None, L, Q)

    if system.particles or system.bodies:
        # T = sum_i 1/2 m_i v_i^2 over the particles + sum_b (1/2 M_b v_cm,b^2 + 1/2 I_cm,b omega_b^2) over the bodies
        particles_T = sum((sp.Rational(1, 2) * m * v2 for m, v2 in zip(masses, speeds, strict=True)), sp.Integer(0))
        T = merged(sp.expand(particles_T + sum((b.kinetic for b in bodies), sp.Integer(0))))
    else:
        T = _parse(system.kinetic or "", names, "kinetic energy", True, system.built)
    U = _parse(system.potential or "0", names, "potential", False, system.built)
    # L = T - U
    L = T - U
    return Mechanics(table, tuple(positions), tuple(masses), tuple(velocities), tuple(speeds), T, U, L, Q, bodies)


def positive_names(system: System) -> set[str]:
    """Parameters whose allowed range is positive, and coordinates declared as distances."""
    names = {p.name for p in system.parameters if p.min is not None and p.min > 0}
    return names | set(system.nonnegative)
