"""A change of generalized coordinates: the declaration written again in the new ones.

A declaration may name new coordinates Q_j = f_j(q, t) (for two bodies on a
line: the centre of mass X = (m1 x1 + m2 x2)/(m1 + m2) and the separation
x = x2 - x1).  The engine solves the definitions for the old coordinates,
q = q(Q, t), substitutes this inverse map into the declaration (the particles'
positions, or T, or L, and U), transforms the generalized forces by the chain
rule,

    Q'_j = sum_k Q_k dq_k/dQ_j,

and the derivation (``app.engine.derivation.derive``) derives everything again from the new
declaration: nothing about the result is assumed.  A coordinate that drops out
of the new L is then found cyclic by the usual test, and the mass matrix in the
new coordinates shows the inertia each one carries (``inertia``: for the
separation, the reduced mass).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from app.engine.algebra.budget import within_budget
from app.engine.algebra.simplify import is_zero, tidy
from app.engine.errors import DerivationError
from app.engine.parser.parse import ExpressionError, parse_expression
from app.engine.parser.symbols import SymbolTable
from app.limits import SOLVE_WORK
from app.scenes.types import CoordinateChange, Particle, System


@dataclass(frozen=True)
class NewCoordinates:
    """The declaration written in the new coordinates, with the maps between the two sets."""

    change: CoordinateChange
    original: SymbolTable
    definitions: tuple[sp.Expr, ...]  # Q_j = f_j(q, t)
    inverse: dict[sp.Symbol, sp.Expr]  # q = q(Q, t)
    system: System  # the declaration in the new coordinates


def _text(expr: sp.Expr, names: dict[str, sp.Symbol]) -> str:
    """The expression as declaration text, checked to read back as the same expression."""
    text = sp.sstr(expr)
    try:
        back = parse_expression(text, names)
    except ExpressionError as exc:
        raise DerivationError(f"the transformed expression cannot be written back as a declaration: {exc}") from None
    if not is_zero(back - expr):
        raise DerivationError("the transformed expression does not read back unchanged")
    return text


def collected(expr: sp.Expr, symbols) -> sp.Expr:
    """expr as a sum over monomials in ``symbols``, each coefficient brought to lowest terms."""
    parts = sp.collect(sp.expand(expr), list(symbols), evaluate=False)
    return sp.Add(*(tidy(coefficient) * monomial for monomial, coefficient in parts.items()))


def compact(expr: sp.Expr) -> sp.Expr:
    """The shorter of the budgeted display form and the factored form (k (x - l0)^2 / 2 stays a square)."""
    factored = within_budget(lambda: sp.factor(sp.cancel(expr)), expr, SOLVE_WORK)
    return min((tidy(expr), factored), key=sp.count_ops)


def new_coordinates(system: System) -> NewCoordinates | None:
    """The system declared again in its declared new coordinates (None when it declares none)."""
    change = system.coordinate_change
    if change is None:
        return None
    if len(change.coordinates) != len(system.coordinates) or len(change.definitions) != len(change.coordinates):
        raise DerivationError(
            "a change of coordinates needs one definition per new coordinate, as many as the old ones"
        )
    clash = set(change.coordinates) & set(system.coordinates)
    if clash:
        raise DerivationError(f"new coordinates must have new names; {sorted(clash)} are already coordinates")
    params = tuple(p.name for p in system.parameters)
    old = SymbolTable(tuple(system.coordinates), params)
    new = SymbolTable(tuple(change.coordinates), params)
    old_names = {k: v for k, v in old.namespace().items() if not k.endswith("_dot")}
    try:
        defs = tuple(parse_expression(text, old_names) for text in change.definitions)
    except ExpressionError as exc:
        raise ExpressionError(f"coordinate change: {exc}", exc.part) from None

    # Solve Q_j = f_j(q, t) for the old coordinates: the inverse map q = q(Q, t)
    equations = [sp.Eq(Q, f) for Q, f in zip(new.q, defs, strict=True)]
    found = within_budget(lambda: sp.solve(equations, list(old.q), dict=True), None, SOLVE_WORK)
    if not found or len(found) != 1 or set(found[0]) != set(old.q):
        raise DerivationError("the change of coordinates could not be inverted to a single map q = q(Q, t)")
    inverse = {q: collected(found[0][q], new.q) for q in old.q}
    # dq/dt along the motion, in the new coordinates: q_dot = sum_j dq/dQ_j Q_dot_j + dq/dt
    velocities = {qd: new.dt(inverse[q]) for q, qd in zip(old.q, old.qd, strict=True)}
    to_new = {**inverse, **velocities}

    names = new.namespace()
    particles = tuple(
        Particle(
            p.mass,
            tuple(_text(collected(parse_expression(c, old_names).xreplace(inverse), new.q), names) for c in p.position),  # type: ignore[arg-type]
            p.label,
        )
        for p in system.particles
    )

    def placed(text: str) -> str:
        # a position (a particle's or a body's centre) or a body's angle, written in the new coordinates
        return _text(collected(parse_expression(text, old_names).xreplace(inverse), new.q), names)

    bodies = tuple(
        replace(b, centre=(placed(b.centre[0]), placed(b.centre[1]), placed(b.centre[2])), angle=placed(b.angle))
        for b in system.bodies
    )

    def moved(text: str | None, with_velocities: bool) -> str | None:
        # a potential keeps its shape (k (x - l0)^2 / 2); T and L are sorted by powers of the velocities
        if text is None:
            return None
        expr = parse_expression(text, old.namespace() if with_velocities else old_names).xreplace(to_new)
        return _text(collected(expr, new.qd) if with_velocities else compact(expr), names)

    # Q'_j = sum_k Q_k dq_k/dQ_j
    old_forces = [parse_expression(system.forces.get(n, "0"), old.namespace()).xreplace(to_new) for n in old.names]
    forces = {}
    for Qj, name in zip(new.q, new.names, strict=True):
        f = sp.expand(sum(F * sp.diff(inverse[q], Qj) for F, q in zip(old_forces, old.q, strict=True)))
        if f != 0:
            forces[name] = _text(compact(f), names)

    moved_system = replace(
        system,
        coordinates=tuple(change.coordinates),
        particles=particles,
        bodies=bodies,
        kinetic=moved(system.kinetic, True),
        potential=moved(system.potential, False),
        lagrangian=moved(system.lagrangian, True),
        forces=forces,
        nonnegative=(),
        coordinate_change=None,
    )
    return NewCoordinates(change, old, defs, inverse, moved_system)


def inertia(change: CoordinateChange, M: sp.Matrix) -> tuple[tuple[sp.Expr, ...], bool, sp.Expr | None]:
    """The inertia each new coordinate carries (the diagonal of the mass matrix M in the new coordinates),
    whether M is diagonal (the new coordinates decoupled in T), and the relative coordinate's inertia, the
    reduced mass, when it is declared and decoupled."""
    diagonal = tuple(tidy(M[i, i]) for i in range(M.shape[0]))
    decoupled = all(is_zero(M[i, j]) for i in range(M.shape[0]) for j in range(M.shape[1]) if i != j)
    reduced = None
    if change.relative is not None:
        if change.relative not in change.coordinates:
            raise DerivationError(f"'relative' names {change.relative!r}, which is not a new coordinate")
        if decoupled:
            reduced = diagonal[change.coordinates.index(change.relative)]
    return diagonal, decoupled, reduced
