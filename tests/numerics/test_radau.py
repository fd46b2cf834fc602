"""The compiled Radau IIA (order 5): its coefficients, its accuracy against exact motion and scipy, its order,
its dense output, and the engine's Jacobian it runs on."""

import time

import numpy as np
import pytest
from numba import njit
from scipy.integrate import solve_ivp
from scipy.linalg import expm

from app.engine.derivation.derive import derive
from app.numerics.bound import Bound
from app.numerics.choose import central_differences
from app.numerics.kernels import radau
from app.numerics.kernels.common import DONE, RHS_SIG, RUNNING
from app.numerics.methods import METHODS, STIFF, Problem
from app.numerics.simulate import simulate
from app.numerics.system import generated_sources, numeric_system
from tests.numerics.extreme_cases import system_for
from tests.numerics.systems import DOUBLE_PENDULUM, TWO_MODES

K_TWO = np.array([1.0, 1.0, 1e8, 0.1, 2e3])  # m, k1, k2, b1, b2
# y' = A y for TWO_MODES: x_i'' = -(k_i / m) x_i - (b_i / m) x_i'
A_TWO = np.array([[0, 0, 1, 0], [0, 0, 0, 1], [-1.0, 0, -0.1, 0], [0, -1e8, 0, -2e3]])


def radau_problem(system, k, y0, t, rtol, atol):
    atol = np.full(y0.size, atol) if np.isscalar(atol) else np.asarray(atol, dtype=float)
    return Problem(system, k, y0, t, rtol, atol, np.full(y0.size, 1e8), time.perf_counter() + 60, 10**7)


def exact_two_modes(y0, t):
    return np.array([expm(A_TWO * ti) @ y0 for ti in t])


@pytest.fixture(scope="module")
def two_modes():
    return numeric_system(derive(TWO_MODES))


def test_coefficients():
    """T^-1 A^-1 T is the real eigenvalue and the complex pair's 2 x 2 block; P is the collocation cubic; the
    error weights E make (h gamma_0 f0 + E Z) vanish on a cubic solution (the embedded method's order 3)."""
    s6 = np.sqrt(6.0)
    # Radau IIA's Butcher matrix (Hairer and Wanner, Table IV.5.6)
    A = np.array(
        [
            [(88 - 7 * s6) / 360, (296 - 169 * s6) / 1800, (-2 + 3 * s6) / 225],
            [(296 + 169 * s6) / 1800, (88 + 7 * s6) / 360, (-2 - 3 * s6) / 225],
            [(16 - s6) / 36, (16 + s6) / 36, 1 / 9],
        ]
    )
    np.testing.assert_allclose(A.sum(axis=1), radau.C, rtol=1e-15)
    np.testing.assert_allclose(radau.TI @ radau.T_MAT, np.eye(3), atol=1e-14)
    block = radau.TI @ np.linalg.inv(A) @ radau.T_MAT
    a, b = radau.MU_COMPLEX.real, radau.MU_COMPLEX.imag
    np.testing.assert_allclose(block, [[radau.MU_REAL, 0, 0], [0, a, -b], [0, b, a]], atol=1e-12)
    # u(c_i h) = Z_i: the cubic sum_j Q_j x^j with Q = P^T Z passes through the stages
    V = np.array([[c, c**2, c**3] for c in radau.C])
    np.testing.assert_allclose(V @ radau.P.T, np.eye(3), atol=1e-13)
    # on y' = t^2 (exact stages Z_i = (c_i h)^3 / 3, f0 = 0), E Z = 0: the estimate sees no error
    Z = radau.C**3 / 3
    assert abs(radau.E @ Z) < 1e-14


@pytest.mark.slow
def test_exact_for_polynomials_of_degree_five():
    """Collocation at three Radau points integrates y' = g(t) exactly for g of degree 4 (quadrature order 5),
    not for degree 5: y' = 5 t^4 ends at t^5 to round-off, y' = 6 t^5 does not (coarse steps)."""

    @njit(RHS_SIG)
    def quartic(t, y, k, out):
        out[0] = 5.0 * t**4

    @njit(RHS_SIG)
    def quintic(t, y, k, out):
        out[0] = 6.0 * t**5

    errors = []
    for f in (quartic, quintic):
        bound = Bound(f, RHS_SIG)
        y, fy, st = np.zeros(1), np.empty(1), np.zeros(radau.STATE_SIZE)
        t_out = np.array([0.0, 2.0])
        Y, J, Q = np.empty((2, 1)), np.empty((1, 1)), np.zeros((4, 1))
        status = radau.run(bound, bound, 0, np.zeros(1), t_out, 1e-2, np.array([1.0]), np.array([1e8]), 1000,
                           y, fy, st, Y, J, Q)  # fmt: skip
        assert status == DONE and st[radau.STEPS] >= 2
        errors.append(abs(Y[-1, 0] - 32.0 * (1.0 if f is quartic else 2.0)))
    assert errors[0] < 1e-12 < 1e-6 < errors[1]


@pytest.mark.slow
def test_two_modes_against_the_matrix_exponential(two_modes):
    """k/m = 1 and 1e8, both damped, both excited at the start: every sample within a few times rtol of
    exp(A t) y0, in far fewer steps than the fast period would need (2 pi / 1e4 s over 10 s: 1e5 periods)."""
    y0 = np.array([1.0, 1e-3, 0.0, 0.0])
    t = np.linspace(0.0, 10.0, 2001)
    exact = exact_two_modes(y0, t)
    for rtol in (1e-6, 1e-9):
        tr = METHODS[STIFF].integrate(radau_problem(two_modes, K_TWO, y0, t, rtol, rtol * 1e-3))
        assert tr.complete and tr.steps < 10_000
        error = np.abs(tr.y - exact).max(axis=0)
        # positions within a few rtol of their scale (1), the fast velocity within rtol of its peak (about 10)
        assert error[0] < 0.5 * rtol and error[1] < 0.5 * rtol and error[3] < 10 * rtol, (rtol, error)


def test_order_five_at_the_step_ends(two_modes):
    """Error at the end of the run (no dense output involved) against the number of steps on the slow damped
    mode: log error / log steps has slope about -5 (Radau IIA with three stages is order 2s - 1 = 5)."""
    y0 = np.array([1.0, 0.0, 0.0, 0.0])
    t = np.array([0.0, 10.0])
    exact = exact_two_modes(y0, t)[-1]
    steps, errors = [], []
    for rtol in (1e-5, 1e-6, 1e-7, 1e-8):
        tr = METHODS[STIFF].integrate(radau_problem(two_modes, K_TWO, y0, t, rtol, 1e-14))
        steps.append(tr.steps)
        errors.append(np.abs(tr.y[-1] - exact).max())
    slope = np.polyfit(np.log(steps), np.log(errors), 1)[0]
    assert -6.0 < slope < -4.2, (slope, steps, errors)


@pytest.mark.slow
def test_dense_output_between_the_steps(two_modes):
    """Samples inside the steps come from the collocation cubic: at rtol 1e-6 every one of 4001 samples is
    within 1e-6 of the exact motion (a straight line between step ends would be off by about 1e-5 here)."""
    y0 = np.array([1.0, 1e-3, 0.0, 0.0])
    t = np.linspace(0.0, 10.0, 4001)
    tr = METHODS[STIFF].integrate(radau_problem(two_modes, K_TWO, y0, t, 1e-6, 1e-9))
    assert tr.steps < t.size / 2  # most samples fall inside steps
    assert np.abs(tr.y[:, :2] - exact_two_modes(y0, t)[:, :2]).max() < 1e-6


def test_differenced_jacobian_when_none_is_generated(two_modes):
    """A system without a generated Jacobian runs on forward differences inside the kernel, as accurately."""
    sources = {name: text for name, text in generated_sources(two_modes.derivation).items() if name != "jac"}
    plain = numeric_system(two_modes.derivation, sources)
    assert not plain.has_jacobian
    y0 = np.array([1.0, 1e-3, 0.0, 0.0])
    t = np.linspace(0.0, 10.0, 201)
    tr = METHODS[STIFF].integrate(radau_problem(plain, K_TWO, y0, t, 1e-8, 1e-11))
    assert tr.complete and "forward differences" in tr.notes[0]
    assert np.abs(tr.y[:, :2] - exact_two_modes(y0, t)[:, :2]).max() < 1e-8


@pytest.mark.parametrize("key", ["double-pendulum", "stiff-spring", "spherical-pendulum"])
def test_compiled_jacobian_against_differences(key):
    """The compiled generated Jacobian dF/dy equals central differences of the compiled right-hand side."""
    s = numeric_system(derive(DOUBLE_PENDULUM)) if key == "double-pendulum" else system_for(key)
    rng = np.random.default_rng(3)
    jac = s.bound("jac")
    for _ in range(3):
        y = rng.uniform(0.3, 1.2, 2 * s.n)
        k = rng.uniform(0.5, 2.0, len(s.parameter_names))
        J = np.empty(4 * s.n * s.n)
        jac(0.5, y, k, J)
        J = J.reshape(2 * s.n, 2 * s.n)
        differences = central_differences(lambda x: s.f(0.5, x, k), y, 1e-6)  # noqa: B023 - used at once
        np.testing.assert_allclose(J, differences, rtol=1e-6, atol=1e-6 * np.abs(differences).max())
        assert np.any(J != 0.0)


@njit(RHS_SIG, cache=True)
def robertson(t, y, k, out):
    # Robertson's chemical kinetics: A -> B (0.04), B + B -> C + B (3e7), B + C -> A + C (1e4)
    out[0] = -0.04 * y[0] + 1.0e4 * y[1] * y[2]
    out[1] = 0.04 * y[0] - 1.0e4 * y[1] * y[2] - 3.0e7 * y[1] * y[1]
    out[2] = 3.0e7 * y[1] * y[1]


@njit(RHS_SIG, cache=True)
def robertson_jacobian(t, y, k, out):
    out[0], out[1], out[2] = -0.04, 1.0e4 * y[2], 1.0e4 * y[1]
    out[3], out[4], out[5] = 0.04, -1.0e4 * y[2] - 6.0e7 * y[1], -1.0e4 * y[1]
    out[6], out[7], out[8] = 0.0, 6.0e7 * y[1], 0.0


def run_kernel(f, jac, has_jac, y0, t_out, rtol, atol):
    y, fy, st = y0.copy(), np.empty(y0.size), np.zeros(radau.STATE_SIZE)
    Y, J, Q = np.empty((t_out.size, y0.size)), np.empty((y0.size, y0.size)), np.zeros((4, y0.size))
    status = RUNNING
    while status == RUNNING:  # in chunks of 50 steps: resuming must not change the result
        status = radau.run(f, jac, has_jac, np.zeros(1), t_out, rtol, atol, np.full(y0.size, 1e8), 50,
                           y, fy, st, Y, J, Q)  # fmt: skip
    assert status == DONE
    return Y, st


@pytest.mark.slow
def test_robertson_against_a_tight_scipy_radau():
    """Robertson's kinetics to t = 1e5 (rates 0.04 to 3e7): the compiled kernel at rtol 1e-7 against scipy's
    Radau at rtol 1e-12; the concentrations sum to 1 throughout."""
    t_out = np.concatenate([[0.0], np.logspace(-5, 5, 41)])
    y0 = np.array([1.0, 0.0, 0.0])
    atol = np.array([1e-10, 1e-14, 1e-10])
    f, jac = Bound(robertson, RHS_SIG), Bound(robertson_jacobian, RHS_SIG)
    Y, st = run_kernel(f, jac, 1, y0, t_out, 1e-7, atol)

    def rhs(t, y):
        return [-0.04 * y[0] + 1e4 * y[1] * y[2], 0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2, 3e7 * y[1] ** 2]

    reference = solve_ivp(rhs, (0.0, t_out[-1]), y0, method="Radau", t_eval=t_out, rtol=1e-12, atol=atol * 1e-4)
    assert reference.success
    # in units of the tolerance asked for, atol + rtol |y|, at every sample
    relative = np.abs(Y - reference.y.T) / (atol + 1e-7 * np.abs(reference.y.T))
    assert relative.max() < 10.0, relative.max(axis=0)
    assert np.abs(Y.sum(axis=1) - 1.0).max() < 1e-9
    assert st[radau.STEPS] < 1000
    # the same run on differenced Jacobians
    Y_fd, _ = run_kernel(f, f, 0, y0, t_out, 1e-7, atol)
    assert (np.abs(Y_fd - reference.y.T) / (atol + 1e-7 * np.abs(reference.y.T))).max() < 10.0


@pytest.mark.slow
def test_auto_estimate_bounds_the_true_error(two_modes):
    """auto on a stiff start (the fast mode quiet) picks the compiled Radau, and its reported error estimate
    (the compiled Radau again, 1000x tighter) is above the true error and not far above it."""
    y0 = np.array([1.0, 0.0, 0.0, 0.0])
    out = simulate(two_modes, K_TWO, y0, 10.0, 201, rtol=1e-6, atol=1e-9)
    assert out.method == STIFF and out.path == "compiled" and STIFF in out.estimate.reference
    true = np.abs(out.trajectory.y[:, :2] - exact_two_modes(y0, out.trajectory.t)[:, :2]).max()
    assert true <= out.estimate.value <= 1000 * true
