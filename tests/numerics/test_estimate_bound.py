"""The error estimate is a bound (issue 35): never below the true error, against exact solutions (stiff and
long runs) and against a run 10⁴ times tighter (the chaotic double pendulum)."""

from __future__ import annotations

import numpy as np
import pytest

from app.numerics.estimate import SAFETY
from app.numerics.simulate import simulate
from tests.numerics.extreme_cases import CASES, run, system_for

EXACT = [c for c in CASES if c.exact]


@pytest.mark.slow
@pytest.mark.parametrize("case", EXACT, ids=[c.name for c in EXACT])
def test_the_estimate_bounds_the_true_error(case):
    r = run(case)
    assert r.true_error is not None and r.outcome.estimate is not None
    tr = r.outcome.trajectory
    # at the round-off floor the "true" error is itself rounding (of the exact solution and the start):
    # there only a few dozen ulps of the largest coordinate are allowed above the estimate
    ulps = 64 * np.finfo(float).eps * float(np.max(np.abs(tr.y[:, : len(tr.y[0]) // 2])))
    assert max(r.outcome.estimate.value, ulps) >= r.true_error, (case.name, r.outcome.method)
    # and it is a bound of the right size, not a blanket
    assert r.outcome.estimate.value <= 1000 * SAFETY * max(r.true_error, ulps)


def test_the_case_list_has_stiff_and_long_runs():
    names = " ".join(c.name for c in EXACT)
    assert "stiff" in names and "10⁴ periods" in names


@pytest.mark.slow
@pytest.mark.parametrize("rtol", [1e-6, 1e-9])
def test_the_estimate_bounds_the_error_of_a_chaotic_run(rtol):
    s = system_for("double-pendulum")
    k = np.array([1.0, 1.0, 1.0, 1.0, 9.81])[: len(s.parameter_names)]
    y0 = np.array([2.0, 2.5, 0.0, 0.0])  # released high: chaotic
    out = simulate(s, k, y0, 10.0, 200, rtol=rtol, atol=rtol * 1e-2)
    truth = simulate(s, k, y0, 10.0, 200, method="DOP853-compiled", rtol=1e-14, atol=1e-16, estimate=False)
    true_error = float(np.max(np.abs(out.trajectory.y[:, :2] - truth.trajectory.y[:, :2])))
    assert out.estimate is not None and out.estimate.value >= true_error
