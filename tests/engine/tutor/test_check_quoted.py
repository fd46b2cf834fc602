"""A verdict quotes what the student wrote and blames the step the slip is in (review student-m, issue 41): the
student's own term, never the engine's unsimplified or constant-padded one."""

from __future__ import annotations

import unicodedata

import pytest

from app.engine.tutor.answer_sides import read_answer
from app.engine.tutor.check import CheckError, judge
from app.engine.tutor.exercises import exercise_json
from tests.engine.tutor.test_check_slips import derivation, step_problem


def nfc(text: str) -> str:
    """Text as the page shows it, with each dotted letter as one character (ÿ₂ typed or composed alike)."""
    return unicodedata.normalize("NFC", text)


@pytest.mark.slow
def test_a_coupling_terms_sign_is_quoted_as_the_student_multiplied_it_out():
    # ∂/∂x₁ of ½ κ (x₂ − x₁)² is κ (2 x₁ − 2 x₂)/2 in the engine's form: the student wrote κ x₂, never a 2
    result = judge(step_problem("coupled-oscillators", "equation", "x1"), "m*x1_ddot + (k+kappa)*x1 + kappa*x2")
    name = result["mistake"]["name"]
    assert name.startswith("your term +κ x₂, which should be −κ x₂"), name
    assert "2" not in name.replace("x₂", "").replace("₂", ""), name
    assert "the term +κ x₂, which should be −κ x₂" in result["hint"], result["hint"]


def test_a_sum_the_student_kept_whole_is_quoted_without_the_engines_common_factor():
    result = judge(step_problem("coupled-oscillators", "equation", "x1"), "m*x1_ddot + k*x1 + kappa*(x1 + x2)")
    # the place and the kind of slip named; the correct sum kept for the student to ask for (review student-l 3)
    assert result["mistake"]["name"].startswith("x₁ + x₂: the sign of x₂"), result["mistake"]
    assert "x_{1} - x_{2}" in result["correct_part"]["latex"], result["correct_part"]


@pytest.mark.slow
def test_a_doubled_group_in_u_is_quoted_without_the_constant_the_student_never_wrote():
    result = judge(step_problem("pulley", "potential", None), "m1*g*y1 + m2*g*y2 - M*g*(y1+y2)")
    name = result["mistake"]["name"]
    assert name == "the M terms, −M (y₁ + y₂) g, twice what they should be", name
    assert "c" not in name.replace("twice", "").replace("should", ""), name


@pytest.mark.slow
def test_an_equations_dropped_coupling_terms_are_named_in_the_equation_and_t_blamed_only_if_it_has_the_slip():
    # the student's T was right; the θ₂ equation was written as a simple pendulum's (review student-m #36)
    result = judge(step_problem("double-pendulum", "equation", "theta2"), "m2*l2**2*theta2_ddot + m2*g*l2*sin(theta2)")
    hint = nfc(result["hint"])
    assert hint.startswith(
        nfc(
            "Your equation for θ₂ has the terms m₂ l₁ l₂ (θ̈₁ cos(θ₁ − θ₂) − θ̇₁² sin(θ₁ − θ₂)) left out: they come "
            "from the cross term m₂ l₁ l₂ θ̇₁ θ̇₂ cos(θ₁ − θ₂) of T."
        )
    ), hint
    # the earlier step only conditionally, and after this equation's terms
    assert nfc("If your T leaves out the part of the lower bob's velocity that comes from θ̇₁, that is where") in hint
    assert "fix it there" not in hint and not hint.startswith("Your equation for θ₂ follows from a T")


@pytest.mark.slow
def test_a_dropped_cross_acceleration_is_named_on_the_pulley_and_the_wedge():
    pulley = judge(step_problem("pulley", "equation", "y1"), "(m1+M/4)*y1_ddot + m1*g - M*g/2")
    assert nfc(pulley["mistake"]["name"]) == nfc("the term M ÿ₂/4 left out"), pulley["mistake"]
    assert nfc("the cross term M ẏ₁ ẏ₂/4 of T") in nfc(pulley["hint"]), pulley["hint"]
    wedge = judge(step_problem("movable-incline", "equation", "X"), "(M+m)*X_ddot")
    assert nfc(wedge["mistake"]["name"]) == nfc("the term m D̈ cos(α) left out"), wedge["mistake"]
    assert nfc("If your T leaves out the part of the block's velocity that comes from Ḋ") in nfc(wedge["hint"])


@pytest.mark.slow
def test_gravity_written_twice_with_opposite_signs_is_named_as_two_terms_that_cancel():
    # review student-m #113: the typed text holds −m g sin α and +m g sin α; built whole, SymPy cancels them
    text = "m*D_ddot + m*X_ddot*cos(alpha) - m*g*sin(alpha) + m*g*sin(alpha)"
    result = judge(step_problem("movable-incline", "equation", "D"), text)
    assert result["verdict"] == "incorrect"
    assert result["mistake"]["name"] == "your terms −m g sin(α) and +m g sin(α) cancel", result["mistake"]
    assert result["hint"] == (
        "In your equation for D, the terms −m g sin(α) and +m g sin(α) cancel: gravity's force enters once, as −∂U/∂D."
    )
    # the same answer typed without the pair is gravity left out, as before
    plain = judge(step_problem("movable-incline", "equation", "D"), "m*D_ddot + m*X_ddot*cos(alpha)")
    assert "cancel" not in plain["hint"], plain["hint"]
    # beside another slip (the coupling's sign), with either term kept the answer is still wrong: no pair blamed
    text = "m*D_ddot - m*X_ddot*cos(alpha) - m*g*sin(alpha) + m*g*sin(alpha)"
    other = judge(step_problem("movable-incline", "equation", "D"), text)
    assert other["verdict"] == "incorrect" and "cancel" not in other["hint"], other["hint"]


def test_a_squared_sum_in_a_one_body_denominator_is_named_as_that():
    # review student-m #88: the helix's z̈ with (1 + αR)² for 1 + α²R²; no "every body the motion carries"
    result = judge(step_problem("helix-bead", "acceleration", "z"), "-g/(1+alpha*R)^2")
    assert result["mistake"]["key"] == "solved.square_of_a_sum", result["mistake"]
    assert result["mistake"]["name"] == "the denominator (1 + R α)²: the square of a sum for a sum of squares"
    assert result["correct_part"]["what"] == "denominator", result["correct_part"]
    assert "cross term 2 R α" in result["mistake"]["where"] and "every body" not in result["hint"], result["hint"]


@pytest.mark.slow
def test_an_acceleration_without_a_moving_bodys_mass_says_which_mass_is_missing():
    # review student-m #52: an Atwood machine's result for the pulley, with m₂ nowhere in it
    result = judge(step_problem("pulley", "acceleration", "y1"), "(M-2*m1)*g/(2*m1+M)")
    where = nfc(result["mistake"]["where"])
    assert where.startswith(nfc("your answer has no m₂, as if that body did not move")), where
    assert nfc("here y₁ and y₂ both move") in where and "every body the motion carries" not in where, where


def test_an_omega_squared_with_the_coordinate_still_in_it_is_graded_and_named():
    # review student-m #24: g cos(θ)/R was refused as "Not checked"; at θ = 0 it is the right ω²
    pb = step_problem("simple-pendulum", "omega_squared", None)
    result = judge(pb, read_answer("g/R*cos(theta)", "omega_squared", None, pb.kinds)[0])
    assert result["verdict"] == "incorrect"
    assert result["mistake"]["key"] == "omega_squared.not_at_equilibrium", result["mistake"]
    assert (
        result["hint"] == "Your ω² still depends on θ: ω² = U_eff″/I_eff not evaluated at the equilibrium: put θ = 0."
    )
    # wrong even at the equilibrium: graded wrong, with the rule, and no slip named
    other = judge(pb, read_answer("2*g/R*cos(theta)", "omega_squared", None, pb.kinds)[0])
    assert other["verdict"] == "incorrect" and other["mistake"] is None, other
    assert other["hint"].startswith("Your ω² still depends on θ, but ω² at an equilibrium is a constant"), other
    # the coordinate is read to name the slip, never offered among the names the step may use
    omega = next(e for e in exercise_json(derivation("simple-pendulum"))["exercises"] if e["step"] == "omega_squared")
    assert "theta" not in omega["names"] and "theta" not in " ".join(omega["names_said"]), omega["names"]
    # the time is still refused
    with pytest.raises(CheckError, match="ω² at an equilibrium is a constant"):
        read_answer("g/R + 0*t", "omega_squared", None, pb.kinds)
