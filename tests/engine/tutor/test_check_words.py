"""What a student reads after a check (review 41, items 6, 10 and 19): the piece under "The mistake:" says
what it is and is in the scale of the answer, a wrong follow-up gets a new hint, and no sentence speaks of
"the engine's" answer or of a constant where none was left out."""

from __future__ import annotations

import pytest

from app.engine.document.notation import letter, text
from app.engine.tutor.check import judge, judge_follow_up
from app.engine.tutor.check_problem import problem
from app.engine.tutor.exercises import exercise_json
from tests.engine.tutor.test_check_slips import derivation, step_problem

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

INCLINE_T = "M*X_dot**2/2 + m*D_dot**2/2"


def test_no_message_says_the_engines_answer():
    wrong = judge(step_problem("simple-pendulum", "kinetic", None), "m*R**2*theta_dot**2")
    right = judge(step_problem("simple-pendulum", "kinetic", None), "m*R**2*theta_dot**2/2")
    shifted = judge(step_problem("simple-pendulum", "potential", None), "-m*g*R*cos(theta)")
    for result in (wrong, right, shifted):
        assert "engine" not in result["message"] + (result["hint"] or ""), result
    assert wrong["message"] == "Incorrect: this is not the correct kinetic energy T."
    # the difference is not said: it is kept for the step's reveal
    assert "(yours − correct)" not in wrong["message"] and wrong["reveal"]["difference"]["latex"]


def test_an_equation_divided_through_is_plainly_the_equation_of_motion():
    result = judge(
        step_problem("movable-incline", "equation", "D"), "-(m*D_ddot + m*X_ddot*cos(alpha) - m*g*sin(alpha))/m"
    )
    assert result["message"] == "Correct: this is the equation of motion for D.", result["message"]


def test_the_constant_clause_only_where_a_constant_was_left_out():
    # L = T − m g D sin α: U's sign reversed, no constant anywhere
    no_constant = judge(
        step_problem("movable-incline", "lagrangian", None),
        "M*X_dot**2/2 + m*(X_dot**2 + D_dot**2 + 2*X_dot*D_dot*cos(alpha))/2 - m*g*D*sin(alpha)",
    )
    assert "constant" not in no_constant["message"], no_constant["message"]
    # U = m g R cos θ against m g R (1 − cos θ): the constant −m g R is left out of the comparison, and said so
    with_constant = judge(step_problem("simple-pendulum", "potential", None), "m*g*R*cos(theta)")
    assert "constants in U are ignored in this comparison" in with_constant["message"], with_constant["message"]
    # a position is no U (student-g 11): the clause names no U there
    z = judge(step_problem("simple-pendulum", "position", "z"), "R*cos(theta)")
    assert z["verdict"] == "incorrect" and "U" not in z["message"], z["message"]
    assert "a constant added to it is ignored in this comparison" in z["message"], z["message"]


def test_the_piece_kept_for_the_reveal_is_labelled_or_not_repeated():
    # the sign of ∂L/∂q: the piece would be the difference again, at another scale; one formula only
    sign = judge(step_problem("simple-pendulum", "equation", "theta"), "theta_ddot - g/R*sin(theta)")
    assert sign["reveal"]["piece"] == "" and sign["reveal"]["difference"]["latex"]
    # sign of U: the piece 2 m g R cos θ − 2 m g R would repeat the difference with its constant
    u = judge(step_problem("simple-pendulum", "potential", None), "m*g*R*cos(theta)")
    assert u["reveal"]["piece"] == ""
    # a term left out of an equation divided through: the term at the student's scale, labelled
    left_out = judge(
        step_problem("double-pendulum", "equation", "theta2"),
        "l2*theta2_ddot + l1*cos(theta1 - theta2)*theta1_ddot + g*sin(theta2)",
    )
    assert left_out["mistake"]["latex"] == ""  # never under the name: it is the answer's
    tex = left_out["reveal"]["piece"]
    assert tex.startswith(r"\text{what your equation for") and "leaves out" in tex, tex
    assert "m_{2}" not in tex, tex  # in the scale of the answer (divided by m₂ l₂), not the engine's
    # a slip in a term of the right scale: the correct term, labelled
    swapped = judge(step_problem("simple-pendulum", "potential", None), "m*g*R*sin(theta)")
    assert swapped["reveal"]["piece"].startswith(r"\text{the correct term: }"), swapped["reveal"]
    assert swapped["mistake"]["latex"] == ""


def test_the_piece_and_why_do_not_give_the_follow_ups_answer_away():
    result = judge(step_problem("movable-incline", "kinetic", None), INCLINE_T)
    assert result["follow_up"] is not None
    assert "of size" not in result["mistake"]["where"] and "of size" not in result["hint"]
    tex = result["reveal"]["piece"]
    assert tex.startswith(r"\text{what your T leaves out: }") and tex != r"\text{what your T leaves out: }\dot{X}"


def test_a_wrong_follow_up_gets_a_new_and_concrete_hint():
    pb = step_problem("movable-incline", "kinetic", None)
    key = judge(pb, INCLINE_T)["follow_up"]["key"]
    wrong = judge_follow_up(pb, key, "X_dot*cos(alpha)")
    assert wrong["verdict"] == "incorrect"
    first = judge(pb, INCLINE_T)
    assert wrong["hint"] not in (first["hint"], f"Think of where it comes from: {first['mistake']['where']}.")
    # concrete: what moving X alone does to the block, and the position it reads from (never its velocity)
    assert "carries the block" in wrong["hint"] and "X + D cos(α)" in wrong["hint"], wrong["hint"]
    assert "velocity (Ẋ" not in wrong["hint"], wrong["hint"]
    right = judge_follow_up(pb, key, "X_dot")
    assert right["verdict"] == "correct"


def test_a_hint_speaks_of_springs_only_where_a_spring_can_be():
    from app.engine.derivation.derive import derive
    from app.engine.tutor.check import judge, problem
    from app.scenes import SCENES

    # the sign of U reversed: the pendulum's hint says nothing of springs; the tabletop spring's problem may
    pendulum = judge(problem(derive(SCENES["simple-pendulum"].system), "potential"), "m*g*R*cos(theta)")
    assert pendulum["verdict"] == "incorrect" and pendulum["hint"] and "spring" not in pendulum["hint"]
    assert problem(derive(SCENES["tabletop-spring"].system), "potential", mistakes=False).springs
    assert not problem(derive(SCENES["pulley"].system), "potential", mistakes=False).springs


def test_a_missing_factor_with_a_name_is_said_by_its_name():
    # student-g 4: "It has a factor in s²/kg·m too many" for a T typed as a length; a force is what is missing
    hint = judge(step_problem("incline-block", "kinetic", None), "X*sin(alpha)")["hint"]
    assert (
        "Your T is a length (metres), but it should be an energy (kg·m²/s²). A factor with the units of a force "
        "(kg·m/s²) is missing." in hint
    ), hint
    assert "too many" not in hint, hint


def test_gravity_counted_twice_in_u_says_why():
    # student-g 7: "Why: This piece appears once in the derivation" explained nothing
    doubled = judge(step_problem("incline-block", "potential", None), "2*m*g*X*sin(alpha)")
    assert doubled["mistake"]["where"] == "each mass's weight enters U once, as m g times its height: gravity is counted twice here"


def test_the_frequency_step_uses_the_documents_letter_where_omega_is_a_parameter():
    """prof-h 1, student-h 7: on the rotating wire ω is the wire's rate, and the practice step printed
    "ω² = 2gα − ω²"; the step, its prompt and its verdict use the page's letter for the frequency, Ω."""
    d = derivation("rotating-parabola")
    assert (letter("frequency", d), text("frequency", d)) == (r"\Omega", "Ω")
    step = next(e for e in exercise_json(d)["exercises"] if e["step"] == "omega_squared")
    assert step["title"].startswith("Ω² of small oscillations") and step["lhs"] == r"\Omega^2", step
    assert step["answer"]["latex"].startswith(r"\Omega^2 = 2 g \alpha - \omega^{2}"), step["answer"]
    # (ω² in "2gα > ω²" is the wire's rate: the frequency is Ω throughout)
    assert step["answer"]["notes"] and all("Ω² is" in n and "ω² is" not in n for n in step["answer"]["notes"])
    right = judge(problem(d, "omega_squared", None, mistakes=False), "2*g*alpha - omega**2")
    assert right["verdict"] == "correct" and "Ω² of small oscillations" in right["message"], right
    # where ω is free, it stays ω
    simple = next(e for e in exercise_json(derivation("simple-pendulum"))["exercises"] if e["step"] == "omega_squared")
    assert simple["title"].startswith("ω² of small oscillations") and simple["lhs"] == r"\omega^2"


def test_the_rule_for_u_names_no_gravity_where_the_system_has_none():
    """student-i 3: the masses between springs slide on a horizontal line, and the hint spoke of m g × height."""
    # (an answer no mistake names: the middle spring stretched by x₂ alone is named since issue 41, 1)
    hint = judge(step_problem("coupled-oscillators", "potential", None), "k*(x1**2 + x2**2)/2 + kappa*x1*x2")["hint"]
    assert hint == "U depends on positions only: ½ k times the square of each spring's stretch.", hint
    # with gravity, both
    hint = judge(step_problem("simple-pendulum", "potential", None), "m*g*R*theta")["hint"] or ""
    assert "m g times the height" in hint or "Check the units" in hint, hint
