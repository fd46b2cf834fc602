"""Request and response models of the step checker (POST /api/scenes/{id}/check, POST /api/check)
and of the practice exercises (GET /api/scenes/{id}/practice, POST /api/practice).

Shapes only: the step names come from the engine (``app.engine.tutor.check.STEPS``);
whether a step applies to a system, the coordinate and the answer's text are
checked by the service with located messages.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from app.engine.tutor.check import STEPS
from app.web.schemas.user import STRICT, Expression, ExprPair, Name, SystemSpec

Step = Literal[STEPS]  # type: ignore[valid-type]


class CheckRequest(BaseModel):
    """A student's answer for one step."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={
            "example": {"step": "equation", "coordinate": "theta", "answer": "theta_ddot + g/R*sin(theta)"}
        },
    )

    step: Step = Field(
        description="position (one Cartesian component of one body, in the generalised coordinates), kinetic (T), "
        "potential (U), lagrangian (L), momentum (p of a coordinate), equation (the "
        "Euler–Lagrange equation of a coordinate as an expression equal to zero, q_ddot for accelerations), "
        "acceleration (q_ddot of a coordinate), hamiltonian (h in q and q_dot), omega_squared (ω² of small "
        "oscillations, where the system has a stable equilibrium)."
    )
    coordinate: Name | None = Field(
        None,
        description="The coordinate, for momentum, equation and acceleration; for position, the component: x, y or z "
        "of a single body, x1, z2, … (axis and body's number) where there are several.",
    )
    answer: Expression
    follow_up: str | None = Field(
        None,
        max_length=200,
        description="To answer a named mistake's follow-up question: the `key` of `follow_up` from the verdict "
        "(with the same step and coordinate); `answer` is then judged against that question's answer.",
    )


class SystemCheckRequest(CheckRequest):
    """A student's answer for one step of a system declared as for POST /api/derive."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={
            "example": {
                "system": {
                    "coordinates": ["x"],
                    "parameters": ["m", "k"],
                    "kinetic": "m*x_dot**2/2",
                    "potential": "k*x**2/2",
                },
                "step": "acceleration",
                "coordinate": "x",
                "answer": "-k*x/m",
            }
        },
    )

    system: SystemSpec


class Mistake(BaseModel):
    key: str = Field(
        description="Stable machine key for records: `<step>.<family>[.<detail>…]` for a generated mistake "
        "(`kinetic.velocity_part.ball.phi`, `equation.chain_rule.theta2`), a rule's name otherwise "
        "(`missing_half`); two mistakes at once are joined by `+`."
    )
    family: str = Field(description="The kind of mistake (`velocity_part`, `natural_length`, `chain_rule`, …).")
    name: str = Field(description="What went wrong, in the system's words (display text, Unicode mathematics).")
    latex: str = Field(
        description="The student's own piece the name speaks of, typeset and labelled (for units: the sum whose units "
        "disagree); empty otherwise. Never the correct piece (that is in `reveal`)."
    )
    where: str = Field(description="Where in the set-up that piece comes from.")
    approximation: bool = Field(description="True when it is an approximation (small angles), not a slip.")
    count: int = Field(description="How many mistakes at once (1 or 2).")


class Partial(BaseModel):
    message: str
    agree: list[str] = Field(description="The parts that agree with the engine's (empty after a named mistake).")
    differ: list[str] = Field(description="The parts that do not.")


class FollowUp(BaseModel):
    key: str = Field(description="Send it back as the request's `follow_up` with the answer to the question.")
    question: str
    names: list[str] = Field(description="The names the answer may use.")
    names_said: list[str] = Field(
        default_factory=list, description="The same names as the page prints them, each with how it is typed once."
    )
    kind: str = Field(
        "", description="The step whose names the answer may use, and as whose answer it is typeset (`/api/typeset`)."
    )


class CorrectPart(BaseModel):
    what: str = Field(
        description='The part in words, after "the correct": "denominator", "numerator", "stretch", "moment of inertia '
        'about the end".'
    )
    latex: str = Field(description="The correct part, typeset.")
    text: str = Field(description="The same in plain text with Unicode mathematics (for a screen reader).")
    note: str = Field("", description='What holds it, in words ("up to a constant factor"); empty otherwise.')


class Reveal(BaseModel):
    difference: ExprPair = Field(
        description="answer − the correct one (less an accepted additive constant; for an equation, against the "
        "correct one scaled to the answer's coefficient of the acceleration)."
    )
    piece: str = Field(
        description='The correct piece the mistake is in, typeset and labelled ("what your T leaves out: …", '
        '"the correct term: …"), or empty where the difference says it.'
    )


class Formula(BaseModel):
    text: str = Field(description="The formula as the words print it (Unicode), e.g. `I = M l²`.")
    latex: str = Field(description="The same formula in LaTeX, in the same order, for a page to typeset it there.")


class CheckResponse(BaseModel):
    verdict: Literal["correct", "equivalent", "incorrect"]
    message: str = Field(
        description="Plain words: what the verdict means, and for an equivalent answer how it differs."
    )
    hint: str | None = Field(None, description="For an incorrect answer: the likely mistake, or the step's rule.")
    mistake: Mistake | None = Field(
        None,
        description="For an incorrect answer that matches a mistake generated from this system's derivation (or a "
        "rule every system invites): which one. None when no known mistake matches.",
    )
    partial: Partial | None = Field(
        None,
        description="For an incorrect answer: what is right. After a named mistake, that everything else is; "
        "otherwise which parts (the terms of each product of velocities and accelerations) agree.",
    )
    follow_up: FollowUp | None = Field(
        None, description="A short question after a named mistake, answerable through this endpoint."
    )
    correct_part: CorrectPart | None = Field(
        None,
        description="For an incorrect answer whose named mistake points at one part (a solved answer's denominator "
        "or numerator, a stretch, a rod's moment of inertia): that part as it should be, for a page to show closed, "
        "opened only when the student asks for it. The mistake's name says the place and the kind of slip without it.",
    )
    reveal: Reveal | None = Field(
        None,
        description="For an incorrect answer: what follows the correct answer, for a page to show only with the "
        'step itself ("Show this step"), never beside the verdict: the other fields name the mistake without it.',
    )
    formulas: list[Formula] = Field(
        default_factory=list,
        description="The formulas the words above print (message, hint, the mistake's name and where, partial, the "
        "follow-up question), longest first, each with its LaTeX: a page sets each as a formula where it stands.",
    )


class ExerciseAnswer(ExprPair):
    notes: list[str] | None = Field(
        None,
        description="For ω²: sentences under the formula, whether the equilibrium asked about is stable (or "
        "while what holds) and the other equilibria, where each exists and whether it is stable.",
    )


class Exercise(BaseModel):
    step: str
    coordinate: str | None
    title: str
    lhs: str = Field(description="LaTeX of what the answer stands for (T, p_θ, θ̈; 0 for an equation).")
    names: list[str] = Field(description="The names the answer may use.")
    names_said: list[str] = Field(
        description="The same names as the page prints them, each followed once by how it is typed where the two "
        "differ: θ̇ (type theta_dot)."
    )
    acceleration: str | None = Field(None, description="For an acceleration step: the acceleration as printed (θ̈).")
    answer: ExerciseAnswer = Field(description="The engine's step (to reveal on request).")
    note: str | None = Field(
        None, description="For a position: the axes and origin it is judged against, in a sentence for the student."
    )


class Exercises(BaseModel):
    model_config = ConfigDict(extra="allow")
    exercises: list[Exercise]
    symbols: dict[str, str] = Field(description="How each name prints in LaTeX.")
    rules: dict[str, str] = Field(description="Each step's rule in a sentence.")
