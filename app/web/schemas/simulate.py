"""Request and response models of POST /api/scenes/{id}/simulate (and the user-system twin).

Every float is finite (JSON's NaN and Infinity, which Python's json accepts,
are a 422); the settings' ranges are ``limits.RANGES`` (app/numerics/limits.py),
the table the service's checks read too.
Ranges that depend on the system (parameter ranges, which names exist) are
checked by app.service.simulations.simulation with messages naming the field.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.numerics import limits
from app.numerics.methods import CHOICES
from app.web.schemas.common import STRICT

# "auto" and the registry's names (app/numerics/methods/__init__.py)
Method = Literal[CHOICES]
Precision = Literal["full", "display"]
Values = Annotated[
    dict[Annotated[str, Field(max_length=40)], Annotated[float, Field(ge=-limits.VALUE_MAX, le=limits.VALUE_MAX)]],
    Field(max_length=limits.MAX_NAMES),
]


def within(name: str) -> dict[str, float]:
    """A setting's range (``limits.RANGES``) as a field's bounds."""
    allowed = limits.RANGES[name]
    return {"ge": allowed.low, "le": allowed.high}


class SimulateRequest(BaseModel):
    """What to simulate; only ``initial`` is required, the rest defaults from the scene."""

    model_config = ConfigDict(
        **STRICT,
        json_schema_extra={
            "example": {
                "parameters": {"m": 1.0, "g": 9.81, "R": 1.0},
                "initial": {"theta": 2.5, "theta_dot": 0.0},
                "t_end": 20.0,
                "method": "auto",
                "rtol": 1e-8,
                "atol": 1e-10,
                "samples": 500,
            }
        },
    )

    parameters: Values = Field(default_factory=dict, description="Parameter values by name (default: the scene's).")
    initial: Values = Field(
        description="Initial coordinates and velocities by name (q and q_dot); missing ones default from the scene."
    )
    t_end: float | None = Field(None, **within("t_end"), description="End time in seconds.")
    method: Method = Field("auto", description="'auto' chooses per scene and request and says why in stats.reason.")
    rtol: float | None = Field(None, **within("rtol"), description="Relative tolerance.")
    atol: float | None = Field(None, **within("atol"), description="Absolute tolerance.")
    samples: int | None = Field(None, **within("samples"), description="Evenly spaced output times from 0 to t_end.")
    precision: Precision = Field(
        "full",
        description="'full': every float as computed; 'display': the state and constraint forces rounded to 7 "
        "significant digits (what a plot needs; fewer bytes); energy, h, conserved momenta and stats unchanged "
        "(their changes since t = 0 are plotted).",
    )


class SimulateEvent(BaseModel):
    name: str = Field(description="The scene's name for the event, e.g. 'foot of the ramp'.")
    t: float = Field(description="When it happened (s); the run's last sample is the state at that instant.")
    message: str = Field(description="What happened, in words.")


class SimulateStats(BaseModel):
    method: str
    reason: str
    path: str = Field(
        description="'compiled' (a numba step loop), 'scipy' (a scipy method asked for or chosen) or "
        "'scipy-fallback' (the server's compiled code was not ready yet, so scipy's DOP853 answered)."
    )
    steps: int
    rhs_evaluations: int
    wall_time_s: float
    error_estimate: float | None = Field(
        description="A bound on max |q - q_exact| over the samples: the difference from a second, more accurate "
        "run (or, for a fixed-step method, Richardson's estimate from half the step) times a safety factor of 2, "
        "so that the true global error does not exceed it (tested on stiff, long and chaotic runs)."
    )
    max_energy_drift: float | None
    max_hamiltonian_drift: float | None
    warnings: list[str]
    t_end_reached: float
    complete: bool
    event: SimulateEvent | None = Field(
        None, description="The terminal event that ended the run before t_end (the set-up no longer holds), or null."
    )


class BrowserPreview(BaseModel):
    rhs: str = Field(
        description="Body of a JavaScript function (t, y, k, out) writing (q_dot, q_ddot) for y = (q, q_dot) and k the "
        "parameters: printed from the engine's expressions with renamed symbols (q0, v0, k0, t), for the page's "
        "live preview"
    )
    coordinates: list[str] = Field(description="The order of the coordinates in y")
    parameters: list[str] = Field(description="The order of the parameters in k")


class Trust(BaseModel):
    """Whether the run's error estimate is small against the motion (app/service/simulations/trust.py)."""

    trusted: bool | None = Field(
        description="False when the estimated error is 5 % or more of the range of some coordinate over the run "
        "(the motion shown is not reliable); null when the run has no error estimate."
    )
    ratio: float | None = Field(description="The worst estimated error / range of motion over the coordinates.")
    coordinate: str | None = Field(description="The coordinate where that ratio is worst.")
    message: str | None = Field(description="A plain-language warning when not trusted, else null.")


class SimulateResponse(BaseModel):
    t: list[float]
    state: dict[str, list[float | None]]
    energy: list[float | None]
    hamiltonian: list[float | None]
    conserved: dict[str, list[float | None]]
    constraint_forces: dict[str, list[float | None]]
    stats: SimulateStats
    trust: Trust
    preview: BrowserPreview | None = None


class WorkPrecisionRun(BaseModel):
    method: str
    rtol: float
    error: float | None
    wall_time_s: float | None
    rhs_evaluations: int | None


class WorkPrecision(BaseModel):
    reference: str
    runs: list[WorkPrecisionRun]
