"""The action S(ε): closed forms for the harmonic oscillator, independent quadratures for the pendulum and the
tabletop spring, the conjugate time and the change of kind as T passes it."""

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from app.engine.derivation.derive import derive
from app.numerics.action import action_of, action_terms, conjugate_time
from app.numerics.system import numeric_system
from app.scenes.types import Parameter, System
from app.service.chapter.derivations import derivation

M, W = 2.0, 3.0
OSCILLATOR = System(
    coordinates=("x",),
    parameters=(Parameter("m", M), Parameter("w", W)),
    lagrangian="m*x_dot**2/2 - m*w**2*x**2/2",
)


@pytest.fixture(scope="module")
def oscillator():
    return numeric_system(derive(OSCILLATOR))


@pytest.fixture(scope="module")
def pendulum():
    return numeric_system(derivation("simple-pendulum"))


@pytest.mark.parametrize(("T", "k"), [(0.7, 1), (2.0, 1), (2.0, 3), (5.0, 2)])
def test_oscillator_action_is_exactly_quadratic(oscillator, T, k):
    eps = [-0.4, -0.1, 0.0, 0.05, 0.3]
    r = action_of(oscillator, np.array([M, W]), np.array([0.7, 0.4]), T, 0, k, eps)
    # S(ε) - S(0) = ε² (m/2)(T/2)((kπ/T)² - ω²): the cross term ∫ (m q̇ η' - m ω² q η) dt vanishes on the true path
    a = (M / 2) * (T / 2) * ((k * math.pi / T) ** 2 - W**2)
    for e, S in zip(eps, r.action, strict=True):
        assert S - r.true == pytest.approx(e**2 * a, rel=1e-9, abs=1e-12)
    assert r.second_variation == pytest.approx(2 * a, rel=1e-9)
    assert abs(r.first_variation) < 1e-9
    # the true S(0) by its closed form: x = A cos ωt + B sin ωt, L = m/2 (ẋ² - ω² x²)
    A, B = 0.7, 0.4 / W
    exact, _ = quad(
        lambda t: M / 2 * ((W * (B * math.cos(W * t) - A * math.sin(W * t))) ** 2
                           - W**2 * (A * math.cos(W * t) + B * math.sin(W * t)) ** 2),
        0, T, epsabs=1e-13, epsrel=1e-12,
    )  # fmt: skip
    assert r.true == pytest.approx(exact, rel=1e-8)
    assert abs(r.true - exact) < max(r.error_estimate, 1e-13)


def test_oscillator_conjugate_time_and_kind(oscillator):
    k, y0 = np.array([M, W]), np.array([0.7, 0.4])
    before = action_of(oscillator, k, y0, math.pi / W - 0.02, 0, 1, [])
    after = action_of(oscillator, k, y0, math.pi / W + 0.02, 0, 1, [])
    assert before.conjugate_time is None and before.kind == "minimum"
    assert after.conjugate_time == pytest.approx(math.pi / W, rel=1e-8)
    assert after.kind == "saddle" and after.second_variation < 0 < before.second_variation
    long = action_of(oscillator, k, y0, 2.5 * math.pi / W, 0, 1, [])
    assert long.conjugate_time == pytest.approx(math.pi / W, rel=1e-8)  # the first one, not the second


def test_small_pendulum_conjugate_time_is_half_its_period(pendulum):
    g, R = 9.81, 1.0
    r = action_of(pendulum, np.array([1.0, g, R]), np.array([1e-3, 0.0]), 1.5, 0, 1, [])
    assert r.conjugate_time == pytest.approx(math.pi * math.sqrt(R / g), rel=1e-6)
    assert r.kind == "saddle"


def _pendulum_L(t, y, m=1.0, g=9.81, R=1.0):
    return m * R**2 * y[1] ** 2 / 2 - m * g * R * (1 - math.cos(y[0]))


def _independent(rhs, L, y0, T, eta_of, c, eps):
    """scipy's DOP853 at rtol 1e-13 with its own dense output, and adaptive Gauss-Kronrod (quad)."""
    sol = solve_ivp(rhs, (0, T), y0, method="DOP853", rtol=1e-13, atol=1e-14, dense_output=True)
    n = len(y0) // 2

    def integrand(t):
        y = sol.sol(t).copy()
        eta, deta = eta_of(t)
        y[c] += eps * eta
        y[n + c] += eps * deta
        return L(t, y)

    value, _ = quad(integrand, 0, T, limit=400, epsabs=1e-12, epsrel=1e-11)
    return value


@pytest.mark.parametrize("eps", [0.0, 0.3, -0.5])
def test_large_pendulum_against_an_independent_quadrature(pendulum, eps):
    T, k = 1.7, 2
    y0 = np.array([2.8, 0.0])

    def rhs(t, y):
        return [y[1], -9.81 * math.sin(y[0])]

    def eta_of(t):
        w = k * math.pi / T
        return math.sin(w * t), w * math.cos(w * t)

    r = action_of(pendulum, np.array([1.0, 9.81, 1.0]), y0, T, 0, k, [eps])
    expected = _independent(rhs, _pendulum_L, y0, T, eta_of, 0, eps)
    assert r.action[0] == pytest.approx(expected, rel=1e-8)


@pytest.mark.slow
def test_tabletop_spring_against_an_independent_quadrature():
    system = numeric_system(derivation("tabletop-spring"))
    m, kk = 1.0, 4.0
    y0 = np.array([1.0, 0.0, 0.3, 1.0])  # r, theta, r_dot, theta_dot
    T, k, eps = 3.0, 1, 0.2

    def rhs(t, y):
        r, th, rd, thd = y
        return [rd, thd, r * thd**2 - kk / m * r, -2 * rd * thd / r]

    def L(t, y):
        return m * (y[2] ** 2 + y[0] ** 2 * y[3] ** 2) / 2 - kk * y[0] ** 2 / 2

    def eta_of(t):
        w = k * math.pi / T
        return math.sin(w * t), w * math.cos(w * t)

    for c in (0, 1):
        r = action_of(system, np.array([m, kk]), y0, T, c, k, [eps, 0.0])
        assert r.action[0] == pytest.approx(_independent(rhs, L, y0, T, eta_of, c, eps), rel=1e-8)
        assert r.action[1] == pytest.approx(_independent(rhs, L, y0, T, eta_of, c, 0.0), rel=1e-8)
        assert abs(r.first_variation) < 1e-7 * abs(r.true)


def test_jacobi_matrix_of_two_uncoupled_oscillators_is_singular_at_the_first_focus():
    # P = 1, C = 0, R = -diag(ω²): J = diag(sin ω_i t / ω_i), det J = 0 first at π / max ω
    t = np.linspace(0.0, 2.0, 4 * 512 + 1)
    ones = np.ones_like(t)
    P = np.array([[ones, 0 * ones], [0 * ones, ones]])
    C = np.zeros_like(P)
    R = -np.array([[4.0 * ones, 0 * ones], [0 * ones, 9.0 * ones]])
    assert conjugate_time(t, P, C, R) == pytest.approx(math.pi / 3, rel=1e-9)


def test_browser_lagrangian_is_the_engine_L(oscillator):
    source = action_terms(oscillator).browser
    assert "return _L;" in source and "Math.pow" in source
    assert "x" not in source.replace("Math", "").replace("k0", "").replace("max", "")


def test_jacobi_fields_of_two_equal_oscillators_touch_zero_together():
    # P = 1, C = 0, R = -ω² 1: J = (sin ωt / ω) 1, det J = sin² ωt / ω² ≥ 0 touches 0 at π/ω without changing sign
    w = 2.0
    t = np.linspace(0.0, 2.5, 4 * 512 + 1)
    ones, zeros = np.ones_like(t), np.zeros_like(t)
    P = np.array([[ones, zeros], [zeros, ones]])
    R = -(w**2) * P
    assert conjugate_time(t, P, np.zeros_like(P), R) == pytest.approx(math.pi / w, rel=1e-8)


def _cyclotron(wc: float, T: float) -> tuple[np.ndarray, ...]:
    """L = ½(ẋ² + ẏ²) + (ω_c/2)(x ẏ − y ẋ): P = 1, C_xẏ = ω_c/2, C_yẋ = −ω_c/2, R = 0 (m = qB/ω_c = 1)."""
    t = np.linspace(0.0, T, 4 * 512 + 1)
    ones, zeros = np.ones_like(t), np.zeros_like(t)
    P = np.array([[ones, zeros], [zeros, ones]])
    C = np.array([[zeros, wc / 2 * ones], [-wc / 2 * ones, zeros]])
    return t, P, C, np.zeros_like(P)


def test_cyclotron_focus_where_every_jacobi_field_vanishes():
    # every path from a point returns to it after one turn, 2π/ω_c; det J = 2(1 − cos ω_c t)/ω_c² never goes negative
    wc = 2.0
    assert conjugate_time(*_cyclotron(wc, 4.0)) == pytest.approx(2 * math.pi / wc, rel=1e-8)
    assert conjugate_time(*_cyclotron(wc, 3.0)) is None  # before the focus: no minimum of |det J| is a zero


def test_magnetron_focus_with_an_outward_spring():
    # add -½κ(x² + y²) to L (R = κ 1): with z = x + iy, z̈ + iω_c ż - κz = 0 has the roots -i(ω_c ∓ s)/2,
    # s = √(ω_c² - 4κ), so the fields from 0 are ∝ e^{-iω_c t/2} sin(st/2): they all return to 0 at 2π/s
    wc, kappa = 2.0, 0.05
    t, P, C, _ = _cyclotron(wc, 4.0)
    found = conjugate_time(t, P, C, kappa * P)
    assert found == pytest.approx(2 * math.pi / math.sqrt(wc**2 - 4 * kappa), rel=1e-8)


COUPLED = System(
    coordinates=("x", "y"),
    parameters=(Parameter("w", 2.0), Parameter("c", 0.5)),
    lagrangian="(x_dot**2 + y_dot**2)/2 - w**2*(x**2 + y**2)/2 - c*x*y",
)


@pytest.mark.slow
def test_the_varied_coordinate_alone_has_its_own_focus():
    # L = ½(ẋ² + ẏ²) − ½ω²(x² + y²) − c x y: the normal modes x ± y have ω² ± c, so all variations together reach
    # their first focus at π/√(ω² + c); varying x alone (y kept on the true path) the Jacobi equation is
    # η″ = −ω² η, whose focus is π/ω, later (prof-e 17: the two foci were one number on the page)
    system = numeric_system(derive(COUPLED))
    r = action_of(system, np.array([2.0, 0.5]), np.array([0.3, -0.2, 0.1, 0.4]), 2.0, 0, 1, [])
    assert r.conjugate_time == pytest.approx(math.pi / math.sqrt(4.5), rel=1e-7)
    assert r.varied_conjugate_time == pytest.approx(math.pi / 2.0, rel=1e-7)
    # before x's own focus, past the one of both together: a minimum among the variations of x alone
    between = action_of(system, np.array([2.0, 0.5]), np.array([0.3, -0.2, 0.1, 0.4]), 1.53, 0, 1, [])
    assert between.conjugate_time is not None and between.varied_conjugate_time is None
    assert between.kind == "minimum"
