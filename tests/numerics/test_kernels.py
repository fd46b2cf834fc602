"""The compiled kernels: agreement with scipy, orders of accuracy, tableaux, resumable chunks."""

import time

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from app.numerics.methods import METHODS, Problem
from app.numerics.methods.symplectic import GaussLegendre, Yoshida4, gauss_tableau
from tests.numerics.extreme_cases import system_for

K = np.array([1.0, 9.81, 1.0])  # m, g, R of the simple pendulum


def problem(system, y0, t, rtol=1e-8, atol=1e-10, k=K):
    m = y0.size
    return Problem(system, k, y0, t, rtol, np.full(m, atol), np.full(m, 1e8), time.perf_counter() + 60, 10**8)


def test_compiled_dop853_is_scipys_dop853():
    s = system_for("spherical-pendulum")
    y0 = np.array([2.2, 0.0, 0.0, 2.0])
    t = np.linspace(0, 5, 51)
    ours = METHODS["DOP853-compiled"].integrate(problem(s, y0, t))
    theirs = solve_ivp(lambda tt, y: s.f(tt, y, K), (0, 5), y0, method="DOP853", t_eval=t, rtol=1e-8, atol=1e-10)
    # same tableau, same controller, same dense output: equal up to round-off differences
    np.testing.assert_allclose(ours.y, theirs.y.T, rtol=1e-9, atol=1e-9)
    assert abs(ours.rhs_evaluations - theirs.nfev) <= 0.02 * theirs.nfev


@pytest.mark.parametrize("method", ["Verlet", "Yoshida4", "Gauss-Legendre"])
def test_observed_order(method):
    """Halving the step divides the error by about 2^p."""
    s = system_for("simple-pendulum")
    y0 = np.array([1.0, 0.0])
    t = np.array([0.0, 2.0])
    m = METHODS[method]
    reference = METHODS["DOP853-compiled"].integrate(problem(s, y0, t, 1e-13, 1e-15)).y[-1]
    base = {"Verlet": 400, "Yoshida4": 40, "Gauss-Legendre": 8}[method]
    errors = [np.max(np.abs(m.integrate(problem(s, y0, t), substeps=n).y[-1] - reference)) for n in (base, 2 * base)]
    observed = np.log2(errors[0] / errors[1])
    assert abs(observed - m.order) < 0.3, (errors, observed)


def test_gauss_tableau_conditions():
    A, b, c, E = gauss_tableau(3)
    assert np.isclose(b.sum(), 1.0)
    # order conditions up to 6 for the quadrature, and the collocation conditions sum_j a_ij c_j^(q-1) = c_i^q / q
    for q in range(1, 7):
        assert np.isclose(b @ c ** (q - 1), 1.0 / q)
    for q in range(1, 4):
        np.testing.assert_allclose(A @ c ** (q - 1), c**q / q, atol=1e-15)
    # symplecticity: b_i a_ij + b_j a_ji - b_i b_j = 0
    M = b[:, None] * A + (b[:, None] * A).T - np.outer(b, b)
    np.testing.assert_allclose(M, 0.0, atol=1e-15)
    # extrapolation reproduces polynomials of degree s - 1 through the nodes
    np.testing.assert_allclose(E @ c**2, (1 + c) ** 2, atol=1e-13)


def test_yoshida_weights():
    w = Yoshida4.weights
    assert np.isclose(w.sum(), 1.0)
    assert np.isclose((w**3).sum(), 0.0, atol=1e-15)  # the third-order error term cancels


@pytest.mark.parametrize("method", ["DOP853-compiled", "Vern8", "Radau-compiled", "Yoshida4", "Gauss-Legendre"])
def test_chunks_resume_exactly(method, monkeypatch):
    """Running in many small chunks gives bit-for-bit the same trajectory as one long call."""
    from app.numerics.methods import base

    s = system_for("spherical-pendulum" if method != "Yoshida4" else "simple-pendulum")
    y0 = np.array([2.2, 0.0, 0.0, 2.0]) if s.n == 2 else np.array([2.0, 0.0])
    t = np.linspace(0, 3, 31)
    # the adaptive methods choose their own steps; the fixed-step ones take 50 per output interval
    options = {} if method in ("DOP853-compiled", "Vern8", "Radau-compiled") else {"substeps": 50}
    whole = METHODS[method].integrate(problem(s, y0, t), **options)

    def tiny_chunks(step, steps_done, problem_, method_):
        status = step(3)
        while status == 0:
            status = step(3)
        return status

    # the compiled pairs and Radau are driven by base.run_kernel; the symplectic methods call drive themselves
    monkeypatch.setattr(base, "drive", tiny_chunks)
    monkeypatch.setattr("app.numerics.methods.symplectic.drive", tiny_chunks)
    pieces = METHODS[method].integrate(problem(s, y0, t), **options)
    np.testing.assert_array_equal(whole.y, pieces.y)
    assert whole.steps == pieces.steps


def test_gauss_legendre_keeps_a_cyclic_momentum_exactly():
    """p_phi is a coordinate of the (q, p) state and its rate is identically 0: it cannot drift."""
    s = system_for("spherical-pendulum")
    y0 = np.array([2.2, 0.0, 0.0, 2.0])
    t = np.linspace(0, 20, 201)
    run = GaussLegendre().integrate(problem(s, y0, t, 1e-6, 1e-8))
    p = np.array([s.momenta(0.0, y, K)[1] for y in run.y])
    assert np.max(np.abs(p - p[0])) <= 1e-14 * abs(p[0])
