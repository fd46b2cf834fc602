"""Bounds on a simulation request: what is accepted, and how much work one run may do.

The web schema and the service read these numbers, so the API's documented
ranges and the checks inside the numerics are the same numbers: a request's
settings and their ranges are ``RANGES``, the schema's bounds and the service's
checks alike.
"""

from __future__ import annotations

from dataclasses import dataclass

T_END_MIN = 1.0e-9  # seconds of simulated time
T_END_MAX = 1.0e5
SAMPLES_MIN = 2
SAMPLES_MAX = 20_000
SAMPLES_DEFAULT = 1_000
RTOL_MIN = 1.0e-12
RTOL_MAX = 1.0e-2
RTOL_DEFAULT = 1.0e-8
RTOL_MENU = (1.0e-3, 1.0e-4, 1.0e-6, 1.0e-8, 1.0e-10, 1.0e-12)  # what a page offers, loose to tight
ATOL_MIN = 1.0e-15
ATOL_MAX = 1.0
ATOL_DEFAULT = 1.0e-10
VALUE_MAX = 1.0e12  # |parameter| and |initial value| above this are refused
MAX_NAMES = 64  # entries in "parameters" or "initial"


@dataclass(frozen=True)
class Range:
    """The values a setting accepts: low <= value <= high."""

    low: float
    high: float


# a simulation request's settings by name: the one table the web schema's fields and the service's checks read
RANGES = {
    "t_end": Range(T_END_MIN, T_END_MAX),
    "rtol": Range(RTOL_MIN, RTOL_MAX),
    "atol": Range(ATOL_MIN, ATOL_MAX),
    "samples": Range(SAMPLES_MIN, SAMPLES_MAX),
}

# Work budgets.  A run that needs more is stopped and reported as too much work.
WALL_SECONDS = 8.0  # for the whole request (main run and error-estimate run)
COMPILED_STEPS = 20_000_000  # steps of a compiled loop
SCIPY_STEPS = 400_000  # right-hand-side evaluations under scipy's Python loop
STATE_BOUND = 1.0e8  # |q_dot| (and |q| of angles) beyond this ends the run
RUNAWAY_FACTOR = 1.0e3  # a non-angle coordinate beyond this times max(1, |q(0)|) ends the run (a runaway)
