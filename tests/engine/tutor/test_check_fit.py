"""Each explanation fits the problem it is shown in (review student-f, A): no derivative of a fixed angle, no
spring in a problem without one, no letter the page does not use, units named the right way up, a term quoted
as the student typed it."""

from __future__ import annotations

import re
import unicodedata

import pytest

from app.engine.derivation.derive import derive
from app.engine.tutor.check import judge
from app.engine.tutor.exercises import exercise_json
from app.engine.tutor.mistakes import OMEGA_HINT, POINTERS, pointer, springs_possible
from app.scenes import SCENES
from tests.engine.slip_corpus import SLIPS
from tests.engine.tutor.test_check_slips import declared, step_problem

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

SPRING_WORDS = re.compile(r"spring|stretch|natural length", re.IGNORECASE)


def shown(result: dict) -> str:
    """Every word the page shows of a verdict: the hint, and the mistake's name and reason."""
    m = result["mistake"] or {"name": "", "where": ""}
    return f"{result['hint']} | {m['name']} | {m['where']}"


SPRINGLESS = [s for s in SLIPS if not springs_possible(declared(s[0]))]


@pytest.mark.parametrize("slip", SPRINGLESS, ids=[f"{s[0]}-{s[1]}-{i}" for i, s in enumerate(SPRINGLESS)])
def test_a_problem_without_a_spring_is_never_told_of_one(slip):
    system, step, coordinate, answer, _ = slip
    result = judge(step_problem(system, step, coordinate), answer)
    assert not SPRING_WORDS.search(shown(result)), shown(result)


def test_a_fixed_angle_is_not_differentiated():
    result = judge(step_problem("incline-block", "acceleration", "X"), "-g*cos(alpha)")
    assert "derivative of cos α" not in shown(result)
    assert "α is a fixed angle of the set-up, not a coordinate" in result["mistake"]["where"]
    # a coordinate's sine still comes from differentiating its cosine
    pendulum = judge(step_problem("simple-pendulum", "acceleration", "theta"), "-g*cos(theta)/R")
    assert "the derivative of cos θ is −sin θ" in pendulum["mistake"]["where"]


def test_a_sign_slip_in_a_springless_sum_is_the_sign_of_a_term():
    result = judge(
        step_problem("spherical-pendulum", "acceleration", "theta"),
        "sin(theta)*cos(theta)*phi_dot**2 - g*sin(theta)/R",
    )
    assert result["mistake"]["name"] == "the sign of your term −g sin(θ)/R"


def test_sin_and_cos_swapped_throughout_speaks_of_no_length_the_page_does_not_use():
    result = judge(
        step_problem("spherical-pendulum", "lagrangian", None),
        "m*R**2*(theta_dot**2 + cos(theta)**2*phi_dot**2)/2 - m*g*R*sin(theta)",
    )
    assert result["mistake"]["key"] == "lagrangian.piece.sin_cos_throughout"
    assert not re.search(r"\bl\b|down", result["mistake"]["where"]), result["mistake"]["where"]


def test_a_wrong_mass_reason_opens_with_words_so_m1_is_never_capitalised():
    result = judge(
        step_problem("pulley", "kinetic", None), "m1*y1_dot**2/2 + m1*y2_dot**2/2 + M*(y1_dot + y2_dot)**2/8"
    )
    assert result["mistake"]["where"] == "this term comes from the right mass (mass m₂), and m₁ belongs to the left mass"


def test_the_sign_of_gravity_in_u_speaks_of_heights_only():
    result = judge(step_problem("pulley", "potential", None), "M*g*(y1 + y2)/2 + m1*g*y1 + m2*g*y2")
    assert result["mistake"]["where"] == "a height is measured upward, against gravity"


def test_a_units_factor_too_many_is_named_the_right_way_up_in_full_sentences():
    result = judge(step_problem("simple-pendulum", "kinetic", None), "m*g*R**2*theta_dot**2/2")
    assert result["hint"] == (
        "Check the units. Your T is a quantity in kg·m³/s⁴, but it should be an energy (kg·m²/s²). "
        "It has a factor g (m/s²) too many."
    )
    # the whole answer is the student's own preview: not printed again under the words
    assert result["mistake"]["latex"] == ""
    incline = judge(step_problem("incline-block", "acceleration", "X"), "-g*sin(alpha)*m")
    assert "but it should be an acceleration (m/s²). It has a factor m (kilograms) too many." in incline["hint"]


def test_a_long_sum_of_mixed_units_is_not_quoted_inside_the_sentence():
    result = judge(
        step_problem("pulley", "lagrangian", None),
        "m1*y1_dot**2/2 + m2*y2_dot**2/2 + M*(y1_dot + y2_dot)**2/8 + m1*g*y1 + m2*g*y2 - (m1 + m2 + M)*g",
    )
    assert unicodedata.normalize("NFC", result["hint"]) == unicodedata.normalize("NFC",
        "Check the units. Your sum adds an energy (m₁ ẏ₁²/2) to a force (−(M + m₁ + m₂) g), and the terms of a "
        "sum must have the same units."
    )  # fmt: skip
    # a short sum is quoted, being the student's piece
    short = judge(step_problem("simple-pendulum", "omega_squared", None), "(m + g)/R")
    assert "m + g adds" in short["hint"] or "g + m adds" in short["hint"], short["hint"]


def test_a_swapped_term_of_an_equation_is_quoted_as_typed():
    result = judge(step_problem("simple-pendulum", "equation", "theta"), "theta_ddot + g*cos(theta)/R")
    assert result["mistake"]["name"] == "sin and cos swapped in your term g cos(θ)/R"
    scaled = judge(step_problem("simple-pendulum", "equation", "theta"), "m*R**2*theta_ddot + m*g*R*cos(theta)")
    assert scaled["mistake"]["name"] == "sin and cos swapped in your term m g R cos(θ)"


def test_the_rule_for_omega_squared_uses_no_coordinate_of_its_own_and_no_program_names():
    assert not re.search(r"r₀|_", pointer("omega_squared")), pointer("omega_squared")


def test_the_frequencys_letter_is_a_field_of_its_words_filled_where_read():
    # (issue 41, 6a) the rule and the ω-for-ω² hint hold the letter as a field, never a literal ω patched over
    assert "ω" not in POINTERS["omega_squared"] and "ω" not in OMEGA_HINT
    # the practice page's rule for the rotating wire speaks of Ω², as its hints do
    rule = exercise_json(derive(SCENES["rotating-parabola"].system))["rules"]["omega_squared"]
    assert "Ω² is the effective potential's second derivative" in rule and "ω" not in rule, rule
    assert "ω² is the effective" in exercise_json(derive(SCENES["simple-pendulum"].system))["rules"]["omega_squared"]


def test_a_spring_loses_its_half_and_a_mass_in_an_acceleration_is_named():
    half = judge(step_problem("rail-two-body", "potential", None), "k*(x2 - x1 - l0)**2")
    assert half["mistake"]["name"] == "the ½ of ½ k × stretch² left out of your term k (x₂ − x₁ − l₀)²"
    mass = judge(step_problem("rail-two-body", "acceleration", "x2"), "-k*(x2 - x1 - l0)/m1")
    assert mass["mistake"]["name"] == "the wrong mass: m₁ where m₂ belongs"


def test_a_momentum_term_left_out_is_said_in_words_and_your_is_said_once():
    result = judge(step_problem("pulley", "momentum", "y2"), "m2*y2_dot + M*y2_dot/4")
    assert unicodedata.normalize("NFC", result["mistake"]["name"]) == unicodedata.normalize("NFC", "the ẏ₁ term missing")
    assert "p_" not in shown(result)
    swapped = judge(step_problem("incline-block", "potential", None), "m*g*X*cos(alpha)")
    assert swapped["hint"].lower().count("your") == 1, swapped["hint"]


def test_gravity_counted_twice_speaks_of_no_generalized_force():
    result = judge(step_problem("simple-pendulum", "acceleration", "theta"), "-g*sin(theta)/R - g*sin(theta)/R")
    assert "counted twice" in result["mistake"]["name"] and "Q" not in shown(result), shown(result)


def test_a_rods_formulas_typed_for_a_bob_are_named_with_the_rods_reason():
    rod = judge(step_problem("simple-pendulum", "kinetic", None), "m*R**2*theta_dot**2/6")
    assert rod["mistake"]["name"].startswith("a rod's T for a bob") and not re.search(r"\bl\b", rod["mistake"]["where"])
    centre = judge(step_problem("simple-pendulum", "potential", None), "m*g*(R/2)*(1 - cos(theta))")
    assert "a rod's centre is at half its length" in centre["mistake"]["where"]
    assert "differentiating" not in centre["mistake"]["where"]


def test_a_stretch_is_quoted_as_typed_and_the_right_one_in_a_textbooks_order():
    result = judge(step_problem("rail-two-body", "potential", None), "k*(x1 - x2 - l0)**2/2")
    assert result["mistake"]["name"].startswith("x₁ − x₂ − l₀: the sign of l₀")
    # the right one, in a textbook's order, only on request (review student-l 3)
    assert "x₂ − x₁ − l₀" not in result["mistake"]["name"] + result["hint"]
    assert result["correct_part"]["what"] == "stretch" and result["correct_part"]["text"] == "x₂ − x₁ − l₀"
