"""The exact solutions used as references: they satisfy their equations, and are recognised correctly."""

import math

import numpy as np
import pytest

from app.numerics.exact import constant_accelerations, exact_solution, pendulum, pendulum_frequency
from tests.numerics.extreme_cases import system_for

W2 = 9.81


def second_derivative(solution, t, h=1e-4):
    return (solution(t + h)[:, 0] - 2 * solution(t)[:, 0] + solution(t - h)[:, 0]) / h**2


@pytest.mark.parametrize(
    "q0, v0",
    [
        (0.3, 0.0),
        (2.5, 0.0),
        (1.0, -2.0),
        (math.pi - 1e-3, 0.0),
        (math.pi - 1e-6, 0.0),
        (0.0, 7.0),  # over the top: rotation (k > 1)
        (-2.0, -8.0),
        (7.0, 0.5),  # an angle beyond pi
    ],
)
def test_pendulum_solution_solves_the_equation(q0, v0):
    sol = pendulum(W2, q0, v0)
    t = np.linspace(0.3, 25.0, 9)
    y = sol(t)
    # q'' = -w0^2 sin q, checked by central differences of the closed form
    np.testing.assert_allclose(second_derivative(sol, t), -W2 * np.sin(y[:, 0]), atol=2e-5)
    # q' from the formula equals the slope of q
    slope = (sol(t + 1e-6)[:, 0] - sol(t - 1e-6)[:, 0]) / 2e-6
    np.testing.assert_allclose(y[:, 1], slope, atol=1e-6)
    # the energy level is kept: q'^2/2 - w0^2 cos q
    energy = y[:, 1] ** 2 / 2 - W2 * np.cos(y[:, 0])
    np.testing.assert_allclose(energy, v0**2 / 2 - W2 * math.cos(q0), atol=1e-9)
    # and it starts where it should
    np.testing.assert_allclose(sol(np.array([0.0]))[0], [q0, v0], atol=1e-12)


def test_small_swings_are_harmonic():
    sol = pendulum(W2, 1e-4, 0.0)
    t = np.linspace(0, 10, 11)
    np.testing.assert_allclose(sol(t)[:, 0], 1e-4 * np.cos(math.sqrt(W2) * t), atol=1e-12)


def test_near_separatrix_the_pendulum_lingers_at_the_top():
    """From pi - 1e-6 the bob needs ln(8 / 1e-6)/w0 ~ 5 s to fall: the closed form shows it, ellipj could not."""
    sol = pendulum(W2, math.pi - 1e-6, 0.0)
    assert sol(np.array([3.0]))[0, 0] > 3.0  # still near the top after 3 s
    assert sol(np.array([10.0]))[0, 0] < 0.0  # on the other side after one half period


def test_recognising_the_exact_cases():
    k = np.array([2.0, 9.81, 0.5])
    assert pendulum_frequency(system_for("simple-pendulum"), k) == pytest.approx(9.81 / 0.5, rel=1e-12)
    for key in ("spherical-pendulum", "rotating-parabola", "tabletop-spring"):
        assert pendulum_frequency(system_for(key), np.ones(len(system_for(key).parameter_names))) is None
    damped = system_for("damped-pendulum")
    assert pendulum_frequency(damped, np.array([1.0, 9.81, 1.0, 0.3])) is None
    assert pendulum_frequency(damped, np.array([1.0, 9.81, 1.0, 0.0])) == pytest.approx(9.81)
    for key in ("incline-block", "pulley", "movable-incline", "helix-bead"):
        s = system_for(key)
        assert constant_accelerations(s, np.array([1.5] * len(s.parameter_names))) is not None, key
    for key in ("simple-pendulum", "rail-two-body", "stiff-spring"):
        s = system_for(key)
        assert constant_accelerations(s, np.ones(len(s.parameter_names))) is None, key
    assert exact_solution(system_for("tabletop-spring"), np.ones(2), np.array([1.0, 0, 0, 1.0])) is None
