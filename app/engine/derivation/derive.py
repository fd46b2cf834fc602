"""The whole derivation of a system, in the order the chapter teaches it.

``derive`` builds the core (T, U, L, the Euler-Lagrange equations, the conservation laws and the
reduction).  The members beyond it (the forces of constraint, the derivation in declared new
coordinates, Hamilton's equations, the equilibria and normal modes) are computed on first use, each
within its own bound of work (MEMBER_WORK), and kept on the derivation: each is either its value or a
``Skipped`` saying why it is left out.  Each analysis takes what it needs (the system, its mechanics,
its equations, the reduction), never the derivation: the derivation calls them.  The document (``app.engine.document.contract``) prints them; numerics,
viz, the service and the exports read them from here.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, TypeVar

import sympy as sp

from app.engine.algebra import work as counted
from app.engine.algebra.budget import Skipped, bounded, work_limit
from app.engine.algebra.work import WorkExceeded
from app.engine.display.names import MASS_MATRIX
from app.engine.equations.conservation import Energetics, energetics
from app.engine.equations.constraints import ConstraintForce, constraint_forces
from app.engine.equations.hamilton import Hamilton, hamilton
from app.engine.equations.lagrange import Equations, euler_lagrange
from app.engine.equations.mechanics import Mechanics, build_mechanics, positive_names
from app.engine.equations.reduction import Reduction, reduce_to_one
from app.engine.equations.transform import inertia, new_coordinates
from app.engine.equilibria.modes import NormalModes, normal_modes
from app.engine.errors import EquationsTooCostly
from app.engine.parser.symbols import SymbolTable
from app.limits import EQUATIONS_WORK, MEMBER_RESERVE_WORK, MEMBER_WORK, REDUCTION_WORK
from app.scenes.types import CoordinateChange, System

T = TypeVar("T")

# From LARGE_FROM coordinates on (no chapter scene has more than two) each bound is this share of its own:
# the equations come first
LARGE_FROM = 3
LARGE_SHARE = 0.5


@dataclass(frozen=True)
class Derivation:
    """Everything the engine derived about one system, as SymPy objects."""

    system: System
    mechanics: Mechanics
    equations: Equations
    energetics: Energetics
    reduction: Reduction | None
    # members left out of the derivation itself, each with its reason (the document adds its own)
    skipped: tuple[Skipped, ...] = ()
    # the members computed so far (by name, and by held momenta for the normal modes): pickled with the
    # derivation, so that a process loading it from the disk cache does not compute them again
    _members: dict[Any, Any] = field(default_factory=dict, init=False, repr=False, compare=False)

    @property
    def table(self) -> SymbolTable:
        return self.mechanics.table

    def member_work(self, member: str) -> float:
        """The bound of work of a member: its own, a share of it from LARGE_FROM coordinates on."""
        share = 1.0 if len(self.table.names) < LARGE_FROM else LARGE_SHARE
        return share * MEMBER_WORK[member]

    def _member(self, key: Any, member: str, what: str, work: Callable[[], T]) -> T | Skipped:
        """``work()`` within the member's bound, remembered; past the bound, a Skipped with its reason.

        A Skipped because an enclosing bound had little work left is not remembered: within another
        enclosing bound the member may well be computed."""
        if key in self._members:
            return self._members[key]
        units = self.member_work(member)
        outer = counted.left()
        constrained = outer is not None and outer - MEMBER_RESERVE_WORK < units
        notes: list[Skipped] = []
        # the value in a 1-tuple, told apart from the fallback (a member's value may itself be None)
        value = bounded(member, what, units, lambda: (work(),), None, notes)
        result: T | Skipped = notes[0] if notes or value is None else value[0]
        if not (notes and constrained):
            self._members[key] = result
        return result

    @property
    def constraint_forces(self) -> tuple[ConstraintForce, ...] | Skipped:
        """The force of each declared constraint (chapter § 4.2), by Lagrange multipliers.

        Raises DerivationError when the declared constraints do not fit the system."""
        return self._member("constraint_forces", "constraint_forces", "The forces of constraint",
                            lambda: constraint_forces(self.system, self.mechanics, self.equations))  # fmt: skip

    @property
    def transformed(self) -> Transformed | None | Skipped:
        """The derivation in the declared new coordinates (None when none is declared)."""
        return self._member("transformed", "transformed", "The derivation in the declared new coordinates",
                            lambda: transform(self.system))  # fmt: skip

    @property
    def hamilton(self) -> Hamilton | Skipped:
        """H(q, p, t) and Hamilton's equations."""
        if self.equations.velocity_dependent:
            return Skipped("hamilton", "Hamilton's equations are left out: ∂²L/∂q̇² depends on the velocities, so "
                           "p = ∂L/∂q̇ is not linear in q̇ and the engine does not invert it for q̇(q, p); "
                           "the Euler–Lagrange equations above hold as they are.")  # fmt: skip
        if not self.equations.closed_form and not self.equations.mass_matrix.is_diagonal():
            return Skipped("hamilton", f"Hamilton's equations are left out: q̇ = {MASS_MATRIX[1]}⁻¹(p − b) has no closed form "
                           "short enough to read for this many coordinates (as with the accelerations).")  # fmt: skip
        return self._member("hamilton", "hamilton", "Hamilton's equations", lambda: hamilton(self.mechanics, self.equations))

    def normal_modes(self, momenta: Mapping[str, float] | None = None) -> NormalModes | Skipped:
        """The equilibria, their stability and normal modes at the default parameters.

        ``momenta`` holds the conserved momenta of the reduction's relative equilibria (1 each when
        not given; a scene holds them at its initial state); each set is computed once."""
        held = dict(momenta or {})
        key = ("normal_modes", tuple(sorted(held.items())))
        return self._member(key, "normal_modes", "The equilibria and normal modes",
                            lambda: normal_modes(self.system, self.mechanics, self.equations, self.reduction, held))  # fmt: skip


@dataclass(frozen=True)
class Transformed:
    """The derivation in the new coordinates, with the maps between the two sets."""

    change: CoordinateChange
    original: SymbolTable
    definitions: tuple[sp.Expr, ...]
    inverse: dict[sp.Symbol, sp.Expr]
    system: System
    derivation: Derivation
    inertia: tuple[sp.Expr, ...]
    decoupled: bool
    reduced_mass: sp.Expr | None

    def to_original(self, expr: sp.Expr) -> sp.Expr:
        """Write an expression of the new coordinates and velocities in the old ones."""
        forward: dict[sp.Symbol, sp.Expr] = {}
        for Q, Qd, f in zip(self.derivation.table.q, self.derivation.table.qd, self.definitions, strict=True):
            # Q = f(q, t)  and  Q_dot = d/dt f(q, t)
            forward[Q] = f
            forward[Qd] = self.original.dt(f)
        return expr.xreplace(forward)


def transform(system: System) -> Transformed | None:
    """Derive the system again in its declared new coordinates (None when it declares none)."""
    new = new_coordinates(system)
    if new is None:
        return None
    d = derive(new.system)
    diagonal, decoupled, reduced = inertia(new.change, d.equations.mass_matrix)
    return Transformed(new.change, new.original, new.definitions, new.inverse, new.system, d, diagonal, decoupled, reduced)


def value_or(member: T | Skipped, fallback: T) -> T:
    """A member's value, or ``fallback`` when it was skipped."""
    return fallback if isinstance(member, Skipped) else member


def equations_of_motion(mech: Mechanics) -> Equations:
    """The Euler-Lagrange equations and the accelerations, within EQUATIONS_WORK: past it, the system is refused
    (EquationsTooCostly) at the same count of work at any load."""
    try:
        with work_limit(EQUATIONS_WORK):
            return euler_lagrange(mech)
    except WorkExceeded:
        raise EquationsTooCostly(
            "the equations of motion of this system need more algebra than this server's engine gives one system "
            "(a limit of the engine, not a mistake in the system); a form with fewer terms may derive"
        ) from None


def accelerations_only(system: System) -> Equations:
    """The fast path to q_ddot (what the numerics needs), without the later steps."""
    return equations_of_motion(build_mechanics(system))


def derive(system: System) -> Derivation:
    """Derive T, U, L, the Euler-Lagrange equations, conservation laws and the reduction."""
    mech = build_mechanics(system)
    eqs = equations_of_motion(mech)
    en = energetics(mech, eqs)
    skipped: list[Skipped] = []
    if eqs.velocity_dependent:
        # the reduction writes the reduced energy as ½ m_eff ṙ² + U_eff(r), true only for L quadratic in q̇
        skipped.append(Skipped("effective_potential", "The effective potential is left out: ∂²L/∂q̇² depends on "
                               "the velocities, so the energy is not an inertia times half the velocity squared "
                               "plus U_eff."))  # fmt: skip
        return Derivation(system, mech, eqs, en, None, tuple(skipped))
    # the one-coordinate reduction (effective potential, equilibria) is a refinement with its own bound
    red = bounded(
        "effective_potential", "The reduction to one coordinate (effective potential and its equilibria)",
        REDUCTION_WORK, lambda: reduce_to_one(mech, eqs, en, positive_names(system)), None, skipped,
    )  # fmt: skip
    return Derivation(system, mech, eqs, en, red, tuple(skipped))


def substitute_cyclic(expr: sp.Expr, red: Reduction) -> sp.Expr:
    """Write an expression on the level set of the conserved cyclic momenta."""
    return expr.xreplace(red.cyclic_velocities)
