"""Units as a reader reads them (app/engine/derivation/dimensions.py)."""

from fractions import Fraction

import pytest

from app.engine.derivation.dimensions import ENERGY, equation_words, quantity, unit_text
from app.engine.tutor.check import judge
from tests.engine.tutor.test_check_slips import step_problem


def test_a_denominator_of_several_units_is_bracketed():
    # student-i 5: "a quantity in 1/m·s²" read as (1/m)·s²
    assert unit_text({"m": Fraction(-1), "s": Fraction(-2)}) == "1/(m·s²)"
    assert unit_text({"s": Fraction(2), "kg": Fraction(-1), "m": Fraction(-1)}) == "s²/(kg·m)"
    # one unit below needs none, and an energy is as it was
    assert unit_text({"m": Fraction(1), "s": Fraction(-2)}) == "m/s²"
    assert unit_text({"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-2)}) == "kg·m²/s²"
    assert unit_text({}) == "1"


@pytest.mark.slow
def test_a_missing_unit_never_reads_as_a_symbol_of_the_problem():
    # issue 41: "A factor of length (m) is missing" read as "multiply by the mass m"
    hint = judge(step_problem("simple-pendulum", "potential", None), "m*g*cos(theta)")["hint"]
    assert "A factor with the units of a length (metres) is missing: a length such as R." in hint, hint
    assert "(m)" not in hint


@pytest.mark.slow
def test_a_term_of_an_angles_equation_is_a_torque_never_an_energy():
    hint = judge(step_problem("simple-pendulum", "equation", "theta"), "m*R**2*theta_ddot + m*g*sin(theta)")["hint"]
    assert "adds a force (m g sin(θ)) to a torque (m R² θ̈)" in hint, hint
    assert "energy" not in hint


def test_the_words_for_a_term_of_an_equation_follow_the_coordinates_units():
    angle = equation_words("theta", {})
    assert quantity(ENERGY, angle) == "a torque (N·m)"
    length = equation_words("x", {"m": Fraction(1)})
    assert quantity({"kg": Fraction(1), "m": Fraction(1), "s": Fraction(-2)}, length) == "a force"
    assert quantity(ENERGY, length) == "a quantity in kg·m²/s²"
    assert quantity(
        {"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-3)}, equation_words("x", {"s": Fraction(1)})
    ) == ("a term of the x equation (kg·m²/s³)")
    assert equation_words("x", None) == ()
