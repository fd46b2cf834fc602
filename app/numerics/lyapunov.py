"""The largest Lyapunov exponent of a start, measured by following a second run beside it (Benettin's method).

Two starts a distance d₀ apart in the state space (q, q̇) part, in a chaotic motion, as
d(t) ≈ d₀ e^{λt}; λ, the largest Lyapunov exponent, is the rate of that parting.  The gap cannot be
followed for long (it saturates at the size of the motion), so it is rescaled: every ``EVERY`` seconds
the second run is put back at distance d₀ from the first, along the direction the gap has turned to,
and the logarithms of the growths are added up.  The gap first needs time to turn to the direction
that grows fastest (``SETTLE`` seconds, rescaled but not counted); then, over the next t_end seconds,

    λ ≈ (1 / t_end) Σᵢ ln(dᵢ / d₀),

dᵢ being the gap at the end of the i-th interval before it is rescaled.  Both runs are the compiled
DOP853 at a tolerance far below d₀, so the gap measured is the motion's, not the integrator's.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from app.numerics import limits
from app.numerics.errors import TooMuchWork
from app.numerics.methods import METHODS, Problem
from app.numerics.system import NumericSystem

GAP = 1e-9  # d₀: the first coordinate of the second start is this much larger (its own unit)
EVERY = 0.1  # seconds between rescalings of the gap
SETTLE = 1.0  # seconds the gap is followed (and rescaled) before its growth is counted
TOLERANCE = 1e-12  # rtol and atol of both runs
METHOD = "DOP853-compiled"


@dataclass(frozen=True)
class Exponent:
    """The measured exponent (1/s) and how: over ``t_end`` seconds after ``settle`` seconds, gap ``gap``,
    rescaled every ``every`` s."""

    value: float
    t_end: float
    gap: float
    every: float
    settle: float
    method: str


def largest_exponent(
    system: NumericSystem, k: np.ndarray, y0: np.ndarray, t_end: float, wall_seconds: float = limits.WALL_SECONDS
) -> Exponent:
    """λ of the start ``y0`` at parameters ``k``, averaged over ``t_end`` seconds after ``SETTLE`` (Benettin's method).

    Raises ``TooMuchWork`` when the runs do not finish within ``wall_seconds``."""
    method = METHODS[METHOD]
    method.prepare(system)  # compiling (first use) happens before the clock starts
    deadline = time.perf_counter() + wall_seconds
    y0 = np.asarray(y0, dtype=float)
    atol = np.full(y0.size, TOLERANCE)
    bound = np.full(y0.size, limits.STATE_BOUND)
    settling = round(SETTLE / EVERY)
    pieces = settling + max(1, round(t_end / EVERY))
    edges = np.linspace(0.0, pieces * EVERY, pieces + 1)

    def advance(y: np.ndarray, a: float, b: float) -> np.ndarray:
        run = method.integrate(
            Problem(system, k, y, np.array([a, b]), TOLERANCE, atol, bound, deadline, limits.COMPILED_STEPS)
        )
        if not run.complete:
            raise TooMuchWork(f"the run beside the start stopped at t = {run.t_reached:.3g} s: {run.stop_reason}")
        return np.asarray(run.y[-1], dtype=float)

    first = y0.copy()
    second = y0.copy()
    second[0] += GAP
    total = 0.0
    for i, (a, b) in enumerate(zip(edges[:-1], edges[1:], strict=True)):
        first = advance(first, a, b)
        second = advance(second, a, b)
        gap = second - first
        size = float(np.linalg.norm(gap))
        if i >= settling:
            # ln(dᵢ/d₀): this interval's growth of the gap
            total += math.log(size / GAP)
        # the second run put back at d₀ from the first, along the gap's new direction
        second = first + gap * (GAP / size)
    counted = (pieces - settling) * EVERY
    # λ ≈ (1/t_end) Σ ln(dᵢ/d₀)
    return Exponent(total / counted, counted, GAP, EVERY, SETTLE, METHOD)
