"""Global error of a run, estimated by a second, more accurate run.

    error_estimate = max over samples and coordinates of |q_run(t) - q_ref(t)| * factor

* adaptive methods: the reference is the compiled ``REFERENCE`` pair (scipy's DOP853 while the
  kernels compile; when the problem is stiff, the compiled Radau IIA, scipy's Radau while it compiles) at a thousand times tighter tolerances (for Radau, rtol
  only), factor 1.  With
  errors roughly proportional to the tolerance the reference's own error is
  about 1/1000 of the run's, so the difference is the run's error.
* fixed-step methods (order p): the reference is the same method with half the
  step (Richardson): e_h = C h^p and e_{h/2} = e_h / 2^p give
  e_h = (y_h - y_{h/2}) / (1 - 2^-p).  This matters near a separatrix, where a
  symplectic method's bounded energy error makes it far more accurate than an
  adaptive method at any affordable tolerance, so no adaptive run could serve
  as its reference.

Near the round-off floor both runs carry errors of similar size; there the
estimate is never allowed below the run's round-off level, eps max|q| sqrt(steps).

The reported value is that difference times ``SAFETY`` (2): a bound, not only an
estimate.  The difference itself is the run's error minus the reference's (about
a thousandth of it), so it falls just short of the true error about half the time:
in 17 runs with a known true error, true/difference was 0.9999-1.0008.  Doubled
(quadrupled for a fixed step, whose Richardson factor fails next to a separatrix),
the estimate stays above the true error in the stiff, long-run and chaotic cases
(tests/numerics/test_estimate_bound.py) at the cost of a factor two of pessimism.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.engine.display.names import unicode
from app.numerics.methods import FALLBACK, FALLBACK_STIFF, REFERENCE, STIFF, Problem, Trajectory

TIGHTER = 1.0e-3
# The estimate's safety factor: the reported value is SAFETY times the measured difference (a bound).
SAFETY = 2.0
# For a fixed step, Richardson's factor assumes the error shrinks by 2^p with half the step; next to a
# separatrix it shrank by less (Gauss-Legendre, pendulum released at pi - 1e-6: true/difference = 2.2).
SAFETY_FIXED_STEP = 4.0
REFERENCE_RTOL_MIN = 1.0e-13
REFERENCE_ATOL_MIN = 1.0e-16


@dataclass(frozen=True)
class Estimate:
    value: float
    by_coordinate: dict[str, float]
    reference: str


def reference_name(stiff: bool, compiled: bool = True) -> str:
    """The method of an adaptive run's reference: the stiff method for a stiff problem, else the compiled
    reference; scipy's fallbacks while the kernels are not compiled (``compiled=False``)."""
    if stiff:
        return STIFF if compiled else FALLBACK_STIFF
    return REFERENCE if compiled else FALLBACK


def reference_problem(problem: Problem, stiff: bool, compiled: bool = True) -> tuple[str, Problem]:
    """The tighter run.  For a stiff problem atol stays: tightening it would make round-off-sized
    wiggles of the fast mode (which the run rightly ignores) count, and force Radau to resolve them."""
    method = reference_name(stiff, compiled)
    atol = problem.atol if stiff else np.maximum(problem.atol * TIGHTER, REFERENCE_ATOL_MIN)
    tight = Problem(**{**problem.__dict__, "rtol": max(problem.rtol * TIGHTER, REFERENCE_RTOL_MIN), "atol": atol})
    return method, tight


def compare(
    run: Trajectory, reference: Trajectory, coordinates: tuple[str, ...], label: str, factor: float = 1.0
) -> Estimate:
    """Largest coordinate difference over the samples both runs reached, times ``factor``."""
    n = len(coordinates)
    common = min(run.t.size, reference.t.size)
    if common == 0:
        return Estimate(float("nan"), {}, label)
    # |run - reference| times the method's factor (Richardson's for a fixed step) and the safety factor
    safety = SAFETY if factor == 1.0 else SAFETY_FIXED_STEP
    diff = np.abs(run.y[:common, :n] - reference.y[:common, :n]) * (factor * safety)
    eps = np.finfo(float).eps
    floor = eps * np.max(np.abs(run.y[:common, :n]), axis=0) * np.sqrt(max(run.steps, 1))
    per = np.maximum(np.max(diff, axis=0), floor)
    return Estimate(float(per.max()), {name: float(v) for name, v in zip(coordinates, per, strict=True)}, label)


def above_tolerance(estimate: Estimate, run: Trajectory, rtol: float, atol: np.ndarray, fixed_step: bool) -> str | None:
    """A warning when the run's error is above what was asked for, and why; None when it is within.

    What was asked for, per coordinate i: atol_i + rtol max_t |q_i(t)|.  The run's error is the estimate
    without its safety factor (the measured difference, about the true error: the factor only makes the
    reported value a bound), so a run whose true error is within the tolerance is not warned about.
    """
    n = len(estimate.by_coordinate)
    if n == 0 or run.t.size == 0 or not np.isfinite(estimate.value):
        return None
    safety = SAFETY_FIXED_STEP if fixed_step else SAFETY
    measured = np.array(list(estimate.by_coordinate.values())) / safety
    # the tolerance in each coordinate's own scale over the whole run
    asked = np.asarray(atol, dtype=float)[:n] + rtol * np.max(np.abs(run.y[:, :n]), axis=0)
    ratio = measured / asked
    worst = int(np.argmax(ratio))
    if not ratio[worst] > 1.0:
        return None
    name = unicode(list(estimate.by_coordinate)[worst])
    how = (
        "the fixed step was chosen so that each step's own error is about the tolerance"
        if fixed_step
        else "each step keeps its own error within the tolerance"
    )
    # In words a student reads: the coordinate's letter, a plain ratio, no option names; the
    # estimate's figure itself is in the run's details.
    return (
        f"the error in {name} is about {_times(ratio[worst])} times the tolerance asked for: {how}, but over "
        f"this run's {run.steps:,} steps those errors add up (and the motion itself may amplify them); "
        "a smaller tolerance brings the run closer"
    )


def _times(ratio: float) -> str:
    """A ratio as a reader writes it: 1.5, 3, 450, 12,000 (never 4.5e+02)."""
    return f"{ratio:.2g}" if ratio < 10 else f"{float(f'{ratio:.2g}'):,.0f}"
