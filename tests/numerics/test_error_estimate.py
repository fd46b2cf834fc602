"""stats.error_estimate against exact solutions: never below a tenth, never above 1000 times the true error."""

import math
from functools import cache

import numpy as np
import pytest

from app.numerics.simulate import simulate
from tests.numerics.extreme_cases import Case, system_for

K = np.array([1.0, 9.81, 1.0])
T_END, SAMPLES = 10.0, 101
EPS = np.finfo(float).eps


@cache
def pendulum_reference(theta0: float) -> np.ndarray:
    case = Case("", "simple-pendulum", {}, {"theta": theta0}, T_END, exact="pendulum")
    s, k, y0 = case.vectors()
    return case.exact_solution(k, y0)(np.linspace(0.0, T_END, SAMPLES))


def check(outcome, exact: np.ndarray, n: int) -> tuple[float, float]:
    tr = outcome.trajectory
    true = float(np.max(np.abs(tr.y[:, :n] - exact[: tr.t.size, :n])))
    floor = 4 * EPS * float(np.max(np.abs(exact[:, :n])))
    estimate = outcome.estimate.value
    ratio = estimate / max(true, floor)
    assert 0.1 <= ratio <= 1000, f"estimate {estimate:.3g} against true error {true:.3g}"
    return true, estimate


CHEAP = ["auto", "DOP853-compiled", "Yoshida4", "Gauss-Legendre"]
THETAS = [1.0, 2.5, math.pi - 1e-3, math.pi - 1e-6]


@pytest.mark.slow
@pytest.mark.parametrize("theta0", THETAS)
@pytest.mark.parametrize("method", CHEAP)
@pytest.mark.parametrize("rtol", [1e-4, 1e-8, 1e-11])
def test_pendulum_compiled_methods(theta0, method, rtol):
    s = system_for("simple-pendulum")
    out = simulate(s, K, np.array([theta0, 0.0]), T_END, SAMPLES, method, rtol, rtol * 1e-2)
    check(out, pendulum_reference(theta0), 1)


@pytest.mark.slow
@pytest.mark.parametrize("theta0", THETAS)
@pytest.mark.parametrize("method", ["Verlet", "RK45", "DOP853", "LSODA"])
@pytest.mark.parametrize("rtol", [1e-4, 1e-8])
def test_pendulum_other_methods(theta0, method, rtol):
    s = system_for("simple-pendulum")
    out = simulate(s, K, np.array([theta0, 0.0]), T_END, SAMPLES, method, rtol, rtol * 1e-2)
    check(out, pendulum_reference(theta0), 1)


@pytest.mark.slow
@pytest.mark.parametrize("theta0", [1.0, 2.5])
@pytest.mark.parametrize("method", ["Radau", "BDF"])
@pytest.mark.parametrize("rtol", [1e-4, 1e-7])
def test_pendulum_implicit_methods(theta0, method, rtol):
    s = system_for("simple-pendulum")
    out = simulate(s, K, np.array([theta0, 0.0]), T_END, SAMPLES, method, rtol, rtol * 1e-2)
    check(out, pendulum_reference(theta0), 1)


@pytest.mark.parametrize("key", ["incline-block", "pulley", "movable-incline", "helix-bead"])
@pytest.mark.parametrize("method", ["auto", "Yoshida4", "Gauss-Legendre", "RK45", "Radau"])
def test_constant_acceleration_scenes(key, method):
    """Closed form q0 + v0 t + a t^2 / 2: the errors are round-off, and the estimate must say so."""
    from app.scenes import SCENES

    scene = SCENES[key]
    case = Case("", key, {}, dict(scene.initial), scene.t_end, exact="constant")
    s, k, y0 = case.vectors()
    out = simulate(s, k, y0, scene.t_end, 51, method, 1e-8, 1e-10)
    true, estimate = check(out, case.exact_solution(k, y0)(out.trajectory.t), s.n)
    assert true < 1e-9 and estimate < 1e-9
