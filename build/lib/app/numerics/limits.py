"""Bounds on a simulation request: what is accepted, and how much work one run may do.

The web schema and the service read these numbers, so the API's documented
ranges and the checks inside the numerics are the same numbers.
"""

from __future__ import annotations

T_END_MAX = 1.0e5  # seconds of simulated time
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

# Work budgets.  A run that needs more is stopped and reported as too much work.
WALL_SECONDS = 8.0  # for the whole request (main run and error-estimate run)
COMPILED_STEPS = 20_000_000  # steps of a compiled loop
SCIPY_STEPS = 400_000  # right-hand-side evaluations under scipy's Python loop
STATE_BOUND = 1.0e8  # |q_dot| (and |q| of angles) beyond this ends the run
RUNAWAY_FACTOR = 1.0e3  # a non-angle coordinate beyond this times max(1, |q(0)|) ends the run (a runaway)
