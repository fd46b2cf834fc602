"""Request model of POST /api/export and the format vocabulary of both export routes."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from app.limits import DEFAULT_T_END
from app.numerics import limits
from app.service.export.source import FORMATS
from app.web.schemas.simulate import Values
from app.web.schemas.user import STRICT, SystemSpec

ExportFormat = Literal[tuple(FORMATS)]  # type: ignore[valid-type]
FORMAT_HELP = "; ".join(f"{fmt}: {what}" for fmt, (_, what) in FORMATS.items())


class ExportRequest(BaseModel):
    """A system as for POST /api/derive, the format, and optionally the start and length of its simulation."""

    model_config = STRICT

    system: SystemSpec
    format: ExportFormat = Field(description=FORMAT_HELP)
    initial: Values = Field(
        default_factory=dict, description="Initial q and q_dot by name for the exported simulation (missing ones: 0)."
    )
    t_end: float | None = Field(
        None, gt=0, le=limits.T_END_MAX, description=f"End time of the exported simulation (default {DEFAULT_T_END:g} s)."
    )
