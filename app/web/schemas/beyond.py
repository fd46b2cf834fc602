"""Request and response models of the Poincaré-section and normal-mode routes (scenes and user systems)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, create_model

from app.numerics import limits
from app.service.simulations.poincare import COUNT_MAX, DEFAULT_COUNT, DEFAULT_T_END, T_END_MAX
from app.web.schemas.common import STRICT
from app.web.schemas.simulate import Values
from app.web.schemas.user import SystemSpec


class PoincareRequest(BaseModel):
    """Which section: the energy (or the state whose h sets it), the plane, how many orbits, how long."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={"example": {"initial": {"theta1": 2.0, "theta2": 2.0}, "count": 6, "t_end": 200.0}},
    )

    parameters: Values = Field(default_factory=dict, description="Parameter values by name (default: the scene's).")
    initial: Values = Field(
        default_factory=dict, description="A state whose h sets the energy (missing names default from the scene)."
    )
    energy: float | None = Field(
        None,
        ge=-limits.VALUE_MAX,
        le=limits.VALUE_MAX,
        description="The energy surface h = energy (overrides initial).",
    )
    coordinate: str | None = Field(
        None, max_length=40, description="The coordinate the plane cuts (default: the second)."
    )
    value: float = Field(0.0, ge=-limits.VALUE_MAX, le=limits.VALUE_MAX, description="The plane coordinate = value.")
    direction: Literal[1, -1] = Field(1, description="1: crossings upward; -1: downward.")
    count: int = Field(DEFAULT_COUNT, ge=1, le=COUNT_MAX, description="Orbits, started evenly across the plane.")
    t_end: float = Field(DEFAULT_T_END, gt=0, le=T_END_MAX, description="Simulated seconds per orbit.")


class PoincareOrbit(BaseModel):
    initial: dict[str, float]
    t: list[float]
    q: list[float]
    q_dot: list[float]
    p: list[float]
    energy_drift: float
    complete: bool


class PoincareResponse(BaseModel):
    coordinate: str
    value: float
    direction: int
    energy: float
    axes: dict[str, str] = Field(description="q, q_dot and p: the names of the section's axes.")
    orbits: list[PoincareOrbit]
    stats: dict[str, Any]


class ModesRequest(BaseModel):
    """The parameter values the modes are wanted at (the rest at the scene's defaults)."""

    model_config = ConfigDict(**STRICT, json_schema_extra={"example": {"parameters": {"kappa": 0.1}}})

    parameters: Values = Field(default_factory=dict, description="Parameter values by name (default: the scene's).")


class MeasuredMode(BaseModel):
    omega_squared: float
    shape: dict[str, float] = Field(description="The mode's shape, by coordinate, its largest component 1.")
    predicted: float | None = Field(description="√ω² where ω² > 0.")
    measured: float | None = Field(description="ω from a small-amplitude run started along the mode.")
    relative_difference: float | None
    amplitude: float


class MeasuredModes(BaseModel):
    equilibrium: dict[str, float]
    kind: str
    parameters: dict[str, float] = Field(description="The parameter values these modes were computed at.")
    at_defaults: bool = Field(
        False, description="Found only numerically at the default parameters, so it does not follow other values."
    )
    modes: list[MeasuredMode]


def _poincare_fields() -> dict[str, Any]:
    return {n: (f.annotation, f) for n, f in PoincareRequest.model_fields.items() if n != "parameters"}


UserPoincareRequest = create_model(
    "UserPoincareRequest",
    __base__=SystemSpec,
    __doc__="A system as for POST /api/derive (parameter values from its `parameters`), plus which section.",
    **_poincare_fields(),
)


def poincare_options(body: BaseModel) -> dict[str, Any]:
    """The section's options from a (scene or user) request."""
    return body.model_dump(include=set(PoincareRequest.model_fields))
