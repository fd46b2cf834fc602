"""The steps of the members beyond the chapter's core: the forces of constraint and the change of coordinates."""

from __future__ import annotations

import sympy as sp

from app.engine import meaning, notation
from app.engine.constraints import ConstraintForce
from app.engine.notation import CONSTRAINT
from app.engine.report import Printer, _mapping_step, _step, display
from app.engine.transform import Transformed, collected, compact


def constraint_steps(forces: tuple[ConstraintForce, ...], pr: Printer) -> list[dict[str, str]]:
    """The constraints in Cartesian form and the forces the multipliers give."""
    if not forces:
        return []
    return [
        _step(
            "constraints",
            "Constraints in Cartesian form",
            [rf"{CONSTRAINT}_{{{a + 1}}} = {pr.tex(f.g)} = 0" for a, f in enumerate(forces)],
            [f.g for f in forces],
            "Each constraint the coordinates satisfy silently is written again as a surface 𝒞 = 0 in Cartesian "
            "space; it can only push along its normal, the gradient of 𝒞.",
        ),
        _step(
            "constraint-forces",
            "Forces of constraint",
            [
                (rf"\lambda_{{{a + 1}}} = {pr.tex(f.multiplier)},\quad " if f.multiplier != f.force else "")
                # the force on the body the constraint names (``on``): λ times the size of 𝒞's gradient in its position
                + rf"F_{{{a + 1}}} = \lambda_{{{a + 1}}} \left|\frac{{\partial {CONSTRAINT}_{{{a + 1}}}}}"
                + rf"{{\partial \vec r_{{{f.constraint.on}}}}}\right| = {pr.tex(f.force)}"
                + rf"\quad (\text{{{f.constraint.name}}})"
                for a, f in enumerate(forces)
            ],
            [f.force for f in forces],
            "Newton's law with the unknown push λ ∇𝒞, m r̈ = −∇U + Σ λ ∇𝒞, is solved for the multipliers λ with the "
            "engine's accelerations put in for r̈. The force a constraint exerts on the body it acts on, at r_i, is "
            "λ ∂𝒞/∂r_i; its size F = λ |∂𝒞/∂r_i| is then a function of the coordinates and velocities alone, "
            "positive along the gradient.",
        ),
    ]


def transform_steps(tr: Transformed) -> list[dict[str, str]]:
    """The change of coordinates, the Lagrangian in the new ones and what it reveals."""
    d = tr.derivation
    old = Printer(tr.original.latex_names())
    pr = Printer(d.table.latex_names())
    steps = [
        _step(
            "change-of-coordinates",
            "Change of coordinates",
            [f"{pr.tex(Q)} = {old.tex(f)}" for Q, f in zip(d.table.q, tr.definitions, strict=True)],
            list(tr.definitions),
            tr.change.explanation or "New generalized coordinates, defined from the old ones.",
        ),
        _mapping_step(
            "inverse-map",
            "Inverse map",
            tr.inverse,
            "Solving the definitions for the old coordinates gives the map that is substituted into the declaration.",
            old,
            pr,
        ),
        _step(
            "new-lagrangian",
            "Lagrangian in the new coordinates",
            [f"L = {pr.tex(new_lagrangian(tr))}"],
            new_lagrangian(tr),
            "The same Lagrangian, now a function of the new coordinates and their velocities.",
        ),
    ]
    M = d.equations.mass_matrix
    rows = [rf"{notation.letter('mass_matrix', d)} = {pr.tex(M.applyfunc(display))}"]
    why = "The mass matrix in the new coordinates."
    if tr.decoupled:
        why = "The mass matrix is diagonal: each new coordinate moves with its own inertia, unmixed with the others."
    if tr.reduced_mass is not None:
        rows.append(rf"\mu = {pr.tex(tr.reduced_mass)}")
        why += f" The inertia of {tr.change.relative} is the reduced mass μ."
    steps.append(_step("new-inertia", "Inertia of the new coordinates", rows, M.applyfunc(display).tolist(), why))
    acc = [display(a) for a in d.equations.accelerations]
    steps.append(
        _step(
            "new-equations",
            "Equations in the new coordinates",
            [f"{pr.tex(s)} = {pr.tex(a)}" for s, a in zip(d.table.qdd, acc, strict=True)],
            acc,
            "The Euler–Lagrange equations derived again from the new Lagrangian.",
        )
    )
    for c in d.energetics.conserved:
        if c.name.startswith("p_"):
            back = tr.to_original(c.expr)
            # each side grouped by its own velocities: (m₁ + m₂)Ẋ = m₁ẋ₁ + m₂ẋ₂
            original = display(meaning.by_velocity(back, sorted((s for s in back.free_symbols if s.name.endswith("_dot")), key=str)))
            new = display(meaning.by_velocity(c.expr, d.table.qd))
            steps.append(
                _step(
                    f"conserved:{c.name}",
                    f"Conserved {c.name}",
                    [f"{c.latex_name} = {pr.tex(new)} = {old.tex(original)}"],
                    [new, original],
                    f"{c.reason} Written in the original coordinates it is the quantity on the right.",
                )
            )
    return steps


def new_lagrangian(tr: Transformed) -> sp.Expr:
    """L in the new coordinates, grouped by powers of the velocities (T) minus a compact U."""
    m = tr.derivation.mechanics
    if m.T is None:
        return collected(m.L, tr.derivation.table.qd)
    return collected(m.T, tr.derivation.table.qd) - compact(m.U)
