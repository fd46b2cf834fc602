"""Verner's 8(7) pair: the tableau's orders, checked numerically, and the compiled kernel against exact motion."""

import time

import numpy as np
import pytest

from app.numerics.exact import pendulum
from app.numerics.kernels import vern8_tableau as tab
from app.numerics.methods import METHODS, Problem
from tests.numerics.extreme_cases import system_for

K = np.array([1.0, 9.81, 1.0])  # m, g, R of the simple pendulum


def forced_pendulum(t, y):
    return np.array([y[1], -np.sin(y[0]) + 0.3 * np.cos(t)])


def steps(y0, t_end, n, weights):
    """n fixed steps of the pair's stepping stages with the given weights (B or BHAT)."""
    h, y, t = t_end / n, np.array(y0, dtype=float), 0.0
    for _ in range(n):
        Ks = np.zeros((tab.N_ALL, y.size))
        Ks[0] = forced_pendulum(t, y)
        for s in range(1, tab.N_STEP):
            Ks[s] = forced_pendulum(t + tab.C[s] * h, y + h * tab.A[s, :s] @ Ks[:s])
        y, t = y + h * weights @ Ks, t + h
    return y


def reference(y0, t_end):
    # many small steps of the 8th-order formula: error far below the coarse runs'
    return steps(y0, t_end, 400, tab.B)


def test_tableau_consistency():
    assert abs(tab.B.sum() - 1.0) < 1e-14 and abs(tab.BHAT.sum() - 1.0) < 1e-14
    np.testing.assert_allclose(tab.A.sum(axis=1), tab.C, atol=1e-15)
    # the continuous extension ends at the step's result: b_j(1) = B_j
    np.testing.assert_allclose(tab.BI.sum(axis=1), tab.B, atol=1e-11)


@pytest.mark.parametrize("weights, order", [(tab.B, 8), (tab.BHAT, 7)])
def test_observed_orders(weights, order):
    """Halving the step divides the global error by about 2^p."""
    y0, t_end = [1.0, 0.0], 2.0
    exact = reference(y0, t_end)
    errors = [np.abs(steps(y0, t_end, n, weights) - exact).max() for n in (4, 8)]
    assert abs(np.log2(errors[0] / errors[1]) - order) < 0.6


def test_continuous_extension_is_seventh_order():
    """One step, evaluated inside: the local error falls by about 2^8 when h halves."""
    y0 = np.array([1.0, 0.0])
    theta = 0.37
    errors = []
    for h in (0.4, 0.2):
        Ks = np.zeros((tab.N_ALL, 2))
        Ks[0] = forced_pendulum(0.0, y0)
        for s in range(1, tab.N_ALL):
            Ks[s] = forced_pendulum(tab.C[s] * h, y0 + h * tab.A[s, :s] @ Ks[:s])
        dense = y0 + h * (tab.BIC @ (theta - 0.5) ** np.arange(tab.DEGREE + 1)) @ Ks
        errors.append(np.abs(dense - steps(y0, theta * h, 50, tab.B)).max())
    assert np.log2(errors[0] / errors[1]) > 7.4


@pytest.mark.parametrize("p", range(1, tab.DEGREE + 1))
def test_continuous_extension_integrates_polynomials_to_round_off(p):
    """y' = t^(p-1) from 0: the extension's weights satisfy sum_j b_j(theta) c_j^(p-1) = theta^p / p exactly
    (the published coefficients missed by up to 9e-13, see vern8_tableau.centred)."""
    for theta in np.linspace(0.0, 1.0, 11):
        weights = tab.BIC @ (theta - 0.5) ** np.arange(tab.DEGREE + 1)
        assert abs(weights @ tab.C ** (p - 1) - theta**p / p) < 4e-15
    assert np.abs(tab.BIC @ 0.5 ** np.arange(tab.DEGREE + 1) - tab.B).max() < 1e-12  # b_j(1) = B_j


def test_parabola_samples_are_exact_to_round_off():
    """Constant acceleration: every dense sample on the parabola (it was 6e-12 off before the fix)."""
    from tests.numerics.extreme_cases import Case

    case = Case("", "pulley", {}, {}, 2.0, exact="constant")
    s, k, y0 = case.vectors()
    t = np.linspace(0.0, 2.0, 51)
    m = y0.size
    problem = Problem(s, k, y0, t, 1e-11, np.full(m, 1e-13), np.full(m, 1e8), time.perf_counter() + 60, 10**8)
    run = METHODS["Vern8"].integrate(problem)
    assert np.abs(run.y - case.exact_solution(k, y0)(t)).max() < 1e-13


def test_stiffness_is_detected():
    """A stiff radial spring holds h |lambda| at the stability boundary: with stop_on_stiff the run stops and
    says so; a pendulum never trips the test."""
    from tests.numerics.extreme_cases import circular_radius

    s = system_for("stiff-spring")
    k = np.array([1.0, 1e6, 1.0])
    y0 = np.array([circular_radius(1e6, 1.0, 1.0) * (1 + 1e-9), 0.0, 0.0, 1.0])
    t = np.linspace(0.0, 10.0, 101)
    problem = Problem(s, k, y0, t, 1e-4, np.full(4, 1e-4), np.full(4, 1e8), time.perf_counter() + 60, 10**8)
    stiff = METHODS["Vern8"].integrate(problem, stop_on_stiff=True)
    assert stiff.stiff_detected and not stiff.complete and stiff.steps < 1000
    calm = Problem(
        system_for("simple-pendulum"),
        K,
        np.array([2.5, 0.0]),
        t,
        1e-8,
        np.full(2, 1e-10),
        np.full(2, 1e8),
        time.perf_counter() + 60,
        10**8,
    )
    run = METHODS["Vern8"].integrate(calm, stop_on_stiff=True)
    assert run.complete and not run.stiff_detected


def test_kernel_follows_the_exact_pendulum():
    s = system_for("simple-pendulum")
    y0 = np.array([2.5, 0.0])
    t = np.linspace(0.0, 20.0, 301)
    m = y0.size
    problem = Problem(s, K, y0, t, 1e-10, np.full(m, 1e-12), np.full(m, 1e8), time.perf_counter() + 60, 10**8)
    run = METHODS["Vern8"].integrate(problem)
    exact = pendulum(K[1] / K[2], y0[0], y0[1])(t)
    assert run.complete and np.abs(run.y[:, 0] - exact[:, 0]).max() < 1e-7
    assert run.rhs_evaluations >= 13 * run.steps
