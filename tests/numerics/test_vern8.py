"""Verner's efficient 8(7) pair: the tableau's orders, checked numerically, and the compiled kernel against exact motion."""

import time

import numpy as np
import pytest

from app.numerics.exact import pendulum
from app.numerics.kernels import vern8_tableau as tab
from app.numerics.kernels.vern8 import STIFF_LIMIT, interpolant_weights
from app.numerics.methods import METHODS, Problem
from tests.numerics.extreme_cases import system_for
from tests.numerics.rk_trees import density, round_off, stage_weights, trees

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


def weights(theta: float) -> np.ndarray:
    out = np.empty(tab.N_ALL)
    interpolant_weights(theta, out)
    return out


def test_tableau_consistency():
    assert abs(tab.B.sum() - 1.0) < 4e-15 and abs(tab.BHAT.sum() - 1.0) < 4e-15
    # the nodes are the row sums; they match the published c_i (stage 0 is at t, stage 13 at t + h)
    np.testing.assert_allclose(np.delete(tab.C, [0, 13]), tab.C_PUBLISHED, rtol=0, atol=1e-15)
    assert tab.C[0] == 0.0 and tab.C[13] == 1.0
    # the embedded pair: stage 12 enters only the 7th-order result, stage 13 neither
    assert tab.B[12] == 0.0 and tab.BHAT[12] != 0.0 and tab.B[13] == tab.BHAT[13] == 0.0
    # the interpolant ends at the step's result: b_j(1) = B_j, and starts at y: b_j(0) = 0
    np.testing.assert_array_equal(weights(1.0), tab.NODE_VALUES[-1])
    assert np.abs(tab.NODE_VALUES[-1] - tab.B).max() < 1e-15
    assert np.abs(weights(0.0)).max() == 0.0


def test_stiffness_limit_sits_below_the_stability_boundary():
    """|R(-x)| = 1 on the negative real axis at the boundary, R(z) = 1 + z b^T (I - z A)^-1 1 over the
    twelve stages of the 8th-order result; the kernel's limit is 0.955 of it, as DOP853's 6.1 of 6.39."""
    A, b = tab.A[:12, :12], tab.B[:12]

    def growth(x):
        return abs(1.0 - x * b @ np.linalg.solve(np.eye(12) + x * A, np.ones(12)))

    xs = np.linspace(0.01, 10.0, 2000)
    boundary = xs[np.argmax([growth(x) > 1.0 for x in xs])]
    assert all(growth(x) <= 1.0 for x in xs[xs < boundary - 0.01])
    assert abs(STIFF_LIMIT / boundary - 0.955) < 0.01


def test_tree_counts():
    assert [len(trees(p)) for p in range(1, 9)] == [1, 1, 2, 4, 9, 20, 48, 115]


@pytest.mark.parametrize("weights, order", [(tab.B, 8), (tab.BHAT, 7)])
def test_order_conditions(weights, order):
    """Butcher's conditions b . g(t) = 1 / gamma(t) for every rooted tree t with at most ``order`` nodes
    (200 trees for order 8), and some tree of the next order missed."""
    for p in range(1, order + 1):
        for tree in trees(p):
            g = stage_weights(tree, tab.A)
            assert abs(weights @ g - 1.0 / density(tree)) < round_off(weights, g), (p, tree)
    misses = [abs(weights @ stage_weights(t, tab.A) - 1.0 / density(t)) for t in trees(order + 1)]
    assert max(misses) > 1e-8  # far above round-off: the order is exactly ``order``


@pytest.mark.parametrize("theta", [0.1, 0.37, 0.5, 0.8])
def test_interpolant_order_conditions(theta):
    """The interpolant's weights meet b(theta) . g(t) = theta^|t| / gamma(t) for every tree up to order 8."""
    w = weights(theta)
    for p in range(1, 9):
        for tree in trees(p):
            g = stage_weights(tree, tab.A)
            # the weights are themselves sums of eight node values up to 60 each: more ulps
            assert abs(w @ g - theta**p / density(tree)) < round_off(w, g, 200), (p, tree)


def test_interpolant_is_eighth_order():
    """One step, evaluated inside: the local error falls by about 2^9 when h halves."""
    y0 = np.array([1.0, 0.0])
    theta = 0.37
    errors = []
    for h in (0.4, 0.2):
        Ks = np.zeros((tab.N_ALL, 2))
        Ks[0] = forced_pendulum(0.0, y0)
        for s in range(1, tab.N_ALL):
            Ks[s] = forced_pendulum(tab.C[s] * h, y0 + h * tab.A[s, :s] @ Ks[:s])
        dense = y0 + h * weights(theta) @ Ks
        errors.append(np.abs(dense - steps(y0, theta * h, 50, tab.B)).max())
    assert np.log2(errors[0] / errors[1]) > 8.4


def test_parabola_samples_are_exact_to_round_off():
    """Constant acceleration: every dense sample on the parabola, up to round-off (the pair's weights reach 32
    in size and cancel to 1: a few ulps of the state per step, 1.8e-12 of 5.7 after the run's steps)."""
    from tests.numerics.extreme_cases import Case

    case = Case("", "pulley", {}, {}, 2.0, exact="constant")
    s, k, y0 = case.vectors()
    t = np.linspace(0.0, 2.0, 51)
    m = y0.size
    problem = Problem(s, k, y0, t, 1e-11, np.full(m, 1e-13), np.full(m, 1e8), time.perf_counter() + 60, 10**8)
    run = METHODS["Vern8"].integrate(problem)
    assert np.abs(run.y - case.exact_solution(k, y0)(t)).max() < 5e-12


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


@pytest.mark.slow
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
