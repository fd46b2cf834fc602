"""``auto`` never refuses what another method can do, and says which path ran (issue 35)."""

from __future__ import annotations

import numpy as np
import pytest

from app.engine.derivation.derive import derive
from app.numerics import limits as numerics_limits
from app.numerics.choose import analyse, choose
from app.numerics.errors import TooMuchWork
from app.numerics.methods import FALLBACK_STIFF, METHODS, NONSTIFF, STIFF
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from app.scenes.types import Parameter, System
from tests.numerics.extreme_cases import pendulum_period, system_for

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

# two masses on springs, 1e-9 and 1e9: a fast mode (|λ| ≈ 1.4e5/s) far above the slow one (≈ 3e-5/s)
LOPSIDED = System(
    coordinates=("x1", "x2"),
    parameters=(Parameter("m1", 1e-9), Parameter("m2", 1e9), Parameter("k", 10.0)),
    kinetic="m1*x1_dot**2/2 + m2*x2_dot**2/2",
    potential="k*x1**2/2 + k*(x2 - x1)**2/2",
)


def test_an_excited_fast_mode_is_never_given_to_a_symplectic_method():
    s = numeric_system(derive(LOPSIDED))
    k, y0 = np.array([1e-9, 1e9, 10.0]), np.array([0.1, 0.0, 0.0, 0.0])
    analysis = analyse(s, k, y0, 100.0, 1e-8, np.full(4, 1e-10))
    assert analysis.mode_gap > 1e3 and not analysis.stiff and analysis.characteristic_times > 1e3
    name, reason = choose(s, analysis)
    assert name == NONSTIFF and "excited" in reason


def test_a_symplectic_pick_past_its_step_limit_hands_over_instead_of_refusing(monkeypatch):
    s = system_for("simple-pendulum")
    k, y0 = np.array([1.0, 9.81, 1.0]), np.array([2.5, 0.0])
    t_end = 1e3 * pendulum_period(2.5)
    symplectic = METHODS["Gauss-Legendre"]

    def over_the_limit(problem, **options):
        raise symplectic.too_much(problem, f"more than {problem.max_steps:,} steps")

    monkeypatch.setattr(symplectic, "integrate", over_the_limit)
    out = simulate(s, k[: len(s.parameter_names)], y0, t_end, 200, rtol=1e-6, atol=1e-8)
    assert out.method == NONSTIFF and out.path == "compiled"
    assert "Gauss-Legendre" in out.reason and "instead" in out.reason
    assert out.trajectory.complete


def test_a_symplectic_method_asked_for_by_name_still_refuses(monkeypatch):
    s = system_for("simple-pendulum")
    symplectic = METHODS["Gauss-Legendre"]
    monkeypatch.setattr(symplectic, "integrate", lambda problem, **o: (_ for _ in ()).throw(
        symplectic.too_much(problem, "more than 1 steps")))  # fmt: skip
    try:
        simulate(s, np.array([1.0, 9.81, 1.0])[: len(s.parameter_names)], np.array([1.0, 0.0]), 10.0, 50,
                 method="Gauss-Legendre")  # fmt: skip
    except TooMuchWork as exc:
        assert "Gauss-Legendre" in str(exc)
    else:  # pragma: no cover - the failure this test is for
        raise AssertionError("a method asked for by name ran something else")


def test_a_stiff_start_runs_the_compiled_radau():
    s = system_for("stiff-spring")
    from tests.numerics.extreme_cases import circular_radius

    k = np.array([1.0, 1e8, 1.0])
    # the fast radial mode quiet at the start: stiff, so auto picks the compiled Radau IIA at once
    y0 = np.array([circular_radius(1e8, 1.0, 1.0), 0.0, 0.0, 1.0])
    out = simulate(s, k, y0, 5.0, 50)
    assert out.method == STIFF and out.path == "compiled"
    assert out.trajectory.complete and out.trajectory.steps < 100


def test_the_stiff_hand_over_goes_to_the_compiled_radau_or_scipys_while_it_compiles(monkeypatch):
    from app.numerics import jit
    from app.numerics.plan import plan

    s = system_for("simple-pendulum")
    planned = plan(s, np.array([1.0, 9.81, 1.0])[: len(s.parameter_names)], np.array([1.0, 0.0]), 10.0, 50,
                   "auto", 1e-8, 1e-10)  # fmt: skip
    assert planned.path == "compiled" and planned.watch_stiffness
    handed = planned.handed_over(3.0)
    assert handed.name == STIFF and handed.path == "compiled" and handed.reference.name == STIFF
    assert handed.method.compiled and handed.reference.compiled
    # a server that answers while compiling: before the kernel is loaded, scipy's Radau takes the run over
    serving = plan(s, np.array([1.0, 9.81, 1.0])[: len(s.parameter_names)], np.array([1.0, 0.0]), 10.0, 50,
                   "auto", 1e-8, 1e-10, wait_for_compile=False)  # fmt: skip
    monkeypatch.setattr(jit, "ready", lambda name: False)
    handed = serving.handed_over(3.0)
    assert handed.name == FALLBACK_STIFF and handed.path == "scipy" and not handed.method.compiled


def test_auto_out_of_time_answers_with_what_it_reached(monkeypatch):
    """A run auto cannot finish in its budget returns the samples it reached and says how far it got; the
    same run asked for by name is refused (a 422 through the API) and names the method."""
    s = system_for("simple-pendulum")
    k, y0 = np.array([1.0, 9.81, 1.0])[: len(s.parameter_names)], np.array([2.5, 0.0])
    t_end = 1500.0  # about 600 periods (short of a symplectic pick's long run): far more than one chunk of steps
    # a budget of steps, not of seconds, so the run stops at the same place on any machine: the limit is checked
    # between chunks of steps (app/numerics/methods/base.drive), the first of 2,000, past this limit
    monkeypatch.setattr(numerics_limits, "COMPILED_STEPS", 1_000)
    METHODS[NONSTIFF].prepare(s)
    out = simulate(s, k, y0, t_end, 20_000, rtol=1e-12, atol=1e-14)
    tr = out.trajectory
    assert out.method == NONSTIFF and not tr.complete and 0.0 < tr.t_reached < t_end
    assert tr.t.size == tr.y.shape[0] >= 2 and np.all(np.isfinite(tr.y))
    said = [w for w in out.warnings if "stopped" in w]
    assert said and f"t = {tr.t_reached:.6g} s of {t_end:g} s" in said[0] and "1,000 steps" in said[0]
    try:
        simulate(s, k, y0, 100 * t_end, 20_000, method=NONSTIFF, rtol=1e-12, atol=1e-14)
    except TooMuchWork as exc:
        assert NONSTIFF in str(exc)
    else:  # pragma: no cover - the failure this test is for
        raise AssertionError("a method asked for by name answered past its budget")
