"""Rescale a declaration's parameters by unit: every mass (or length) parameter p becomes p * factor.

The rewritten system is the same physics with the named parameters multiplied by a constant, so
its accelerations must equal the original accelerations evaluated at the scaled parameter values.
Names are replaced in Python's ``ast`` tree (trusted test input), never by text substitution.
"""

from __future__ import annotations

import ast
import dataclasses

import sympy as sp

from app.engine.derivation.derive import accelerations_only
from app.scenes.types import Particle, System
from tests.reference import random_point


class _Scale(ast.NodeTransformer):
    def __init__(self, factors: dict[str, float]):
        self.factors = factors

    def visit_Name(self, node: ast.Name) -> ast.AST:
        if node.id in self.factors:
            return ast.BinOp(ast.Name(node.id, ast.Load()), ast.Mult(), ast.Constant(self.factors[node.id]))
        return node


def scale_text(text: str | None, factors: dict[str, float]) -> str | None:
    if text is None:
        return None
    tree = _Scale(factors).visit(ast.parse(text, mode="eval"))
    return ast.unparse(ast.fix_missing_locations(tree))


def scaled(system: System, factors: dict[str, float]) -> System:
    """The declaration with each named parameter p replaced by p * factors[p]."""
    s = lambda text: scale_text(text, factors)  # noqa: E731
    particles = tuple(Particle(s(p.mass), tuple(s(c) for c in p.position), p.label) for p in system.particles)
    bodies = tuple(
        dataclasses.replace(b, mass=s(b.mass), size=s(b.size), centre=tuple(s(c) for c in b.centre), angle=s(b.angle))
        for b in system.bodies
    )
    return dataclasses.replace(
        system,
        particles=particles,
        bodies=bodies,
        kinetic=s(system.kinetic),
        potential=s(system.potential),
        lagrangian=s(system.lagrangian),
        forces={k: s(v) for k, v in system.forces.items()},
        cartesian_potential=s(system.cartesian_potential),
        constraints=(),
        coordinate_change=None,
    )


def factors_for(system: System, units: tuple[str, ...], factor: float) -> dict[str, float]:
    """factor for every parameter whose unit is one of ``units`` (such as "kg" or "m")."""
    return {p.name: factor for p in system.parameters if p.unit in units}


UNIT_SETS = (("kg",), ("m",), ("kg", "m"))
FACTORS = (1e-6, 1e6)


def scaling_cases(
    systems: dict[str, System], unit_sets: tuple[tuple[str, ...], ...] = UNIT_SETS
) -> list[tuple[str, tuple[str, ...], float]]:
    """(name, units, factor) for every system that has a parameter in those units."""
    return [
        (name, units, factor)
        for name in sorted(systems)
        for units in unit_sets
        for factor in FACTORS
        if factors_for(systems[name], units, factor)
    ]


def check_scaled_accelerations(system: System, factors: dict[str, float], original: tuple[sp.Expr, ...]) -> None:
    """The scaled system derives (no refusal) and a'(q, q_dot; p) = a(q, q_dot; p scaled), to 1e-9."""
    ours = accelerations_only(scaled(system, factors)).accelerations
    symbols = sorted(set().union(*(a.free_symbols for a in (*ours, *original))), key=str)
    point = random_point(symbols, seed=3)
    substituted = {s: (v * factors[s.name] if s.name in factors else v) for s, v in point.items()}
    for a, b in zip(ours, original, strict=True):
        va, vb = complex(sp.N(a.xreplace(point), 30)), complex(sp.N(b.xreplace(substituted), 30))
        assert abs(va - vb) <= 1e-9 * max(abs(va), abs(vb), 1e-300), (factors, va, vb)
