"""``auto``: what it picks for which problem, and that it says why."""

import math

import numpy as np
import pytest

from app.numerics import plan as plan_module
from app.numerics.choose import analyse, choose
from app.numerics.methods import NONSTIFF, STIFF
from app.numerics.simulate import simulate
from tests.numerics.extreme_cases import circular_radius, pendulum_period, system_for

PENDULUM = np.array([1.0, 9.81, 1.0])


def pick(key, k, y0, t_end, rtol=1e-8):
    s = system_for(key)
    return choose(s, analyse(s, k, y0, t_end, rtol, np.full(y0.size, rtol * 1e-2)))


def test_short_run_is_explicit():
    name, reason = pick("simple-pendulum", PENDULUM, np.array([1.0, 0.0]), 10.0)
    assert name == NONSTIFF and "non-stiff" in reason


@pytest.mark.slow
def test_long_conservative_run_is_symplectic():
    name, reason = pick("simple-pendulum", PENDULUM, np.array([2.5, 0.0]), 1e4 * pendulum_period(2.5))
    assert name == "Gauss-Legendre" and "long run" in reason and "separates" in reason
    name, reason = pick("spherical-pendulum", PENDULUM, np.array([2.2, 0.0, 0.0, 2.0]), 1e4)
    assert name == "Gauss-Legendre" and "does not separate" in reason


def test_long_damped_run_stays_explicit():
    """Nothing is conserved under friction, so there is no energy to keep."""
    name, _ = pick("damped-pendulum", np.array([1.0, 9.81, 1.0, 0.3]), np.array([1.0, 0.0]), 1e4)
    assert name == NONSTIFF


def test_start_next_to_a_saddle_is_symplectic():
    name, reason = pick("simple-pendulum", PENDULUM, np.array([math.pi - 1e-3, 0.0]), 10.0)
    assert name == "Gauss-Legendre" and "unstable equilibrium" in reason


@pytest.mark.slow
@pytest.mark.parametrize("k_over_m", [1e6, 1e8])
def test_stiff_spring(k_over_m):
    k = np.array([1.0, k_over_m, 1.0])
    quiet = np.array([circular_radius(k_over_m, 1.0, 1.0), 0.0, 0.0, 1.0])
    name, reason = pick("stiff-spring", k, quiet, 10.0)
    assert name == STIFF and reason.startswith("stiff")
    excited = np.array([1.001, 0.0, 0.0, 1.0])
    name, reason = pick("stiff-spring", k, excited, 10.0)
    assert name != STIFF


@pytest.mark.slow
def test_detected_stiffness_switches_to_radau(monkeypatch):
    """If auto's explicit run meets stiffness on the way (here: forced), the run is redone with Radau IIA.

    A fast mode a billionth of the radius strong, far below the tolerance, still holds an explicit
    method's step at its stability limit: DOP853's own stiffness test notices and hands over."""
    s = system_for("stiff-spring")
    k = np.array([1.0, 1e6, 1.0])
    y0 = np.array([circular_radius(1e6, 1.0, 1.0) * (1 + 1e-9), 0.0, 0.0, 1.0])
    monkeypatch.setattr(plan_module, "choose", lambda system, analysis: (NONSTIFF, "forced for the test"))
    out = simulate(s, k, y0, 10.0, 101, rtol=1e-4, atol=1e-4)
    assert out.method == STIFF and out.path == "compiled"
    assert "detected stiffness" in out.reason
    assert out.trajectory.complete and out.trajectory.steps < 100
