"""Pydantic models for the API's documented shapes."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from app.engine.document.model import ParameterInfo
from app.service.runtime.fairness import COOKIE

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


class ValidationIssue(BaseModel):
    loc: list[str]
    msg: str
    type: str


class Problem(BaseModel):
    """Every error the API sends: an RFC 9457 problem (media type application/problem+json), with the fields
    that locate what was refused, or say when to try again (app/web/api/errors.py)."""

    model_config = ConfigDict(extra="allow")
    type: str = Field(description="`about:blank`: the status says what kind of problem it is.")
    title: str = Field(description="The status's phrase (Unprocessable Content, Too Many Requests, …).")
    status: int = Field(description="The HTTP status, repeated.")
    detail: str = Field(description="What was wrong, and what is allowed.")
    part: str | None = Field(None, description="The offending piece of the input.")
    loc: list[str] | None = Field(None, description="Path of the offending field, e.g. body.particles.0.mass.")
    start: int | None = Field(None, description="Offset of the offending part in that field's text.")
    end: int | None = None
    readings: list[str] | None = Field(
        None, description="An expression that reads two ways (`1/2m`): both readings, to write the one meant."
    )
    kind: str | None = Field(None, description="timeout or memory when the work exceeded a limit.")
    errors: list[ValidationIssue] | None = Field(None, description="Shape errors (never echoing the input).")
    retry_after: int | None = Field(None, description="Seconds to wait (429, 503); also in the Retry-After header.")


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
