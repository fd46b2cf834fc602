"""Conserved quantities from the symmetries of L beyond cyclic coordinates: rotations and translations (issue 40,
item 38), each checked along the equations of motion before it is listed."""

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.scenes.types import Parameter, System

P = tuple(Parameter(n, 1.0, min=0.1) for n in ("m", "c", "B", "k", "kappa", "g"))
MAGNETIC = "m/2*(x_dot**2 + y_dot**2) + c*B/2*(x*y_dot - y*x_dot)"


def conserved(**declaration):
    return {c.name: c for c in derive(System(parameters=P, **declaration)).energetics.conserved}


def _symbols(*names):
    return sp.symbols(names, real=True)


def test_a_charge_in_a_magnetic_field_keeps_its_angular_momentum_and_its_guiding_centre():
    found = conserved(coordinates=("x", "y"), lagrangian=MAGNETIC)
    m, c, B, x, y, xd, yd = _symbols("m", "c", "B", "x", "y", "x_dot", "y_dot")
    # m(xẏ − yẋ) + ½cB(x² + y²), and the guiding centre's mẋ − cBy, mẏ + cBx
    assert sp.expand(found["J_z"].expr - (m * (x * yd - y * xd) + c * B * (x**2 + y**2) / 2)) == 0
    assert sp.expand(found["P_x"].expr - (m * xd - c * B * y)) == 0
    assert sp.expand(found["P_y"].expr - (m * yd + c * B * x)) == 0
    assert "Noether" in found["J_z"].reason and "turned together" in found["J_z"].reason
    assert "p_x − Bcy/2" in found["P_x"].reason and "p_y + Bcx/2" in found["P_y"].reason
    assert "h" in found


@pytest.mark.slow
def test_a_system_without_the_symmetry_lists_none():
    # an anisotropic oscillator: turning (x, y) changes U, and moving x or y changes U, by no total derivative
    found = conserved(coordinates=("x", "y"), kinetic="m/2*(x_dot**2 + y_dot**2)", potential="k/2*x**2 + kappa/2*y**2")
    assert set(found) == {"E"}
    # the isotropic one keeps its angular momentum; gravity along z keeps J_z of a free body but not J_x, J_y
    assert "J_z" in conserved(coordinates=("x", "y"), kinetic="m/2*(x_dot**2 + y_dot**2)", potential="k/2*(x**2 + y**2)")
    free = conserved(coordinates=("x", "y", "z"), kinetic="m/2*(x_dot**2 + y_dot**2 + z_dot**2)", potential="m*g*z")
    assert {"p_x", "p_y", "J_z", "E"} == set(free)


def test_a_force_along_the_symmetry_breaks_it():
    # a drag on x does work along the translation of x and along the rotation: neither is listed
    found = conserved(coordinates=("x", "y"), lagrangian=MAGNETIC, forces={"x": "-k*x_dot"})
    assert not {"J_z", "P_x"} & set(found)
    assert "P_y" in found


@pytest.mark.slow
def test_angles_are_not_turned():
    # a spherical pendulum's θ and φ: φ is cyclic (its momentum is listed), and no "rotation" of (θ, φ) is tried
    found = conserved(
        coordinates=("theta", "phi"),
        lagrangian="m*k**2/2*(theta_dot**2 + sin(theta)**2*phi_dot**2) + m*g*k*cos(theta)",
    )
    assert set(found) == {"p_phi", "E"} or set(found) == {"p_phi", "h"}
