"""Request and response models of POST /api/scenes/{id}/action and POST /api/action.

The ranges that depend on the system (which coordinate, the longest t_end, how many ε) are checked by
app.service.simulations.action with messages naming the field and the limit, for scenes and user systems alike.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from app.numerics import limits
from app.service.simulations.action import EPSILONS_MAX, K_MAX, STEPS_DEFAULT, STEPS_MAX, T_SPAN
from app.web.schemas.common import STRICT
from app.web.schemas.simulate import Values
from app.web.schemas.user import SystemSpec


class ActionRequest(BaseModel):
    """Which varied paths: the start and length of the true path, the coordinate varied, the shape, the ε's."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={
            "example": {
                "initial": {"theta": 1.0, "theta_dot": 0.0},
                "t_end": 0.8,
                "coordinate": "theta",
                "shape": "sine",
                "k": 1,
                "epsilons": [-0.2, -0.1, 0.0, 0.1, 0.2],
            }
        },
    )

    parameters: Values = Field(default_factory=dict, description="Parameter values by name (default: the system's).")
    initial: Values = Field(
        default_factory=dict, description="The true path's initial q and q_dot by name (missing: the scene's, or 0)."
    )
    t_end: float = Field(
        ge=-limits.VALUE_MAX,
        le=limits.VALUE_MAX,
        description=f"T: the paths run from 0 to T; positive, at most {T_SPAN} times the scene's own run.",
    )
    coordinate: str | None = Field(None, max_length=40, description="The coordinate varied (default: the first).")
    shape: str = Field("sine", max_length=40, description="The variation's shape: 'sine', η(t) = sin(kπt/T).")
    k: int = Field(1, description=f"The shape's number of half waves, 1 to {K_MAX}.")
    epsilons: list[float] = Field(
        default_factory=list, description=f"The amplitudes ε of the varied paths q + ε η (at most {EPSILONS_MAX})."
    )


class UserActionRequest(ActionRequest):
    """A system as for POST /api/derive, under ``system`` (parameter values from its declaration unless given)."""

    system: SystemSpec


class ActionPath(BaseModel):
    t: list[float]
    q: list[float | None]
    L: list[float | None]
    method: str


class ActionResponse(BaseModel):
    epsilons: list[float]
    action: list[float | None] = Field(description="S(ε) = ∫ L dt along q + ε η, one per ε (null where undefined).")
    true: float = Field(description="S(0): the action of the true path.")
    first_variation: float = Field(description="dS/dε at ε = 0 (zero on the true path of a system without forces Q).")
    second_variation: float = Field(description="d²S/dε² at ε = 0, from the Jacobi (second-variation) operator.")
    kind: str = Field(description="minimum, saddle or maximum: the second variation on the shapes k = 1 … K.")
    conjugate_time: float | None = Field(description="The first t* > 0 where the Jacobi fields from t = 0 vanish.")
    varied_conjugate_time: float | None = Field(
        description="The first kinetic focus of the variations of ``coordinate`` alone (the other coordinates kept on "
        "the true path): t* or later, null before t_end."
    )
    error_estimate: float = Field(description="Estimated absolute error of each S (quadrature and path).")
    coordinate: str
    shape: str
    k: int
    t_end: float
    shapes_checked: int
    eigenvalues: list[float]
    path: ActionPath
    preview: dict[str, Any]
    warnings: list[str]


class RelaxRequest(BaseModel):
    """Two fixed ends and a trial path between them; the ends default to the true path's from ``initial``."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={"example": {"t_end": 0.9, "start": {"theta": 1.0}, "end": {"theta": -0.7}, "steps": 200}},
    )

    parameters: Values = Field(default_factory=dict, description="Parameter values by name (default: the system's).")
    initial: Values = Field(default_factory=dict, description="A start whose true path sets the ends not given.")
    t_end: float = Field(ge=-limits.VALUE_MAX, le=limits.VALUE_MAX, description="T: the path runs from 0 to T.")
    start: Values | None = Field(None, description="q(0) by name (default: the true path's).")
    end: Values | None = Field(None, description="q(T) by name (default: the true path's).")
    trial: dict[str, list[float]] | None = Field(
        None, max_length=8, description="The trial path: for some coordinates, steps + 1 values at even times."
    )
    steps: int = Field(STEPS_DEFAULT, description=f"Steps of the discrete path, 4 to {STEPS_MAX}.")


class UserRelaxRequest(RelaxRequest):
    """A system as for POST /api/derive, under ``system``."""

    system: SystemSpec


def relax_options(body: BaseModel) -> dict[str, Any]:
    return body.model_dump(include=set(RelaxRequest.model_fields))


def action_options(body: BaseModel) -> dict[str, Any]:
    """The service's options from a (scene or user) request."""
    return body.model_dump(include=set(ActionRequest.model_fields))
