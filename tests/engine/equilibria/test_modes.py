"""Equilibria and normal modes: M, K and omega^2 against sympy.physics.mechanics, and measured frequencies."""

from functools import cache

import numpy as np
import pytest
import scipy.linalg
import sympy as sp
import sympy.physics.mechanics as me

from app.engine.derivation.derive import derive
from app.engine.document.contract import held_momenta
from app.engine.equilibria.equilibrium import defaults
from app.engine.equilibria.modes import NEUTRAL, STABLE, UNSTABLE, _at_rest, normal_modes
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from app.scenes import SCENES
from tests.cases import case_list
from tests.engine import systems
from tests.engine.systems import TEST_SYSTEMS
from tests.reference import lagranges_method

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

SYSTEMS = {**{f"scene:{k}": s.system for k, s in SCENES.items()}, **TEST_SYSTEMS}


@cache
def derived(name):
    return derive(SYSTEMS[name])


@cache
def modes(name):
    d = derived(name)
    scene = SCENES.get(name.removeprefix("scene:")) if name.startswith("scene:") else None
    return normal_modes(d.system, d.mechanics, d.equations, d.reduction, held_momenta(d, scene))


@cache
def linearizer(name):
    lm, qs, _ = lagranges_method(SYSTEMS[name])
    t = me.dynamicsymbols._t
    return lm.to_linearizer(q_ind=qs, qd_ind=[q.diff(t) for q in qs]), qs


def reference_matrices(name, position):
    """M and K at an equilibrium from LagrangesMethod's linearizer (operating point q0, q_dot = 0)."""
    system = SYSTEMS[name]
    lin, qs = linearizer(name)
    t = me.dynamicsymbols._t
    op = {q: position[n] for q, n in zip(qs, system.coordinates, strict=True)}
    # at rest, and (the linearizer's surprise away from q = 0) with q_ddot = 0: otherwise terms
    # dM/dq q_ddot stay in its A matrix
    op.update({q.diff(t): 0 for q in qs})
    op.update({q.diff(t, 2): 0 for q in qs})
    M, A, _ = lin.linearize(op_point=op)
    n = len(qs)
    # M [q_dot, q_ddot] = A [q, q_dot]: the lower blocks are the mass matrix and -K
    return M[n:, n:], -A[n:, :n]


def numbers(matrix, values):
    # (a moving constraint leaves sin²(ωt) + cos²(ωt) in the reference: any t will do)
    subs = {sp.Symbol(s.name, real=True): v for s, v in values.items()} | {me.dynamicsymbols._t: 0.37}
    return np.array(matrix.xreplace(subs).evalf(), dtype=float)


# (system, equilibrium) for each equilibrium the engine finds (the list kept on disk between runs: tests/cases.py)
EQUILIBRIA = case_list(
    "modes-equilibria",
    lambda: [(name, i) for name in sorted(SYSTEMS) for i, e in enumerate(modes(name).equilibria) if not e.momenta],
    __file__,
    systems.__file__,
)


def test_every_system_with_a_fixed_point_has_one():
    with_equilibria = {name for name, _ in EQUILIBRIA}
    assert {
        "scene:simple-pendulum",
        "scene:damped-pendulum",
        "scene:rail-two-body",
        "scene:rotating-parabola",
        "scene:double-pendulum",
        "scene:coupled-oscillators",
        "double-pendulum",
        "damped-spring",
        "lagrangian-only",
        "charge-in-field",
        "spring-chain",
    } <= with_equilibria
    # no equilibrium where gravity or a slope always pulls
    for name in ("scene:helix-bead", "scene:incline-block", "scene:pulley", "scene:movable-incline"):
        assert not modes(name).equilibria and modes(name).note


@pytest.mark.parametrize(("name", "index"), EQUILIBRIA)
def test_mass_stiffness_and_frequencies_match_the_linearizer(name, index):
    d = derived(name)
    e = modes(name).equilibria[index]
    values = defaults(d.system, d.table)
    M_ref, K_ref = reference_matrices(name, e.position)
    M, K = numbers(e.mass, values), numbers(e.stiffness, values)
    assert np.allclose(M, numbers(M_ref, values), rtol=1e-9, atol=1e-12), (M, M_ref)
    assert np.allclose(K, numbers(K_ref, values), rtol=1e-9, atol=1e-9), (K, K_ref)
    # omega^2: the generalized eigenvalues of the reference K relative to the reference M
    expected = np.sort(scipy.linalg.eigvals(numbers(K_ref, values), numbers(M_ref, values)).real)
    ours = np.sort([m.omega_squared for m in e.modes])
    assert np.allclose(ours, expected, rtol=1e-8, atol=1e-9), (ours, expected)
    for m in e.modes:
        # each shape solves (K - omega^2 M) a = 0
        a = np.array(m.shape)
        assert np.abs((K - m.omega_squared * M) @ a).max() <= 1e-8 * max(1.0, np.abs(K).max())
        assert np.isclose(np.abs(a).max(), 1.0)
        if m.exact is not None:
            assert float(m.exact.xreplace({sp.Symbol(s.name, real=True): v for s, v in values.items()})) == (
                pytest.approx(m.omega_squared, rel=1e-9, abs=1e-12)
            )
    signs = [m.omega_squared for m in e.modes]
    kind = UNSTABLE if min(signs) < -1e-9 else (NEUTRAL if min(abs(w) for w in signs) < 1e-9 else STABLE)
    assert e.kind == kind and e.stable == (kind != UNSTABLE)


def test_the_double_pendulum_has_four_equilibria_one_stable():
    found = modes("scene:double-pendulum").equilibria
    at = {(round(e.position["theta1"], 9), round(e.position["theta2"], 9)): e for e in found}
    pi = round(np.pi, 9)
    assert set(at) == {(0.0, 0.0), (0.0, pi), (pi, 0.0), (pi, pi)}
    assert at[(0.0, 0.0)].kind == STABLE
    assert all(at[p].kind == UNSTABLE for p in ((0.0, pi), (pi, 0.0), (pi, pi)))
    # both upside down: both directions unstable; one bob up: one of each
    assert sum(m.omega_squared < 0 for m in at[(pi, pi)].modes) == 2
    assert sum(m.omega_squared < 0 for m in at[(0.0, pi)].modes) == 1
    # at the bottom, equal masses and lengths: omega^2 = (2 -+ sqrt 2) g / l
    g = 9.81
    assert sorted(m.omega_squared for m in at[(0.0, 0.0)].modes) == pytest.approx(
        [(2 - np.sqrt(2)) * g, (2 + np.sqrt(2)) * g], rel=1e-12
    )


def test_the_rail_translation_is_neutral_and_the_spring_mode_is_k_over_mu():
    (e,) = modes("scene:rail-two-body").equilibria
    assert e.kind == NEUTRAL and e.stable
    zero, spring = sorted(e.modes, key=lambda m: m.omega_squared)
    assert zero.omega_squared == pytest.approx(0.0, abs=1e-12) and zero.shape == pytest.approx((1.0, 1.0))
    m1, m2, k = 1.0, 2.0, 10.0
    assert spring.omega_squared == pytest.approx(k * (m1 + m2) / (m1 * m2), rel=1e-12)
    names = {s.name: s for s in spring.exact.free_symbols}
    mu = names["m1"] * names["m2"] / (names["m1"] + names["m2"])
    assert sp.simplify(spring.exact - names["k"] / mu) == 0


def test_coordinate_singularities_are_reported_not_linearized():
    nm = modes("scene:spherical-pendulum")
    # theta = 0 and pi: the poles, where M = diag(m R², m R² sin²θ) is singular
    assert sorted(p["theta"] for p in nm.singular) == pytest.approx([0.0, np.pi])


def test_the_conical_pendulum_is_a_steady_motion_of_the_reduction():
    d = derived("scene:spherical-pendulum")
    # the cone at theta0, once: its mirror image at -theta0 is the same motion with phi + pi
    (e,) = modes("scene:spherical-pendulum").equilibria
    assert e.momenta and e.coordinates == ("theta",) and e.kind == STABLE
    theta0 = e.position["theta"]
    m, g, R = 1.0, 9.81, 1.0
    p = e.momenta["p_phi"]
    # U_eff'(theta0) = 0 with U_eff = p²/(2 m R² sin²θ) + m g R cos θ
    assert -(p**2) * np.cos(theta0) / (m * R**2 * np.sin(theta0) ** 3) - m * g * R * np.sin(theta0) == pytest.approx(
        0.0, abs=1e-9
    )
    assert np.pi / 2 < theta0 < np.pi  # below the pivot
    assert d.reduction is not None


def test_the_tabletop_circular_orbit_has_omega_twice_the_orbital_rate():
    (e,) = modes("scene:tabletop-spring").equilibria
    assert e.momenta == {"p_theta": pytest.approx(1.0)}
    assert e.modes[0].omega_squared == pytest.approx(4 * 4.0 / 1.0)
    assert str(e.modes[0].exact) == "4*k/m"


def test_velocity_terms_are_flagged():
    assert modes("charge-in-field").damped and modes("damped-spring").damped and modes("scene:damped-pendulum").damped
    assert not modes("scene:double-pendulum").damped and not modes("spring-chain").damped


def _period(t, x):
    """Mean period from upward zero crossings, linearly interpolated."""
    up = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    times = t[up] - x[up] * (t[up + 1] - t[up]) / (x[up + 1] - x[up])
    return (times[-1] - times[0]) / (len(times) - 1)


def _small_runs():
    cases = []
    for name, index in EQUILIBRIA:
        e = modes(name).equilibria[index]
        # damping and gyroscopic terms shift the frequencies, which leave them out (and say so)
        if e.kind != STABLE or modes(name).damped:
            continue
        cases += [(name, index, j) for j in range(len(e.modes))]
    cases += [("scene:spherical-pendulum", 0, 0), ("scene:tabletop-spring", 0, 0)]  # the cone, listed once
    return cases


@pytest.mark.slow  # compiles each system's right-hand side on first use
@pytest.mark.parametrize(
    ("name", "index", "mode"), case_list("modes-small-runs", _small_runs, __file__, systems.__file__)
)
def test_small_amplitude_runs_oscillate_at_the_predicted_frequency(name, index, mode):
    d = derived(name)
    e = modes(name).equilibria[index]
    m = e.modes[mode]
    table = d.table
    values = defaults(d.system, d.table)
    k = np.array([values[s] for s in table.params])
    n = len(table.names)
    y0 = np.zeros(2 * n)
    amplitude = 1e-4
    for i, q in enumerate(table.names):
        y0[i] = e.position.get(q, 0.0)
    for name_q, a in zip(e.coordinates, m.shape, strict=True):
        y0[table.names.index(name_q)] += amplitude * a
    if e.momenta:
        # the cyclic velocities that hold each conserved momentum at its value
        red = d.reduction
        at = {**values, **{sp.Symbol(p, real=True): v for p, v in e.momenta.items()}}
        at.update({q: y0[i] for i, q in enumerate(table.q)})
        for velocity, expr in red.cyclic_velocities.items():
            y0[n + table.qd.index(velocity)] = float(expr.xreplace(at))
    omega = np.sqrt(m.omega_squared)
    t_end = 20 * 2 * np.pi / omega
    outcome = simulate(numeric_system(d), k, y0, t_end, 4000, "DOP853-compiled", rtol=1e-11, atol=1e-14, estimate=False)
    i = table.names.index(e.coordinates[int(np.argmax(np.abs(m.shape)))])
    x = outcome.trajectory.y[:, i] - e.position[table.names[i]]
    measured = 2 * np.pi / _period(outcome.trajectory.t, x)
    assert measured == pytest.approx(omega, rel=0.01)


def test_a_failing_equilibria_step_leaves_the_rest_of_the_document(monkeypatch):
    from app.engine.document.contract import derivation_json
    from app.engine.equilibria import modes as modes_module

    def broken(*args):
        raise AttributeError("'float' object has no attribute 'evalf'")

    monkeypatch.setattr(modes_module, "_normal_modes", broken)
    doc = derivation_json(derive(SYSTEMS["scene:simple-pendulum"]))
    assert doc["normal_modes"] == [] and doc["accelerations"] and doc["hamilton"]
    (step,) = [s for s in doc["steps"] if s["title"] == "Equilibria"]
    assert "left out" in step["explanation"] and "rest of the derivation is complete" in step["explanation"]


@pytest.mark.parametrize(
    "expr",
    [
        # a chain's force: centripetal terms (squares of velocities), gravity, no term linear in a velocity
        sp.Symbol("m") * sp.Symbol("l") * sp.sin(sp.Symbol("a") - sp.Symbol("b")) * sp.Symbol("b_dot") ** 2
        - sp.Symbol("g") * sp.sin(sp.Symbol("a")),
        # damping, a gyroscopic pair, a product of two velocities, a velocity inside a function and a square of a sum
        -sp.Symbol("c") * sp.Symbol("a_dot") + sp.Symbol("B") * sp.Symbol("b_dot")
        + sp.Symbol("a_dot") * sp.Symbol("b_dot") + sp.sin(sp.Symbol("a_dot")) * sp.Symbol("k")
        + (sp.Symbol("a_dot") + sp.Symbol("k")) ** 2,
        sp.Integer(0),
    ],
)
def test_a_derivative_at_rest_is_the_derivative_set_to_rest(expr):
    """``modes._at_rest``: ∂e/∂v at q̇ = 0, taken term by term with the other velocities set to 0 first, equals the
    derivative of the whole expression set to rest afterwards."""
    zero = {sp.Symbol("a_dot"): sp.Integer(0), sp.Symbol("b_dot"): sp.Integer(0)}
    for v in zero:
        assert sp.simplify(_at_rest(expr, v, zero) - sp.diff(expr, v).xreplace(zero)) == 0, v
