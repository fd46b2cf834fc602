"""The whole derivation of a system, in the order the chapter teaches it."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from app.engine.budget import Skipped, bounded
from app.engine.conservation import Energetics, energetics
from app.engine.lagrange import Equations, euler_lagrange
from app.engine.mechanics import Mechanics, build_mechanics
from app.engine.reduction import Reduction, reduce_to_one
from app.limits import REDUCTION_SECONDS
from app.scenes.types import System


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

    @property
    def table(self):
        return self.mechanics.table


def positive_names(system: System) -> set[str]:
    """Parameters whose allowed range is positive, and coordinates declared as distances."""
    names = {p.name for p in system.parameters if p.min is not None and p.min > 0}
    return names | set(system.nonnegative)


def accelerations_only(system: System) -> Equations:
    """The fast path to q_ddot (what the numerics needs), without the later steps."""
    return euler_lagrange(build_mechanics(system))


def derive(system: System) -> Derivation:
    """Derive T, U, L, the Euler-Lagrange equations, conservation laws and the reduction."""
    mech = build_mechanics(system)
    eqs = euler_lagrange(mech)
    en = energetics(mech, eqs)
    skipped: list[Skipped] = []
    # the one-coordinate reduction (effective potential, equilibria) is a refinement with its own bound
    red = bounded(
        "effective_potential", "The reduction to one coordinate (effective potential and its equilibria)",
        REDUCTION_SECONDS, lambda: reduce_to_one(mech, eqs, en, positive_names(system)), None, skipped,
    )  # fmt: skip
    return Derivation(system, mech, eqs, en, red, tuple(skipped))


def substitute_cyclic(expr: sp.Expr, red: Reduction) -> sp.Expr:
    """Write an expression on the level set of the conserved cyclic momenta."""
    return expr.xreplace(red.cyclic_velocities)
