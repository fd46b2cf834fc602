"""Shared helpers for the scene tests: cached engine results and symbol tables."""

from __future__ import annotations

import re
from functools import cache

import sympy as sp

from app.engine.derivation.derive import Transformed, transform
from app.engine.equations.constraints import ConstraintForce, constraint_forces
from app.scenes import SCENES
from app.service.chapter.derivations import derivation

FUNCTIONS = {"sin", "cos", "tan", "sqrt", "exp", "log", "pi", "Abs"}


def S(name: str) -> sp.Symbol:
    """The project's convention: every name is a real symbol."""
    return sp.Symbol(name, real=True)


@cache
def forces(scene_id: str) -> tuple[ConstraintForce, ...]:
    d = derivation(scene_id)
    return constraint_forces(d.system, d.mechanics, d.equations)


@cache
def transformed(scene_id: str) -> Transformed | None:
    return transform(SCENES[scene_id].system)


def force(scene_id: str, name: str) -> sp.Expr:
    return next(f.force for f in forces(scene_id) if f.constraint.name == name)


def read(text: str) -> sp.Expr:
    """A formula in the symbol convention, every name a real symbol (trusted test input)."""
    names = {n: S(n) for n in set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", text)) - FUNCTIONS}
    return sp.sympify(text, locals=names)


def along_motion(scene_id: str, expr: sp.Expr) -> sp.Expr:
    """d/dt of expr along the motion, with the engine's accelerations put in."""
    d = derivation(scene_id)
    acc = dict(zip(d.table.qdd, d.equations.accelerations, strict=True))
    return d.table.dt(expr).xreplace(acc)


def values(point: dict[str, float]) -> dict[sp.Symbol, float]:
    return {S(k): v for k, v in point.items()}


def close(a: sp.Expr, b: sp.Expr, point: dict[str, float], tol: float = 1e-9) -> bool:
    subs = values(point)
    va, vb = complex(sp.N(sp.sympify(a).xreplace(subs))), complex(sp.N(sp.sympify(b).xreplace(subs)))
    return abs(va - vb) <= tol * max(1.0, abs(va), abs(vb))
