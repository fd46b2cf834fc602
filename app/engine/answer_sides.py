"""An answer typed with an equals sign, read as a textbook writes it.

Every textbook writes an equation of motion as lhs = rhs (θ̈ = −(g/R) sin θ), so a step whose answer is
an equation takes it: the equation ``lhs = rhs`` is read as the expression lhs − rhs, equal to zero. An
acceleration step takes ``q_ddot = rhs`` as its right-hand side. Where the box already names the
left-hand side (T =, U =, L =, p =, h =, ω² =) an equals sign makes no sense, and the student is told to
type only the right-hand side. A refusal of what was read is placed back at the columns as typed.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.engine.check_answers import CheckError

# the comparisons an '=' could be part of, refused by the parser in its own words
_COMPARISONS = ("==", "<=", ">=", "!=")


@dataclass(frozen=True)
class Sides:
    """What to read for an answer typed as text: ``text``, and how its columns map back to the typed ones.

    A column at or after ``boundary`` of ``text`` stood ``shift`` columns earlier in what was typed;
    ``equation`` is true when the student typed an equation lhs = rhs (its last term is the right side).
    """

    text: str
    boundary: int = 0
    shift: int = 0
    equation: bool = False

    def placed(self, exc: CheckError) -> CheckError:
        """A refusal of ``text`` with its columns as the student typed them."""
        if not self.shift or exc.start is None:
            return exc

        def back(column: int) -> int:
            return column - self.shift if column >= self.boundary else column

        moved = CheckError(str(exc), exc.field, exc.part, back(exc.start), None if exc.end is None else back(exc.end))
        moved.readings = exc.readings
        return moved


def sides(text: str, step: str, coordinate: str | None) -> Sides:
    """The text to read for a step's answer: unchanged without '=', else as the step takes an equation."""
    if not isinstance(text, str) or "=" not in text or any(c in text for c in _COMPARISONS):
        return Sides(text)
    at = text.index("=")
    if text.count("=") > 1:
        second = text.index("=", at + 1)
        raise CheckError("answer: write one '=' only, as lhs = rhs", "answer", "=", second, second + 1)
    lhs, rhs = text[:at], text[at + 1 :]
    if step == "equation":
        if not lhs.strip() or not rhs.strip():
            raise CheckError("answer: one side of '=' is empty: write the equation as lhs = rhs", "answer", "=", at, at + 1)
        # lhs = rhs is the equation lhs − rhs = 0; the right side's columns move by the 3 of ' - (' for '='
        return Sides(f"{lhs} - ({rhs})", boundary=at + 4, shift=3, equation=True)
    if step == "acceleration":
        name = lhs.strip()
        wanted = f"{coordinate}_ddot" if coordinate else None
        if (wanted is not None and name == wanted) or (wanted is None and name.endswith("_ddot") and name.isidentifier()):
            if not rhs.strip():
                raise CheckError("answer: the right-hand side of '=' is empty", "answer", "=", at, at + 1)
            return Sides(rhs, boundary=0, shift=-(at + 1))
        shown = wanted or "q_ddot"
        raise CheckError(
            f"answer: the left of '=' must be the acceleration {shown}: type {shown} = … or only the right-hand side",
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
