"""Pydantic models for the API's documented shapes."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from app.service.fairness import COOKIE

# The session cookie the server issues for fair sharing; any other value (tampered, expired,
# not ASCII) is ignored and a fresh session is issued with the answer.
SESSION_COOKIE: dict[str, Any] = {
    "name": COOKIE,
    "in": "cookie",
    "required": False,
    "description": "Your session (issued by the server; a missing or malformed one gets a fresh session).",
    "schema": {"type": "string"},
}


# A request model refuses fields it does not know, and NaN and Infinity (JSON has neither; Python's json reads them).
STRICT = ConfigDict(extra="forbid", allow_inf_nan=False)


class ErrorResponse(BaseModel):
    detail: str


class ParameterInfo(BaseModel):
    default: float
    unit: str
    min: float | None
    max: float | None
    description: str


class SceneSummary(BaseModel):
    model_config = ConfigDict(
        json_schema_extra={
            "example": {
                "id": "simple-pendulum",
                "title": "Simple pendulum",
                "section": "4.3",
                "summary": "...",
                "coordinates": ["theta"],
                "parameters": {"m": {"default": 1.0, "unit": "kg", "min": 0.01, "max": 100.0, "description": "mass"}},
                "initial": {"theta": 1.0, "theta_dot": 0.0},
                "t_end": 10.0,
                "panels": ["effective-potential", "small-oscillations"],
            }
        }
    )

    id: str
    title: str
    section: str
    summary: str
    coordinates: list[str]
    parameters: dict[str, ParameterInfo]
    initial: dict[str, float]
    t_end: float
    panels: list[str] = Field(
        description="The optional panels the scene asks for (app/viz/panels.py); its page also shows every panel "
        "whose availability rule holds for the derivation."
    )
    beyond_chapter: bool = False
