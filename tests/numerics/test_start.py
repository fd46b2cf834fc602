"""A start where the equations of motion have no value is refused with its actual cause, expression and value."""

import numpy as np
import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.numerics.start import GENERAL, value_of, why_not_at_start, written
from app.scenes.types import Parameter, Particle, System


def why(system: System, y0, k=()):
    return why_not_at_start(derive(system), np.array(y0, dtype=float), np.array(k, dtype=float))


def test_a_zero_mass_is_named_as_such():
    system = System(("x",), (Parameter("m", 1.0),), kinetic="m*x_dot**2/2", potential="x**2/2")
    message = why(system, [1.0, 0.0], [0.0])
    assert "mass matrix is singular" in message and "m = 0" in message and "zero mass" in message
    assert "division by zero" not in message


def test_a_particle_of_zero_mass_is_named_too():
    system = System(("x",), (Parameter("m", 1.0),), particles=(Particle("m", ("x", "0", "0")),), potential="x**2/2")
    assert "m = 0" in why(system, [1.0, 0.0], [0.0])


@pytest.mark.slow
def test_a_function_outside_its_domain_names_the_function_and_the_value():
    system = System(("x",), kinetic="x_dot**2/2", potential="acos(x)")
    message = why(system, [2.0, 0.0])
    assert "acos(x) is not defined at x = 2" in message and "[−1, 1]" in message


@pytest.mark.slow
def test_an_overflow_names_the_expression_that_overflows():
    system = System(("x",), kinetic="x_dot**2/2", potential="exp(exp(exp(exp(x))))")
    message = why(system, [5.0, 0.0])
    assert "exp(exp(exp(x))) overflows at x = 5" in message


def test_a_division_by_zero_names_the_denominator():
    system = System(("r",), kinetic="r_dot**2/2", potential="1/r")
    assert "1/r divides by zero at r = 0" in why(system, [0.0, 0.0])


@pytest.mark.slow
def test_a_singular_point_of_the_coordinates_is_still_called_that():
    system = System(("r", "theta"), kinetic="(r_dot**2 + r**2*theta_dot**2)/2", potential="r**2/2")
    message = why(system, [0.0, 0.0, 0.0, 1.0])
    assert "mass matrix is singular at this initial state (r = 0" in message and "move it slightly" in message


def test_a_derivative_outside_the_domain_is_found_in_the_equations():
    # U = x^(3/2) is finite at x = 0, but its force 3/2 sqrt(x) is not real at x = -1; U itself is not either
    system = System(("x",), kinetic="x_dot**2/2", potential="sqrt(x)**3")
    message = why(system, [-1.0, 0.0])
    assert "not defined at x = −1" in message and "negative number" in message


def test_each_undefined_value_is_caught_at_its_smallest_node():
    x = sp.Symbol("x", real=True)
    with pytest.raises(ArithmeticError) as caught:
        value_of(sp.log(x - 3) + 1, {x: 1.0})
    assert written(caught.value.node) == "log(x − 3)"


def test_expressions_are_written_for_a_sentence():
    x, m = sp.symbols("x m", real=True)
    assert written(m * x**2 / 2) == "m·x²/2"
    assert written(sp.Symbol("theta_dot", real=True) ** sp.Rational(3, 2)) == "θ̇^(3/2)"


def test_a_finite_start_gets_the_general_sentence():
    system = System(("x",), kinetic="x_dot**2/2", potential="x**2/2")
    assert why(system, [1.0, 0.0]) == GENERAL
