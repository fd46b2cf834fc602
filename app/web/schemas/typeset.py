"""Request and response models of POST /api/typeset: a student's answer typeset as it is typed.

Shapes only: the text's grammar and the names a step allows are the checker's (app/service/tutor/typesetting.py).
"""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field, model_validator

from app.service.users.user_checks import MAX_COORDINATES, MAX_PARAMETERS
from app.web.schemas.check import Step
from app.web.schemas.user import STRICT, Expression, Name


class TypesetRequest(BaseModel):
    """The text typed so far, with what the checker needs to read it: the step, and the scene or the names."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={"example": {"text": "m*R**2*theta_dot**2/2", "step": "kinetic", "scene": "simple-pendulum"}},
    )

    text: Expression
    step: Step = Field(description="The step the answer is for (its name rules apply), as for POST /api/check.")
    scene: str | None = Field(None, max_length=80, description="The scene whose names the answer may use.")
    coordinate: Name | None = Field(
        None, description="For an acceleration: the coordinate whose acceleration the box asks for (θ̈ = … is read)."
    )
    coordinates: list[Name] | None = Field(
        None, max_length=MAX_COORDINATES, description="For a declared system (no `scene`): its coordinates."
    )
    parameters: list[Name] | None = Field(
        None, max_length=MAX_PARAMETERS, description="For a declared system (no `scene`): its parameters' names."
    )

    @model_validator(mode="after")
    def _one_context(self) -> TypesetRequest:
        if (self.scene is None) == (self.coordinates is None):
            raise ValueError("give either scene, or coordinates (and parameters) of a declared system")
        return self

    def names(self) -> tuple[tuple[str, ...], tuple[str, ...]]:
        return tuple(self.coordinates or ()), tuple(self.parameters or ())


class TypesetResponse(BaseModel):
    latex: str = Field(
        description="The answer as the checker reads it, printed as it was typed (its structure kept, never evaluated)."
    )
    equation: bool = Field(
        False, description="True when the text is an equation typed lhs = rhs (an equation step): `latex` is all of it."
    )
