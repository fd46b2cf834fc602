"""Request and response models of the step checker (POST /api/scenes/{id}/check, POST /api/check)
and of the practice exercises (GET /api/scenes/{id}/practice, POST /api/practice).

Shapes only: the step names come from the engine (``app.engine.check.STEPS``);
whether a step applies to a system, the coordinate and the answer's text are
checked by the service with located messages.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from app.engine.check import STEPS
from app.web.schemas_user import STRICT, Expression, ExprPair, Name, SystemSpec

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
        description="kinetic (T), potential (U), lagrangian (L), momentum (p of a coordinate), equation (the "
        "Euler–Lagrange equation of a coordinate as an expression equal to zero, q_ddot for accelerations), "
        "acceleration (q_ddot of a coordinate), hamiltonian (h in q and q_dot), omega_squared (ω² of small "
        "oscillations, where the system has a stable equilibrium)."
    )
    coordinate: Name | None = Field(None, description="The coordinate, for momentum, equation and acceleration.")
    answer: Expression


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


class CheckResponse(BaseModel):
    verdict: Literal["correct", "equivalent", "incorrect"]
    message: str = Field(
        description="Plain words: what the verdict means, and for an equivalent answer how it differs."
    )
    difference: ExprPair | None = Field(
        None,
        description="For an incorrect answer: answer − the engine's (less an accepted additive constant; for an "
        "equation, against the engine's scaled to the answer's coefficient of the acceleration).",
    )
    hint: str | None = Field(None, description="For an incorrect answer: the likely mistake, or the step's rule.")


class Exercise(BaseModel):
    step: str
    coordinate: str | None
    title: str
    lhs: str = Field(description="LaTeX of what the answer stands for (T, p_θ, θ̈; 0 for an equation).")
    names: list[str] = Field(description="The names the answer may use.")
    answer: ExprPair = Field(description="The engine's step (to reveal on request).")


class Exercises(BaseModel):
    model_config = ConfigDict(extra="allow")
    exercises: list[Exercise]
    symbols: dict[str, str] = Field(description="How each name prints in LaTeX.")
    rules: dict[str, str] = Field(description="Each step's rule in a sentence.")
