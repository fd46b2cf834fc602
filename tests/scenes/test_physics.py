"""Physics checks that do not follow the engine's own path (Newton's laws, hand derivations)."""

import pytest
import sympy as sp

from app.engine.derivation.derive import substitute_cyclic
from app.service.chapter.derivations import derivation
from tests.scenes.common import S, along_motion, close, force, transformed

m, M, g, R, k, b, alpha, omega = (S(n) for n in ("m", "M", "g", "R", "k", "b", "alpha", "omega"))
m1, m2, l0 = S("m1"), S("m2"), S("l0")
theta, theta_dot, phi_dot = S("theta"), S("theta_dot"), S("phi_dot")


def same(a, b):
    return sp.simplify(a - b) == 0


@pytest.mark.slow
def test_simple_pendulum_tension():
    # radial Newton's law with the string along -r_hat: T - m g cos(theta) = m R theta_dot^2
    assert same(force("simple-pendulum", "string tension"), m * R * theta_dot**2 + m * g * sp.cos(theta))


@pytest.mark.slow
def test_damped_pendulum_loses_energy_at_the_rate_of_the_drag():
    d = derivation("damped-pendulum")
    # dE/dt = Q theta_dot = -b theta_dot^2
    assert same(along_motion("damped-pendulum", d.energetics.energy), -b * theta_dot**2)
    # the drag acts along the path, so the string's tension is the undamped one
    assert same(force("damped-pendulum", "string tension"), force("simple-pendulum", "string tension"))


def test_the_damped_pendulums_stated_drag_is_the_engines_generalized_force():
    from app.scenes import SCENES

    statement = SCENES["damped-pendulum"].statement
    # the statement's model: a torque −b θ̇ about the pivot with b fixed, a force of magnitude (b/R)|θ̇| on the
    # bob against its motion; never a coefficient b/R² that the length slider would change (prof-l 6)
    assert "torque about the pivot is −b θ̇" in statement and "(b/R) |θ̇|" in statement and "R²) v" not in statement
    d = derivation("damped-pendulum")
    (position,) = d.mechanics.positions
    tangent = sp.Matrix([sp.diff(c, theta) for c in position])  # ∂r/∂θ, of length R along the path
    # the stated force: magnitude (b/R) θ̇ along −∂r/∂θ / R; its virtual work per δθ is Q_θ = F · ∂r/∂θ
    force_on_bob = -(b / R) * theta_dot * tangent / R
    assert same(force_on_bob.dot(tangent), d.mechanics.Q[0]) and same(d.mechanics.Q[0], -b * theta_dot)


@pytest.mark.slow
@pytest.mark.parametrize("theta0", [1.9, 2.3, 2.8])
def test_conical_pendulum(theta0):
    """Steady circling at theta0 (below the pivot): Newton fixes the rate, the engine's U_eff is flat there."""
    d = derivation("spherical-pendulum")
    point = {"m": 0.7, "g": 9.81, "R": 1.3}
    th0 = sp.Float(theta0)
    # Newton: T sin(th0) = m R sin(th0) Omega^2 horizontally, -T cos(th0) = m g vertically
    Omega2 = -point["g"] / (point["R"] * sp.cos(th0))
    tension = point["m"] * point["R"] * Omega2
    p_phi = point["m"] * point["R"] ** 2 * sp.sin(th0) ** 2 * sp.sqrt(Omega2)
    red = d.reduction
    at = {"theta": th0, "p_phi": p_phi, **point}
    # U_eff'(theta0) = 0 for this p_phi
    assert close(red.equilibrium_condition, 0, at, tol=1e-9)
    # and the steady motion is stable: U_eff'' > 0
    assert float(sp.N(red.omega_squared_at.xreplace({S(k): v for k, v in at.items()}))) > 0
    # the engine's tension in that motion is Newton's
    state = {"theta": th0, "theta_dot": 0.0, "phi_dot": sp.sqrt(Omega2), **point}
    assert close(force("spherical-pendulum", "string tension"), tension, state)


@pytest.mark.slow
def test_spherical_pendulum_tension():
    expected = m * R * (theta_dot**2 + sp.sin(theta) ** 2 * phi_dot**2) - m * g * sp.cos(theta)
    assert same(force("spherical-pendulum", "string tension"), expected)


@pytest.mark.slow
def test_helix_bead():
    d = derivation("helix-bead")
    # along the wire s = z sqrt(1 + R^2 alpha^2), gravity's share is g / sqrt(1 + R^2 alpha^2)
    assert same(d.equations.accelerations[0], -g / (1 + R**2 * alpha**2))
    z_dot = S("z_dot")
    # the turning bead needs m R (alpha z_dot)^2 toward the axis ...
    assert same(force("helix-bead", "wire force toward the axis"), m * R * alpha**2 * z_dot**2)
    # ... and the wire holds up what the slope does not take, perpendicular to itself
    expected = m * g * alpha * R / sp.sqrt(1 + alpha**2 * R**2)
    assert same(force("helix-bead", "wire force across the helix"), expected)


@pytest.mark.slow
def test_incline_block():
    d = derivation("incline-block")
    assert same(d.equations.accelerations[0], -g * sp.sin(alpha))
    assert same(force("incline-block", "normal force"), m * g * sp.cos(alpha))


@pytest.mark.slow
def test_movable_incline_against_newton():
    d = derivation("movable-incline")
    A, xb, zb, N = sp.symbols("A xb zb N")
    # Newton for the wedge and the block, and the block staying on the slope (twice differentiated)
    solution = sp.solve(
        [
            M * A + N * sp.sin(alpha),
            m * xb - N * sp.sin(alpha),
            m * zb - N * sp.cos(alpha) + m * g,
            (xb - A) * sp.sin(alpha) + zb * sp.cos(alpha),
        ],
        [A, xb, zb, N],
        dict=True,
    )[0]
    X_dd, D_dd = d.equations.accelerations
    assert same(X_dd, solution[A])
    # D is measured along the slope: x_block - X = D cos(alpha)
    assert same(D_dd, (solution[xb] - solution[A]) / sp.cos(alpha))
    # the known closed forms
    assert same(X_dd, -m * g * sp.sin(alpha) * sp.cos(alpha) / (M + m * sp.sin(alpha) ** 2))
    assert same(D_dd, (M + m) * g * sp.sin(alpha) / (M + m * sp.sin(alpha) ** 2))
    assert same(force("movable-incline", "normal force on the block"), solution[N])
    assert same(force("movable-incline", "floor force on the wedge"), M * g + solution[N] * sp.cos(alpha))


@pytest.mark.slow
def test_pulley_against_newton():
    d = derivation("pulley")
    a1, a2, T = sp.symbols("a1 a2 T")
    # each end mass: T up, weight down; the movable pulley: 2T up; the string: A = -(a1 + a2)/2
    solution = sp.solve(
        [m1 * a1 - T + m1 * g, m2 * a2 - T + m2 * g, M * (-(a1 + a2) / 2) - 2 * T + M * g],
        [a1, a2, T],
        dict=True,
    )[0]
    y1_dd, y2_dd = d.equations.accelerations
    assert same(y1_dd, solution[a1]) and same(y2_dd, solution[a2])
    assert same(force("pulley", "string tension"), solution[T])
    # balanced case: m1 = m2 = M/2 stays at rest with T = m1 g
    balanced = {m2: m1, M: 2 * m1}
    assert sp.simplify(y1_dd.subs(balanced)) == 0
    assert same(force("pulley", "string tension").subs(balanced), m1 * g)


@pytest.mark.slow
def test_rail_two_body_reduced_mass():
    d = derivation("rail-two-body")
    x1, x2 = S("x1"), S("x2")
    a1, a2 = d.equations.accelerations
    mu = m1 * m2 / (m1 + m2)
    # total momentum conserved: m1 a1 + m2 a2 = 0; separation: mu (a2 - a1) = -k (x2 - x1 - l0)
    assert same(m1 * a1 + m2 * a2, 0)
    assert same(mu * (a2 - a1), -k * (x2 - x1 - l0))
    tr = transformed("rail-two-body")
    new = tr.derivation
    X_dd, x_dd = new.equations.accelerations
    assert new.energetics.cyclic == ("X",)
    assert X_dd == 0 and same(x_dd, -k * (S("x") - l0) / mu)
    assert same(tr.reduced_mass, mu) and tr.decoupled
    p_X = next(c for c in new.energetics.conserved if c.name == "p_X")
    assert same(tr.to_original(p_X.expr), m1 * S("x1_dot") + m2 * S("x2_dot"))
    # the relative coordinate oscillates about l0 at omega^2 = k / mu
    (eq,) = new.reduction.equilibria
    assert same(eq.position, l0) and same(eq.omega_squared, k / mu)


@pytest.mark.slow
def test_tabletop_reduction():
    d = derivation("tabletop-spring")
    red = d.reduction
    r, r_dot, P, E_r = S("r"), S("r_dot"), S("p_theta"), S("E_r")
    assert d.energetics.cyclic == ("theta",)
    assert same(next(c.expr for c in d.energetics.conserved if c.name == "p_theta"), m * r**2 * S("theta_dot"))
    U_eff = P**2 / (2 * m * r**2) + k * r**2 / 2
    assert same(red.effective_potential, U_eff) and same(red.effective_mass, m)
    # energy first integral: E with theta_dot = p / (m r^2) is m r_dot^2 / 2 + U_eff
    assert same(substitute_cyclic(d.energetics.energy, red), red.radial_energy)
    assert same(red.radial_energy, m * r_dot**2 / 2 + U_eff)
    # time as an integral: dt = dr / r_dot(r)
    assert same(red.time_integral.function, 1 / sp.sqrt(2 * (E_r - U_eff) / m))
    # circular orbit (Newton: m r Omega^2 = k r and p = m r^2 Omega) and its radial oscillation:
    # x = a cos(Omega t), y = b sin(Omega t) makes r^2 oscillate at 2 Omega, so omega^2 = 4 k / m
    (orbit,) = red.equilibria
    assert same(orbit.position**4, P**2 / (m * k))
    assert same(orbit.omega_squared, 4 * k / m) and orbit.stable


@pytest.mark.slow
def test_rotating_parabola_h_conserved_energy_not():
    d = derivation("rotating-parabola")
    en = d.energetics
    rho, rho_dot = S("rho"), S("rho_dot")
    assert not en.h_equals_e
    # dh/dt = 0 along the motion, dE/dt does not vanish
    assert same(along_motion("rotating-parabola", en.hamiltonian), 0)
    dE = along_motion("rotating-parabola", en.energy)
    assert not same(dE, 0)
    # E - h = p . dr/dt|q = m omega^2 rho^2 (the wire's velocity is omega rho along phi_hat)
    assert same(en.energy_minus_h, m * omega**2 * rho**2)
    # the energy changes by the work of the wire's sideways push, whose point moves at omega rho
    assert same(force("rotating-parabola", "wire force across its plane"), 2 * m * omega * rho_dot)
    assert same(dE, force("rotating-parabola", "wire force across its plane") * omega * rho)
    # the equilibrium at the bottom is stable when omega^2 < 2 g alpha
    (bottom,) = d.reduction.equilibria
    assert bottom.position == 0 and same(bottom.omega_squared, 2 * g * alpha - omega**2)


def test_coupled_oscillators_beat_at_the_difference_of_the_mode_frequencies():
    import numpy as np

    from app.numerics.simulate import simulate
    from app.numerics.system import numeric_system
    from app.scenes import SCENES

    s = SCENES["coupled-oscillators"]
    # by hand: in phase omega1² = k/m, in opposition omega2² = (k + 2 kappa)/m
    m_, k_, kappa = 1.0, 10.0, 1.0
    w1, w2 = np.sqrt(k_ / m_), np.sqrt((k_ + 2 * kappa) / m_)
    beat = np.pi / (w2 - w1)  # the time for the motion to pass from x1 to x2
    y0 = np.array([s.initial[n] for n in ("x1", "x2", "x1_dot", "x2_dot")])
    run = simulate(
        numeric_system(derivation("coupled-oscillators")),
        np.array([m_, k_, kappa, 1.0]),
        y0,
        2 * beat,
        4001,
        "DOP853-compiled",
        estimate=False,
    ).trajectory
    # x1 = a cos((w2 - w1) t/2) cos((w1 + w2) t/2), x2 = a sin((w2 - w1) t/2) sin((w1 + w2) t/2)
    a, t = y0[0], run.t
    assert np.allclose(run.y[:, 0], a * np.cos((w2 - w1) * t / 2) * np.cos((w1 + w2) * t / 2), atol=1e-6)
    assert np.allclose(run.y[:, 1], a * np.sin((w2 - w1) * t / 2) * np.sin((w1 + w2) * t / 2), atol=1e-6)
    # about one carrier period around the beat time: x1 nearly still, x2 swinging with all the amplitude
    near = np.abs(t - beat) < np.pi / (w1 + w2) * 2
    assert np.abs(run.y[near, 0]).max() < 0.2 * a and np.abs(run.y[near, 1]).max() > 0.95 * a
