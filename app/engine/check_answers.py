"""A student's answer to a step (app/engine/check.py): the names it may use, and its reading.

Each step's answer may name some kinds of name only (U no velocity, an acceleration only in the equation
step, ω² only the parameters and conserved momenta); ``check_answer`` refuses any other in pure Python,
with the reason, before the parser's first two gates, so a web process can refuse bad text without SymPy.
``parse_answer`` gives the answer in SymPy, for the worker that judges it.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import sympy as sp

from app.engine.parse import ExpressionError, check_expression, parse_expression
from app.engine.reality import real_somewhere

if TYPE_CHECKING:  # the problem an answer is read for (imported for its type only)
    from app.engine.check_problem import Problem

STEPS = ("kinetic", "potential", "lagrangian", "momentum", "equation", "acceleration", "hamiltonian", "omega_squared")
PER_COORDINATE = frozenset({"momentum", "equation", "acceleration"})

# which kinds of name each step's answer may use
_KINDS = {
    "kinetic": {"parameter", "position", "velocity"},
    "potential": {"parameter", "position"},
    "lagrangian": {"parameter", "position", "velocity"},
    "momentum": {"parameter", "position", "velocity"},
    "equation": {"parameter", "position", "velocity", "acceleration"},
    "acceleration": {"parameter", "position", "velocity"},
    "hamiltonian": {"parameter", "position", "velocity"},
    "omega_squared": {"parameter", "momentum"},
}
_WHY_NOT = {
    ("potential", "velocity"): "U depends on positions only, so a velocity cannot appear in it",
    ("acceleration", "acceleration"): "the acceleration is what you solve for: write it with the coordinates, "
    "velocities, parameters and t, without any q_ddot",
    ("omega_squared", "position"): "ω² at an equilibrium is a constant: write it with the parameters "
    "(and conserved momenta p_q) only",
    ("omega_squared", "velocity"): "ω² at an equilibrium is a constant: write it with the parameters "
    "(and conserved momenta p_q) only",
    ("omega_squared", "acceleration"): "ω² at an equilibrium is a constant: write it with the parameters "
    "(and conserved momenta p_q) only",
}
_IDENTIFIER = re.compile(r"\b[A-Za-z_][A-Za-z0-9_]*")


class CheckError(ExpressionError):
    """A check request refused; ``field`` is ``step``, ``coordinate`` or ``answer``."""

    def __init__(self, message: str, field: str, part: str = "", start: int | None = None, end: int | None = None):
        super().__init__(message, part, start, end)
        self.field = field

    def __reduce__(self):
        return (type(self), (str(self), self.field, self.part, self.start, self.end))


def name_kinds(coordinates: tuple[str, ...], parameters: tuple[str, ...], momenta: tuple[str, ...]) -> dict[str, str]:
    """Every name a check may mention, with its kind."""
    kinds = {p: "parameter" for p in parameters}
    kinds.update({p: "momentum" for p in momenta})
    kinds["t"] = "position"
    for q in coordinates:
        kinds.update({q: "position", f"{q}_dot": "velocity", f"{q}_ddot": "acceleration"})
    return kinds


def allowed_names(step: str, kinds: dict[str, str]) -> list[str]:
    return sorted(name for name, kind in kinds.items() if kind in _KINDS[step])


def check_answer(text: str, step: str, kinds: dict[str, str]) -> None:
    """Refuse an answer the step cannot take, in pure Python (the parser's gates 1 and 2 plus name rules)."""
    if isinstance(text, str):
        for match in _IDENTIFIER.finditer(text[:4000]):
            kind = kinds.get(match.group())
            if kind is not None and kind not in _KINDS[step]:
                why = _WHY_NOT.get((step, kind)) or (
                    "an acceleration appears only in the equation step"
                    if kind == "acceleration"
                    else f"a {kind} cannot appear in this step"
                )
                raise CheckError(
                    f"answer: {why}: {match.group()!r} at column {match.start() + 1}",
                    "answer",
                    match.group(),
                    match.start(),
                    match.end(),
                )
    try:
        check_expression(text, allowed_names(step, kinds))
    except ExpressionError as exc:
        raise CheckError(f"answer: {exc}", "answer", exc.part, exc.start, exc.end) from None


def parse_answer(pb: Problem, text: str, kind: str | None = None) -> sp.Expr:
    """The answer in SymPy (CheckError on the ``answer`` field when it is not allowed); ``kind`` is the step
    whose names it may use (a follow-up question's), by default the problem's own."""
    kind = kind or pb.step
    check_answer(text, kind, pb.kinds)
    allowed = set(allowed_names(kind, pb.kinds))
    try:
        return real_somewhere(text, parse_expression(text, {n: s for n, s in pb.namespace.items() if n in allowed}))
    except ExpressionError as exc:
        raise CheckError(f"answer: {exc}", "answer", exc.part, exc.start, exc.end) from None

