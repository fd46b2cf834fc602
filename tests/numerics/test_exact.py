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


@pytest.mark.slow
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


@pytest.mark.slow
def test_linear_systems_are_recognised_and_solved_by_their_normal_modes():
    from app.numerics.exact import linear_coefficients

    # coupled oscillators, m = 2, k = 3, kappa = 0.7: from x1 = 1, x2 = 0 at rest the two modes, ω₁² = k/m (in
    # phase) and ω₂² = (k + 2κ)/m (opposite), each carry half: x₁ = (cos ω₁t + cos ω₂t)/2, x₂ = (cos ω₁t − cos ω₂t)/2
    k = np.array([2.0, 3.0, 0.7, 1.0])  # m, k, kappa, d (the rest spacing)
    system = system_for("coupled-oscillators")
    found = exact_solution(system, k, np.array([1.0, 0.0, 0.0, 0.0]))
    assert found is not None and "normal modes" in found[1]
    t = np.linspace(0.0, 40.0, 17)
    w1, w2 = math.sqrt(3.0 / 2.0), math.sqrt((3.0 + 1.4) / 2.0)
    y = found[0](t)
    np.testing.assert_allclose(y[:, 0], (np.cos(w1 * t) + np.cos(w2 * t)) / 2, atol=1e-12)
    np.testing.assert_allclose(y[:, 1], (np.cos(w1 * t) - np.cos(w2 * t)) / 2, atol=1e-12)
    np.testing.assert_allclose(y[:, 2], -(w1 * np.sin(w1 * t) + w2 * np.sin(w2 * t)) / 2, atol=1e-12)
    # two masses on a spring along a rail (m1 = 1, m2 = 3, k = 2, l0 = 0.5): the centre of mass drifts at its
    # start velocity, the extension oscillates at ω² = k/μ about l0 — the zero ω's drift is in the solution too
    k = np.array([1.0, 3.0, 2.0, 0.5])
    y0 = np.array([0.0, 0.8, 0.4, 0.0])
    found = exact_solution(system_for("rail-two-body"), k, y0)
    assert found is not None
    y = found[0](t)
    centre = (1.0 * y[:, 0] + 3.0 * y[:, 1]) / 4.0
    np.testing.assert_allclose(centre, (0.8 * 3.0) / 4.0 + 0.1 * t, atol=1e-11)
    w = math.sqrt(2.0 * (1.0 + 3.0) / 3.0)
    extension = y[:, 1] - y[:, 0] - 0.5
    np.testing.assert_allclose(extension, 0.3 * np.cos(w * t) - 0.4 / w * np.sin(w * t), atol=1e-11)
    # a system that is not linear is not taken for one
    for key in ("simple-pendulum", "tabletop-spring", "rotating-parabola", "double-pendulum"):
        s = system_for(key)
        assert linear_coefficients(s, np.ones(len(s.parameter_names))) is None, key
