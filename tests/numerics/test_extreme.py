"""The stiff and extreme cases (the table in docs/benchmarks.md comes from the same cases)."""

import numpy as np
import pytest

from app.numerics.methods import STIFF
from app.scenes import SCENES
from tests.numerics.extreme_cases import CASES
from tests.numerics.extreme_cases import run as run_case

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

ALL_SCENES = set(SCENES)
_results = {}


def run(case):
    if case.name not in _results:
        _results[case.name] = run_case(case)
    return _results[case.name]


def test_the_cases_use_existing_scenes():
    """Fail loudly (never skip) if a scene the suite needs is missing."""
    needed = {c.system for c in CASES} - {"stiff-spring"}
    assert needed <= ALL_SCENES, f"missing scenes: {sorted(needed - ALL_SCENES)}"


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_extreme_case(case):
    r = run(case)
    out = r.outcome
    tr = out.trajectory
    expect = case.expect
    assert out.reason
    if "method" in expect:
        assert out.method == expect["method"], out.reason
    if "not_method" in expect:
        assert out.method != expect["not_method"], out.reason
    if out.method in (STIFF, "Radau"):
        # stiffness detected: a handful of implicit steps, not a resolved fast oscillation
        assert tr.steps < 100
    if expect.get("runaway"):
        assert not tr.complete and tr.t_reached < case.t_end
        assert any("ran away" in w for w in out.warnings)
        return
    assert tr.complete
    if "warning" in expect:
        assert any(expect["warning"] in w for w in r.summary["warnings"]), r.summary["warnings"]
    # the error estimate is honest wherever an exact solution exists
    assert out.estimate is not None
    if r.true_error is not None:
        floor = 4 * np.finfo(float).eps * float(np.max(np.abs(tr.y[:, : len(case.vectors()[0].coordinates)])))
        assert 0.1 <= out.estimate.value / max(r.true_error, floor) <= 1000
    # conserved quantities: tiny relative drift (the rotating parabola conserves h, not E)
    for name, drift in r.summary["conserved_drift"].items():
        assert drift["relative"] < 1e-5, (name, drift)


def test_long_symplectic_run_keeps_the_energy_error_flat():
    """Over 10^4 periods the energy error of the symplectic path does not grow: the last tenth of the run
    is no worse than the first tenth."""
    case = next(c for c in CASES if "10⁴ periods" in c.name)
    r = run(case)
    assert r.outcome.method == "Gauss-Legendre"
    from app.numerics.observables import build

    s, k, _ = case.vectors()
    energy = build(s).evaluate(r.outcome.trajectory.t, r.outcome.trajectory.y, k)["energy"]
    error = np.abs(energy - energy[0])
    tenth = error.size // 10
    assert error[-tenth:].max() <= 3 * error[:tenth].max()


def test_spherical_pendulum_near_the_pole_reports_the_drift_of_p_phi():
    case = next(c for c in CASES if "pole" in c.name)
    r = run(case)
    drift = r.summary["conserved_drift"]["p_phi"]
    assert drift["absolute"] > 0 and drift["relative"] < 1e-5
    assert any("singular point" in w for w in r.summary["warnings"])
