"""An answer typed with an equals sign, read as a textbook writes it.

Every textbook writes an equation of motion as lhs = rhs (θ̈ = −(g/R) sin θ), so a step whose answer is
an equation takes it: the equation ``lhs = rhs`` is read as the expression lhs − rhs, equal to zero. An
acceleration step takes ``q_ddot = rhs`` as its right-hand side, and the frequency step ``ω² = rhs`` (in the
document's letter: Ω² where ω is a parameter). Where the box already names the left-hand side (T =, U =, L =,
p =, h =) an equals sign makes no sense, and the student is told to type only the right-hand side. A refusal of what was read is placed back at the columns as typed.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from app.engine.display.names import said, said_all, unicode
from app.engine.document.notation import free_letter
from app.engine.parser.parse import Parsed
from app.engine.parser.rules import FUNCTIONS, ExpressionError, typed_function
from app.engine.parser.typed import typed
from app.engine.tutor.check_answers import CheckError, allowed_names, check_answer

# the comparisons an '=' could be part of, refused by the parser in its own words
_COMPARISONS = ("==", "<=", ">=", "!=")


def _names_then_function(typed: str, names: list[str]) -> str:
    """``typed`` as declared names followed by a function, spaced ("mgRcos" -> "m g R cos"), or "" if it is not."""
    for function in sorted(FUNCTIONS, key=len, reverse=True):
        if typed.endswith(function) and len(typed) > len(function):
            split = _as_names(typed[: -len(function)], names)
            if split:
                return " ".join([*split, function])
    return ""


def _as_names(typed: str, names: list[str]) -> list[str]:
    """``typed`` cut into declared names, the longest first at each place (``mgR`` -> m, g, R), or []."""
    if not typed:
        return []
    for name in sorted(names, key=len, reverse=True):
        if typed.startswith(name):
            rest = typed[len(name) :]
            tail = _as_names(rest, names)
            if not rest or tail:
                return [name, *tail]
    return []


def _placed(exc: CheckError, offset: int) -> CheckError:
    """A refusal of one side, at its columns in the whole text typed (the side's own column left unsaid)."""
    if not offset or exc.start is None:
        return exc
    said = re.sub(r" at column \d+", "", str(exc))
    moved = CheckError(said, exc.field, exc.part, exc.start + offset, None if exc.end is None else exc.end + offset)
    moved.readings = exc.readings
    return moved


def _side(text: str, offset: int, step: str, kinds: dict[str, str]) -> Parsed:
    try:
        return check_answer(text, step, kinds)
    except CheckError as exc:
        raise _placed(exc, offset) from None


def read_answer(
    text: str, step: str, coordinate: str | None, kinds: dict[str, str], absent: Mapping[str, str] | None = None
) -> tuple[Parsed, bool]:
    """What ``check_answer`` reads of a step's answer, and whether it was typed as an equation lhs = rhs.

    Each side is read on its own first, so a refusal quotes the student's own text at their columns.  ``absent``:
    names a student may expect that the problem has not, each with why (g where the masses stay level).
    """
    try:
        return _read(text, step, coordinate, kinds)
    except CheckError as exc:
        raise _in_words(exc, text, step, coordinate, kinds, absent or {}) from None


# the names of the steps' own quantities, which a student may type for what they stand for (L = T − U)
_QUANTITIES = frozenset({"T", "U", "V", "L"})
_KIND_WORDS = {"parameter": "a parameter", "position": "a coordinate", "velocity": "a velocity", "momentum": "a momentum"}
_MEANT = {"T": "the kinetic energy T", "U": "the potential energy U", "V": "the potential energy V", "L": "the Lagrangian L"}
_DERIVATIVE = (
    "a derivative cannot be typed here: work it out, and write the result in the coordinates, their velocities and "
    "the parameters"
)
# functions a student may type under another name
_FUNCTION_WORDS = {
    "ln": "the natural logarithm is typed log(x)",
    "diff": _DERIVATIVE,
    "derivative": _DERIVATIVE,
}
# a derivative typed as a quotient of differentials: d/dt(...), dL/dtheta_dot, dT/dx
_DIFFERENTIALS = re.compile(r"\bd([A-Za-z_]\w*)?\s*/\s*d[A-Za-z_]")


def _in_words(
    exc: CheckError, text: str, step: str, coordinate: str | None, kinds: dict[str, str], absent: Mapping[str, str]
) -> CheckError:
    """A refusal said as a tutor says it where the parser's words would not help: T − U typed in the L box, a
    derivative typed as d/dt(…) or dL/dθ̇, another acceleration on the right of an acceleration, a declared name
    typed in the other case (L for l)."""
    unknown = "unknown name" in str(exc)
    out = None
    # d/dt (…) read as a quotient (d over dt times …) is a derivative all the same, anywhere in the answer
    derivative = isinstance(text, str) and bool(_DIFFERENTIALS.search(text)) and "quotient" in str(exc)
    # a declared name typed with its letters' case changed (L for the length l): names are case-sensitive; names
    # are said as typed, as the box's own list prints them
    near = [
        n
        for n in allowed_names(step, kinds)
        if unknown and n not in (exc.part, "t") and n.lower() == str(exc.part).lower()
    ]
    if derivative:
        out = _DERIVATIVE
    elif near:
        out = (
            f"{exc.part} is not {_KIND_WORDS.get(kinds[near[0]], 'a name')} here; did you mean "
            f"{near[0]}? A capital and a small letter are different names"
        )
        if exc.part in _QUANTITIES and step not in ("kinetic", "potential"):
            out += f" (and if you meant {_MEANT[exc.part]}, write it out in the coordinates, their velocities and the parameters)"
    elif unknown and not (exc.part in _QUANTITIES or _DIFFERENTIALS.search(text if isinstance(text, str) else "")):
        # the parser's own words, as a tutor says them: the names as the page prints them
        # each name as the page prints it, with how it is typed (θ̇ (type theta_dot))
        allowed = ", ".join(said_all(allowed_names(step, kinds)))
        advice = re.search(r"; (.*)\): '", str(exc))  # the parser's advice (letters written together, e^x)
        split = advice.group(1) if advice else ""
        out = f"{exc.part} is not a name in this problem; the names you may use are {allowed} and pi"
        if exc.part in absent:
            # why the problem has no such name: g where the masses stay level
            out = f"{exc.part} is not a name in this problem: {absent[exc.part]}; the names you may use are {allowed} and pi"
        if split:
            out += f" ({split})"
    elif "only these functions may be called" in str(exc) and (apart := _names_then_function(exc.part, allowed_names(step, kinds))):
        # mgRcos(theta): the names and the function typed together read as one unknown function
        out = f"{exc.part} reads as one name: write {apart}(…), with a space or * between the names"
    elif "only these functions may be called" in str(exc) and (glued := _as_names(exc.part, allowed_names(step, kinds))):
        # mgR(1 − cos θ): declared names typed together before a bracket read as one function's name
        out = (
            f"{exc.part} reads as one name: write {' '.join(glued)} (or {'*'.join(glued)}) for the product, with a "
            "space or * between the names"
        )
    elif "only these functions may be called" in str(exc) and str(exc.part).lower() in _FUNCTION_WORDS:
        # a function a student knows under another name, or a derivative: said as a tutor says it
        out = _FUNCTION_WORDS[str(exc.part).lower()]
    elif "only these functions may be called" in str(exc):
        # a sentence, not a code allowlist: each function as a student types it (abs, never SymPy's Abs)
        functions = sorted(typed_function(f) for f in FUNCTIONS)
        bar = isinstance(text, str) and "|" in text
        out = (
            f"{exc.part} is not a function you may use here; the functions are {', '.join(functions[:-1])} and "
            f"{functions[-1]}" + ("; |x| is typed abs(x)" if bar else "")
        )
    elif exc.part in _QUANTITIES and unknown:
        out = f"{exc.part} is not a name the answer may use: write T and U out in the coordinates, their velocities and the parameters"
    elif unknown and exc.part.startswith("d") and isinstance(text, str) and _DIFFERENTIALS.search(text):
        out = _DERIVATIVE
    elif step == "acceleration" and exc.part.endswith("_ddot"):
        wanted = unicode(f"{coordinate}_ddot") if coordinate else "the acceleration"
        out = (
            f"an acceleration cannot appear on the right: solve the equations of motion for {wanted} alone, so "
            "that only the coordinates, their velocities and the parameters remain"
        )
    return exc if out is None else CheckError(f"answer: {out}", exc.field, exc.part, exc.start, exc.end)


def _name_read(text: str) -> str:
    """The one name ``text`` is as the parser reads it (θ̈, θ + U+0308, ẍ, theta'' and thetaddot are all
    theta_ddot, x_ddot), else the text stripped."""
    try:
        return typed(text).text.strip()
    except ExpressionError:
        return text.strip()


def _read(text: str, step: str, coordinate: str | None, kinds: dict[str, str]) -> tuple[Parsed, bool]:
    if not isinstance(text, str) or "=" not in text or any(c in text for c in _COMPARISONS):
        return check_answer(text, step, kinds), False
    at = text.index("=")
    if text.count("=") > 1:
        second = text.index("=", at + 1)
        raise CheckError("answer: write one '=' only, as lhs = rhs", "answer", "=", second, second + 1)
    lhs, rhs = text[:at], text[at + 1 :]
    if step == "equation":
        if not lhs.strip() or not rhs.strip():
            raise CheckError("answer: one side of '=' is empty: write the equation as lhs = rhs", "answer", "=", at, at + 1)
        _side(lhs, 0, step, kinds)
        _side(rhs, at + 1, step, kinds)
        # lhs = rhs is the equation lhs − rhs = 0
        return check_answer(f"{lhs} - ({rhs})", step, kinds), True
    if step == "acceleration":
        name = _name_read(lhs)
        wanted = f"{coordinate}_ddot" if coordinate else None
        if (wanted is not None and name == wanted) or (wanted is None and name.endswith("_ddot") and name.isidentifier()):
            if not rhs.strip():
                raise CheckError("answer: the right-hand side of '=' is empty", "answer", "=", at, at + 1)
            return _side(rhs, at + 1, step, kinds), False
        # the acceleration as the page prints it (θ̈), with how it is typed once
        raise CheckError(
            f"answer: the left of '=' must be the acceleration {said(wanted) if wanted else 'q̈'}: write "
            f"{unicode(wanted) if wanted else 'q̈'} = … or only the right-hand side",
            "answer",
            lhs,
            0,
            at,
        )
    if step == "omega_squared":
        # the box's own left side typed out, ω² = g/R (omega^2, or Ω² where ω is a parameter), as θ̈ = … is taken
        square = free_letter("frequency", kinds)[1]
        if _name_read(lhs).replace(" ", "") == _name_read(f"{square}²"):
            if not rhs.strip():
                raise CheckError("answer: the right-hand side of '=' is empty", "answer", "=", at, at + 1)
            return _side(rhs, at + 1, step, kinds), False
        raise CheckError(
            f"answer: the left of '=' must be {square}² (type {_name_read(square)}^2): write {square}² = … or only "
            "the right-hand side",
            "answer",
            lhs,
            0,
            at,
        )
    raise CheckError(
        "answer: type only the right-hand side: the box already has the left-hand side and its '='",
        "answer",
        "=",
        at,
        at + 1,
    )
