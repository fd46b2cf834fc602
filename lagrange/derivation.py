"""A derivation in a notebook: the engine's steps and results, as SymPy objects and as typeset LaTeX."""

from __future__ import annotations

import html
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import sympy as sp

from app.engine.derivation.derive import Derivation as Derived
from app.engine.derivation.derive import derive as derive_system
from app.engine.document.contract import derivation_json
from lagrange.system import System


@dataclass(frozen=True)
class Step:
    """One step of a derivation: its title, the mathematics (LaTeX), and the one-line reason."""

    title: str
    latex: str
    reason: str

    def _repr_latex_(self) -> str:
        return f"$$\\textbf{{{_text(self.title)}}}\\qquad {self.latex}$$"


def _text(words: str) -> str:
    # plain words inside \text{…}: LaTeX's special characters escaped
    return "".join("\\" + c if c in "#$%&_{}" else c for c in words)


class Derivation:
    """What the engine derives about a system: T, U, L, the equations of motion, momenta, h, conserved
    quantities and the steps between them.  In Jupyter it displays its equations of motion; ``steps``
    displays every step."""

    def __init__(self, system: System, derived: Derived) -> None:
        self.system = system
        self.derived = derived  # the engine's own value (app/engine/derivation/derive.py)

    @cached_property
    def document(self) -> dict[str, Any]:
        """The printed document, as ``POST /api/derive`` answers it (LaTeX, SymPy text, reasons)."""
        return derivation_json(self.derived, self.system._scene)

    @property
    def lagrangian(self) -> sp.Expr:
        return self.derived.mechanics.L

    @property
    def kinetic(self) -> sp.Expr:
        return self.derived.mechanics.T

    @property
    def potential(self) -> sp.Expr:
        return self.derived.mechanics.U

    @property
    def equations(self) -> list[sp.Eq]:
        """The Euler–Lagrange equations, d/dt ∂L/∂q̇ − ∂L/∂q = Q, one per coordinate, as SymPy equations."""
        eq = self.derived.equations
        return [sp.Eq(sp.expand(r), 0) for r in eq.residuals]

    @property
    def accelerations(self) -> dict[str, sp.Expr]:
        """Each coordinate's acceleration (q̈ = …), where the engine solved for them in closed form; empty where it
        did not (a large system: ``equations`` still hold them)."""
        names, accelerations = self.derived.table.names, self.derived.equations.accelerations
        if len(accelerations) != len(names):  # no closed form (a large system): solve ℳ q̈ = f numerically
            return {}
        return {f"{q}_ddot": a for q, a in zip(names, accelerations, strict=True)}

    @property
    def steps(self) -> list[Step]:
        return [Step(s["title"], s["latex"], s.get("explanation", "")) for s in self.document["steps"]]

    def _repr_latex_(self) -> str:
        lines = [e["latex"] for e in self.document["equations_of_motion"]]
        return "$$\\begin{aligned}" + " \\\\ ".join(_aligned(line) for line in lines) + "\\end{aligned}$$"

    def _repr_html_(self) -> str:
        items = "".join(
            f"<li><strong>{html.escape(s.title)}</strong> $${html.escape(s.latex)}$$"
            f"<br><small>{html.escape(s.reason)}</small></li>"
            for s in self.steps
        )
        title = html.escape(self.system.title)
        return f"<details><summary>{title}: {len(self.steps)} steps</summary><ol>{items}</ol></details>" + (
            self._repr_latex_()
        )

    def __repr__(self) -> str:
        return f"<Derivation of {self.system.title}: {len(self.document['steps'])} steps>"


def _aligned(line: str) -> str:
    # the first "=" of each equation is where the lines align
    return line.replace("=", "&=", 1) if "=" in line else line


def derive(system: System) -> Derivation:
    """Derive a system's mechanics (the engine of the web book; no server, no time limit of its own)."""
    return Derivation(system, derive_system(system.declared))
