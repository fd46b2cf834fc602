"""The engine against results derived by hand."""

import pytest
import sympy as sp

from app.engine.algebra import work
from app.engine.derivation import derive as derive_module
from app.engine.derivation.derive import derive
from app.engine.errors import DerivationError, EquationsTooCostly
from app.errors import TooMuchWork
from app.scenes import SCENES
from app.scenes.types import Parameter, System
from tests.engine.systems import DAMPED_SPRING, LAGRANGIAN_ONLY, SPINNING_ROD, TABLETOP

S = {
    n: sp.Symbol(n, real=True)
    for n in "m g R k b omega t x x_dot rho rho_dot r r_dot theta theta_dot phi phi_dot".split()
}


def same(a, b):
    return sp.simplify(a - b) == 0


def test_simple_pendulum_by_hand():
    d = derive(SCENES["simple-pendulum"].system)
    m, g, R, th, thd = S["m"], S["g"], S["R"], S["theta"], S["theta_dot"]
    assert same(d.equations.accelerations[0], -g / R * sp.sin(th))
    assert same(d.equations.momenta[0], m * R**2 * thd)
    assert same(d.energetics.hamiltonian, m * R**2 * thd**2 / 2 + m * g * R * (1 - sp.cos(th)))
    assert d.energetics.h_equals_e
    assert d.energetics.cyclic == ()
    # about the bottom, omega^2 = g/R; the top is unstable
    eq = {e.position: e for e in d.reduction.equilibria}
    assert same(eq[0].omega_squared, g / R) and eq[0].stable is True
    assert same(eq[sp.pi].omega_squared, -g / R) and eq[sp.pi].stable is False


@pytest.mark.slow
def test_spherical_pendulum_by_hand():
    d = derive(SCENES["spherical-pendulum"].system)
    m, g, R, th, thd, phd = S["m"], S["g"], S["R"], S["theta"], S["theta_dot"], S["phi_dot"]
    th_dd, ph_dd = d.equations.accelerations
    # theta from the upward vertical: U = m g R cos(theta)
    assert same(th_dd, sp.sin(th) * sp.cos(th) * phd**2 + g / R * sp.sin(th))
    assert same(ph_dd, -2 * thd * phd * sp.cos(th) / sp.sin(th))
    assert d.energetics.cyclic == ("phi",)
    p_phi = next(c for c in d.energetics.conserved if c.name == "p_phi")
    assert same(p_phi.expr, m * R**2 * sp.sin(th) ** 2 * phd)
    assert d.reduction is not None and d.reduction.coordinate == "theta"
    P = sp.Symbol("p_phi", real=True)
    assert same(d.reduction.effective_potential, P**2 / (2 * m * R**2 * sp.sin(th) ** 2) + m * g * R * sp.cos(th))


@pytest.mark.slow
def test_cyclic_coordinate_and_circular_orbit():
    d = derive(TABLETOP)
    m, k = S["m"], S["k"]
    assert d.energetics.cyclic == ("theta",)
    (orbit,) = d.reduction.equilibria
    P = sp.Symbol("p_theta", real=True)
    # r0^4 = p^2 / (m k) and omega^2 = 4 k / m for a Hooke central force
    assert same(orbit.position**4, P**2 / (m * k))
    assert same(orbit.omega_squared, 4 * k / m)
    assert orbit.stable is True


def test_h_equals_e_on_fixed_constraints_and_not_on_moving_ones():
    fixed = derive(TABLETOP).energetics
    assert fixed.h_equals_e and fixed.energy_minus_h == 0
    assert any(c.name == "E" for c in fixed.conserved)

    moving = derive(SPINNING_ROD).energetics
    m, w, rho = S["m"], S["omega"], S["rho"]
    assert not moving.h_equals_e
    # T0 = m omega^2 rho^2 / 2, so E - h = 2 T0
    assert same(moving.energy_minus_h, m * w**2 * rho**2)
    names = [c.name for c in moving.conserved]
    assert "h" in names and "E" not in names
    assert "moving constraint" in moving.reason


def test_spinning_rod_acceleration():
    d = derive(SPINNING_ROD)
    assert same(d.equations.accelerations[0], S["omega"] ** 2 * S["rho"])


def test_generalized_force_enters_the_equation_and_the_power():
    d = derive(DAMPED_SPRING)
    m, k, b, x, xd = S["m"], S["k"], S["b"], S["x"], S["x_dot"]
    assert same(d.equations.accelerations[0], (-k * x - b * xd) / m)
    assert same(d.energetics.power, -b * xd**2)
    assert not any(c.name in ("h", "E") for c in d.energetics.conserved)
    assert d.reduction is None


def test_lagrangian_form():
    d = derive(LAGRANGIAN_ONLY)
    assert same(d.equations.accelerations[0], -S["k"] * S["x"])
    assert d.energetics.h_equals_e is None and "Only L" in d.energetics.reason


@pytest.mark.parametrize(
    ("lagrangian", "message"),
    [
        ("x**2 + y", "zero"),
        ("(x_dot + y_dot)**2/2 - x**2", "singular"),
        ("x_dot**3 + y_dot**2", "depends on the velocities"),
        ("x_dot**2/2", "singular"),
    ],
)
def test_singular_mass_matrix_is_refused(lagrangian, message):
    system = System(coordinates=("x", "y"), parameters=(Parameter("k", 1.0),), lagrangian=lagrangian)
    with pytest.raises(DerivationError, match=message):
        derive(system)


def test_names_are_checked():
    with pytest.raises(DerivationError, match="declared twice"):
        derive(System(coordinates=("x", "x"), lagrangian="x_dot**2"))
    with pytest.raises(DerivationError, match="reserved"):
        derive(System(coordinates=("sin",), lagrangian="x_dot**2"))


def test_equations_past_their_bound_of_work_are_refused_at_that_count(monkeypatch):
    # the equations have no plainer form to fall back to: past EQUATIONS_WORK the system is refused, at a count of
    # work (the same on an idle machine and a loaded one), as a refusal for too much work
    spring = System(coordinates=("x",), parameters=(), lagrangian="x_dot**2 + (x + x_dot + 1)**8")
    counted = work.done()
    derive(spring)  # 7,645 units of equations: well inside the bound
    assert work.done() > counted
    monkeypatch.setattr(derive_module, "EQUATIONS_WORK", 2_000)
    with pytest.raises(EquationsTooCostly, match="need more algebra than") as refused:
        derive(spring)
    assert isinstance(refused.value, TooMuchWork)
