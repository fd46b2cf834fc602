"""A student's answer to a step (app/engine/tutor/check.py): the names it may use, and its reading.

Each step's answer may name some kinds of name only (U no velocity, an acceleration only in the equation
step, ω² only the parameters and conserved momenta); ``check_answer`` refuses any other in pure Python,
with the reason, before the parser's first two gates, so a web process can refuse bad text without SymPy;
what it read (``app.engine.parser.parse.Parsed``) goes to the worker, where ``parse_answer`` builds it in SymPy
without reading the text again (docs/parsing.md).
"""

from __future__ import annotations

import re
from typing import Protocol

import sympy as sp

from app.engine.parser.parse import MAX_LENGTH, ExpressionError, Parsed, build, narrowed, read, typed, typed_terms
from app.engine.parser.reality import real_somewhere


class Asked(Protocol):
    """What reading an answer needs of the problem it answers (app/engine/tutor/check_problem.py's ``Problem``): the
    step, the kind of each name it may use, and the SymPy symbol of each name."""

    @property
    def step(self) -> str: ...

    @property
    def kinds(self) -> dict[str, str]: ...

    @property
    def namespace(self) -> dict[str, sp.Symbol]: ...


STEPS = ("position", "kinetic", "potential", "lagrangian", "momentum", "equation", "acceleration", "hamiltonian", "omega_squared")
PER_COORDINATE = frozenset({"momentum", "equation", "acceleration"})
# how an answer may differ from the truth and still be physically the same
# (a position from another origin is the figure's plus a constant, as another zero of U is)
RELATIONS = {"position": "constant", "potential": "constant", "lagrangian": "constant", "hamiltonian": "constant", "equation": "factor"}
# the steps answered per Cartesian component of a body (x, z, or x1, z2 … numbered by body), in the same field
PER_COMPONENT = frozenset({"position"})
# the steps whose answer names which one it is (a coordinate or a component): one record per name
KEYED = PER_COORDINATE | PER_COMPONENT

# which kinds of name each step's answer may use
_KINDS = {
    "position": {"parameter", "position"},
    "kinetic": {"parameter", "position", "velocity"},
    "potential": {"parameter", "position"},
    "lagrangian": {"parameter", "position", "velocity"},
    "momentum": {"parameter", "position", "velocity"},
    "equation": {"parameter", "position", "velocity", "acceleration"},
    "acceleration": {"parameter", "position", "velocity"},
    "hamiltonian": {"parameter", "position", "velocity"},
    # (a coordinate is read, and an ω² that still depends on it is judged: evaluated at the equilibrium)
    "omega_squared": {"parameter", "momentum", "position"},
}
# why an ω² may hold no velocity, acceleration or time
_OMEGA_CONSTANT = "ω² at an equilibrium is a constant: write it with the parameters (and any conserved momentum) only"
_WHY_NOT = {
    ("position", "velocity"): "a position depends on the coordinates (and t), not on the velocities",
    ("potential", "velocity"): "U depends on positions only, so a velocity cannot appear in it",
    ("acceleration", "acceleration"): "the acceleration is what you solve for: write it with the coordinates, "
    "velocities, parameters and t, without any acceleration q̈",
    ("omega_squared", "velocity"): _OMEGA_CONSTANT,
    ("omega_squared", "acceleration"): _OMEGA_CONSTANT,
}
_IDENTIFIER = re.compile(r"\b[A-Za-z_][A-Za-z0-9_]*")
# a name of an allowed kind that a step still refuses, with why: an ω² may be typed with the coordinate still in
# it (judged: it was not evaluated at the equilibrium), never with the time
_NOT_HERE = {
    ("t", "omega_squared"): _OMEGA_CONSTANT,
}


class CheckError(ExpressionError):
    """A check request refused; ``field`` is ``step``, ``coordinate`` or ``answer``."""

    def __init__(self, message: str, field: str, part: str = "", start: int | None = None, end: int | None = None):
        super().__init__(message, part, start, end)
        self.field = field

    def __reduce__(self):
        return (_checkerror, (str(self), self.field, self.part, self.start, self.end, self.readings))


def _checkerror(message: str, field: str, part: str, start: int | None, end: int | None, readings: tuple) -> CheckError:
    error = CheckError(message, field, part, start, end)
    error.readings = readings
    return error


def name_kinds(coordinates: tuple[str, ...], parameters: tuple[str, ...], momenta: tuple[str, ...]) -> dict[str, str]:
    """Every name a check may mention, with its kind."""
    kinds = {p: "parameter" for p in parameters}
    kinds.update({p: "momentum" for p in momenta})
    kinds["t"] = "position"
    for q in coordinates:
        kinds.update({q: "position", f"{q}_dot": "velocity", f"{q}_ddot": "acceleration"})
    return kinds


def allowed_names(step: str, kinds: dict[str, str]) -> list[str]:
    return sorted(name for name, kind in kinds.items() if kind in _KINDS[step] and (name, step) not in _NOT_HERE)


# the kinds a step reads only to name a slip, never offered to the student (an ω² with θ still in it)
_READ_NOT_OFFERED = {"omega_squared": frozenset({"position"})}


def offered_names(step: str, kinds: dict[str, str]) -> list[str]:
    """The names a step tells the student they may use: those it reads, less those read only to name a slip."""
    hidden = _READ_NOT_OFFERED.get(step, frozenset())
    return [name for name in allowed_names(step, kinds) if kinds[name] not in hidden]


def answer_error(exc: ExpressionError) -> CheckError:
    """The parser's refusal of an answer, on the ``answer`` field, word for word (with its two readings, when
    the text could be read two ways)."""
    error = CheckError(f"answer: {exc}", "answer", exc.part, exc.start, exc.end)
    error.readings = exc.readings
    return error


def check_answer(text: str, step: str, kinds: dict[str, str]) -> Parsed:
    """Read an answer the step can take, in pure Python (the step's name rules, then the parser's gates 1 and
    2): what was read, for a worker to build without reading the text again; else a CheckError."""
    if isinstance(text, str) and len(text) <= MAX_LENGTH:
        try:
            # the names as the parser reads them (θ' is theta_dot), at the columns they were typed
            written = typed(text)
        except ExpressionError as exc:
            raise answer_error(exc) from None
        for match in _IDENTIFIER.finditer(written.text):
            kind = kinds.get(match.group())
            if kind is not None and (kind not in _KINDS[step] or (match.group(), step) in _NOT_HERE):
                why = _NOT_HERE.get((match.group(), step)) or _WHY_NOT.get((step, kind)) or (
                    "an acceleration appears only in the equation step"
                    if kind == "acceleration"
                    else f"a {kind} cannot appear in this step"
                )
                start, end = written.span(match.start(), match.end())
                raise CheckError(
                    f"answer: {why}: {written.given[start:end]!r} at column {start + 1}", "answer", written.given[start:end], start, end
                )
    try:
        return read(text, allowed_names(step, kinds))
    except ExpressionError as exc:
        raise answer_error(exc) from None


def parse_answer(pb: Asked, answer: Parsed | str, kind: str | None = None) -> sp.Expr:
    """The answer in SymPy (CheckError on the ``answer`` field when it is not allowed); ``kind`` is the step
    whose names it may use (a follow-up question's), by default the problem's own.

    ``answer`` is what ``check_answer`` read in the web process, built here without reading the text again;
    or the text itself, read here, when the web process could not know which names it may use (the answer
    to a follow-up question on a declared system, whose mistakes only the derivation tells).

    A declared system's answer is read in the web process before the system is derived, with a momentum
    ``p_q`` for every coordinate (any may turn out conserved), where the problem knows the conserved ones
    only; every other name has the same kind in both.  So the step's name rules refuse nothing more here,
    and the reading is held to the problem's own names by ``narrowed``: the answer the reading against them
    would give, or the same refusal (an ω² naming the momentum of a coordinate that is not cyclic).
    """
    kind = kind or pb.step
    parsed = check_answer(answer, kind, pb.kinds) if isinstance(answer, str) else answer
    try:
        parsed = narrowed(parsed, allowed_names(kind, pb.kinds))
        return real_somewhere(parsed.text, build(parsed, pb.namespace))
    except ExpressionError as exc:
        raise answer_error(exc) from None


MAX_PAIRED = 12  # of an answer's typed terms, tried in pairs for two that cancel


def cancelling_terms(pb: Asked, answer: Parsed | str) -> tuple[sp.Expr, sp.Expr] | None:
    """Two terms of the answer as typed that cancel (− m g sin α and + m g sin α), which SymPy has merged away
    when it built the answer whole; None where there are none (or more terms than are tried)."""
    try:
        parsed = check_answer(answer, pb.step, pb.kinds) if isinstance(answer, str) else answer
        terms = typed_terms(narrowed(parsed, allowed_names(pb.step, pb.kinds)), pb.namespace)
    except (CheckError, ExpressionError):
        return None
    terms = [t for t in terms if t != 0][:MAX_PAIRED]
    for i, a in enumerate(terms):
        for b in terms[i + 1 :]:
            if sp.expand(a + b) == 0:
                return a, b
    return None
