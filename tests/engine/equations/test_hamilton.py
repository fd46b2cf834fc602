"""Hamilton's equations: H(q, p) is h under the Legendre map, and its equations give the Euler–Lagrange motion."""

from functools import cache

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from app.engine.derivation.derive import derive
from app.engine.equations.hamilton import hamilton
from app.scenes import SCENES
from tests.engine.systems import TEST_SYSTEMS
from tests.reference import numerically_equal

SYSTEMS = {**{f"scene:{k}": s.system for k, s in SCENES.items()}, **TEST_SYSTEMS}


@cache
def derived(name):
    d = derive(SYSTEMS[name])
    return d, hamilton(d.mechanics, d.equations)


def state_symbols(d, ham):
    return sorted({*d.table.q, *d.table.qd, *d.table.params, d.table.t, *ham.momenta}, key=str)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_hamiltonian_is_h_under_the_legendre_map(name):
    d, ham = derived(name)
    # p = dL/dq_dot put into H(q, p) gives back h(q, q_dot)
    legendre = dict(zip(ham.momenta, d.equations.momenta, strict=True))
    H_of_v = ham.hamiltonian.xreplace(legendre)
    assert numerically_equal(H_of_v, d.energetics.hamiltonian, state_symbols(d, ham))
    assert [P.name for P in ham.momenta] == [f"p_{q}" for q in d.table.names]


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_equations_are_the_derivatives_of_h(name):
    d, ham = derived(name)
    symbols = state_symbols(d, ham)
    velocities = dict(zip(d.table.qd, ham.velocities, strict=True))
    for k, (q, P) in enumerate(zip(d.table.q, ham.momenta, strict=True)):
        # q_dot = dH/dp and p_dot = -dH/dq + Q
        assert numerically_equal(sp.diff(ham.hamiltonian, P), ham.velocities[k], symbols)
        Q = d.mechanics.Q[k].xreplace(velocities)
        assert numerically_equal(-sp.diff(ham.hamiltonian, q) + Q, ham.p_dot[k], symbols)


def test_velocity_linear_terms_charge_in_a_magnetic_field():
    d, ham = derived("charge-in-field")
    x, y, m, k, B = (sp.Symbol(n, real=True) for n in ("x", "y", "m", "k", "B"))
    px, py = ham.momenta
    # H = (p - b)·M⁻¹(p - b)/2 + U with b = B (-y, x)/2
    expected = ((px + B * y / 2) ** 2 + (py - B * x / 2) ** 2) / (2 * m) + k * (x**2 + y**2) / 2
    assert sp.simplify(ham.hamiltonian - expected) == 0
    assert [sp.simplify(b - e) for b, e in zip(ham.offsets, (-B * y / 2, B * x / 2), strict=True)] == [0, 0]


def _lambdify(d, ham):
    table = d.table
    args = [table.t, *table.q, *ham.momenta, *table.params]
    rhs = sp.lambdify(args, [*ham.velocities, *ham.p_dot], "math")
    acc = sp.lambdify([table.t, *table.q, *table.qd, *table.params], list(d.equations.accelerations), "math")
    mom = sp.lambdify([table.t, *table.q, *table.qd, *table.params], list(d.equations.momenta), "math")
    return rhs, acc, mom


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_hamiltons_equations_give_the_euler_lagrange_motion(name):
    d, ham = derived(name)
    n = len(d.table.names)
    rhs, acc, mom = _lambdify(d, ham)
    k = [float(p.default) for p in d.system.parameters]
    rng = np.random.default_rng(3)
    q0, v0 = rng.uniform(0.4, 1.2, n), rng.uniform(-0.5, 0.5, n)
    p0 = np.array(mom(0.0, *q0, *v0, *k))
    lagrange = solve_ivp(
        lambda t, y: [*y[n:], *acc(t, *y, *k)], (0, 5), [*q0, *v0], method="DOP853", rtol=1e-11, atol=1e-12
    )
    hamilton_run = solve_ivp(lambda t, z: rhs(t, *z, *k), (0, 5), [*q0, *p0], method="DOP853", rtol=1e-11, atol=1e-12)
    q_l, q_h = lagrange.y[:n, -1], hamilton_run.y[:n, -1]
    assert np.allclose(q_l, q_h, rtol=1e-7, atol=1e-8), (q_l, q_h)
    # and the momenta at the end are p = dL/dq_dot of the Lagrangian run's final state
    assert np.allclose(mom(5.0, *lagrange.y[:, -1], *k), hamilton_run.y[n:, -1], rtol=1e-7, atol=1e-8)
