"""A verdict names the mistake without handing over the answer (review student-d, items 2, 8, 11, 13–18).

What a student reads (the message, the mistake's name, its piece, the hint, what else is right) never prints
the corrected expression or a difference it follows from; the difference and the correct piece travel in
``reveal``, which the page shows only with the step.  Each case is a slip a student made in practice mode.
"""

from __future__ import annotations

import unicodedata

import pytest
import sympy as sp

from app.engine.tutor.check import judge, judge_follow_up
from tests.engine.tutor.test_check_slips import SLIPS, step_problem

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def read(result: dict) -> str:
    """Everything a student reads of a verdict, as one text."""
    m = result["mistake"] or {}
    parts = [result["message"], result["hint"] or "", m.get("name", ""), m.get("where", ""), m.get("latex", "")]
    parts.append((result["partial"] or {}).get("message", ""))
    return " | ".join(parts)


# (system, step, coordinate, answer, what must not be read: the correct piece or the answer)
GIVEAWAYS = [
    ("simple-pendulum", "potential", None, "-m*g*R*sin(theta)", ["m g R cos", "correct term"]),
    ("simple-pendulum", "momentum", "theta", "m*R*theta_dot", ["yours times", "m R² θ̇"]),
    ("movable-incline", "kinetic", None, "M*X_dot**2/2 + m*(D_dot**2 + 2*D_dot*X_dot*cos(alpha))/2",
     ["m Ẋ²/2", "leaves out: "]),
    ("double-pendulum", "kinetic", None,
     "m1*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2 + m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2)",
     ["m₂ l₁² θ̇₁²", "leaves out: "]),
    ("double-pendulum", "potential", None, "-m1*g*l1*cos(theta1) - m2*g*l2*cos(theta2)", ["m₂ g l₁ cos"]),
    ("movable-incline", "momentum", "X", "(M + m)*X_dot", ["m Ḋ cos", "leaves out: "]),
    ("movable-incline", "acceleration", "X", "0", ["sin(α) cos(α)", "Everything else"]),
    # a solved acceleration or ω² read against the truth: the part named, never the correct whole (issue 41, 2)
    ("movable-incline", "acceleration", "X", "-m*g*sin(alpha)*cos(alpha)/(M+m)", ["/(M + m sin²(α))"]),
    ("rotating-parabola", "omega_squared", None, "omega**2 - 2*g*alpha", ["2 g α − ω²"]),
    ("coupled-oscillators", "acceleration", "x1", "-(k+2*kappa)/m*x1", ["x₂ κ/m", "x₂ κ −"]),
    ("helix-bead", "equation", "z", "m*(1+alpha**2*R**2)*z_ddot + m*g*(1+alpha**2*R**2)", ["should be m g"]),
    ("elastic-pendulum", "equation", "phi", "m*r**2*phi_ddot + m*g*r*sin(phi)", ["2 m r φ̇ ṙ", "leaves out: "]),
    ("elastic-pendulum", "potential", None, "-m*g*r*cos(phi) + k*(r - l)**2", ["pulley", "l²/2", "(r − l)²/2"]),
]  # fmt: skip


@pytest.mark.parametrize(("system", "step", "coordinate", "answer", "hidden"), GIVEAWAYS)
def test_an_incorrect_verdict_names_the_slip_without_the_answer(system, step, coordinate, answer, hidden):
    result = judge(step_problem(system, step, coordinate), answer)
    assert result["verdict"] == "incorrect" and result["hint"], result
    text = read(result)
    for words in hidden:
        assert words not in text, (words, text)
    # the difference is kept for the step's reveal, never in what the verdict says
    assert "difference" not in result and "(yours − correct)" not in result["message"]
    assert result["reveal"]["difference"]["latex"], result["reveal"]


def test_no_slip_of_the_corpus_shows_a_difference_or_the_correct_term():
    for slip in SLIPS[::7]:
        result = judge(step_problem(*slip[:3]), slip[3])
        text = read(result)
        assert "correct term" not in text and "leaves out: " not in text and "yours times" not in text, (slip, text)


def test_the_students_own_term_is_quoted_where_it_helps():
    swapped = judge(step_problem("simple-pendulum", "potential", None), "-m*g*R*sin(theta)")
    assert "your term −m g R sin(θ)" in swapped["mistake"]["name"], swapped["mistake"]["name"]
    sign = judge(
        step_problem("double-pendulum", "equation", "theta2"),
        "m2*l2**2*theta2_ddot + m2*l1*l2*cos(theta1 - theta2)*theta1_ddot"
        " + m2*l1*l2*sin(theta1 - theta2)*theta1_dot**2 + m2*g*l2*sin(theta2)",
    )
    # the student's own term, as typed (its sign is the slip, so it is quoted without one)
    assert "your m₂ l₁ l₂ θ̇₁² sin(θ₁ − θ₂) term" in sign["mistake"]["name"] and "−m₂ l₁ l₂" not in read(sign), read(
        sign
    )


def test_a_factor_is_named_and_no_part_agreeing_is_not_said_beside_it():
    half = judge(
        step_problem("double-pendulum", "momentum", "theta1"),
        "(m1 + m2)*l1**2*theta1_dot/2 + m2*l1*l2*theta2_dot*cos(theta1 - theta2)/2",
    )
    assert "half" in half["hint"] and "No part" not in read(half), read(half)
    r = judge(step_problem("simple-pendulum", "momentum", "theta"), "m*R*theta_dot")
    assert "factor R is missing" in r["hint"], r["hint"]
    assert "(1 − R)" not in str(r["reveal"]) and "1 - R" not in str(r["reveal"]), r["reveal"]


def test_everything_else_is_right_is_not_said_of_a_one_term_answer():
    for answer in ("0", "m*R**2*theta_dot**2"):
        step = "acceleration" if answer == "0" else "kinetic"
        pb = step_problem("simple-pendulum", step, "theta" if step == "acceleration" else None)
        result = judge(pb, answer)
        assert "Everything else" not in read(result), read(result)


def test_a_spring_that_lost_its_half_is_said_in_its_own_words():
    result = judge(step_problem("elastic-pendulum", "potential", None), "-m*g*r*cos(phi) + k*(r - l)**2")
    assert "k (r − l)²" in result["mistake"]["name"] or "k (l − r)²" in result["mistake"]["name"], read(result)
    assert "½ k" in result["hint"] and "pulley" not in result["hint"], result["hint"]


def test_a_wrong_follow_up_names_its_slip_and_does_not_repeat_the_question():
    pb = step_problem("elastic-pendulum", "equation", "phi")
    first = judge(pb, "m*r**2*phi_ddot + m*g*r*sin(phi)")
    question = first["follow_up"]["question"]
    wrong = judge_follow_up(pb, first["follow_up"]["key"], "2*r")
    said = unicodedata.normalize("NFC", wrong["message"] + " " + wrong["hint"])
    assert said.count(question) <= 1 and "ṙ" in said and "chain rule" in said, said
    assert judge_follow_up(pb, first["follow_up"]["key"], "2*r*r_dot")["verdict"] == "correct"


def test_a_wrong_follow_up_gets_a_hint_not_the_velocity():
    pb = step_problem("double-pendulum", "kinetic", None)
    first = judge(pb, "m1*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2")
    wrong = judge_follow_up(pb, first["follow_up"]["key"], "l2*theta1_dot")
    assert wrong["verdict"] == "incorrect"
    assert "l₁ θ̇₁ cos" not in wrong["hint"] and "velocity (" not in wrong["hint"], wrong["hint"]
    assert "upper bob" in wrong["hint"], wrong["hint"]


def test_the_wedge_held_still_is_named_not_a_t_that_has_a_mistake():
    for step, answer in (("equation", "m*D_ddot - m*g*sin(alpha)"), ("acceleration", "0")):
        coordinate = "D" if step == "equation" else "X"
        result = judge(step_problem("movable-incline", step, coordinate), answer)
        text = read(result)
        # an acceleration says the wedge is held fixed, as the derivation's own limit does (review prof-q 1)
        assert ("held still" in text or "held fixed" in text) and "M → ∞" in text and "that has a mistake" not in text, text


def test_messages_are_short_sentences():
    upside = judge(step_problem("simple-pendulum", "acceleration", "theta"), "-R/g*sin(theta)")
    for sentence in upside["hint"].split(". "):
        assert sentence.count(":") <= 1, upside["hint"]
    constant = judge(step_problem("simple-pendulum", "potential", None), "m*g*R*cos(theta)")
    assert "constants in U are ignored in this comparison" in constant["message"], constant["message"]
    h = judge(
        step_problem("movable-incline", "hamiltonian", None),
        "M*X_dot**2/2 + m*(X_dot**2 + D_dot**2 + 2*D_dot*X_dot*cos(alpha))/2 + m*g*D*sin(alpha)",
    )
    assert "energy function h" in h["hint"] and "Hamiltonian is h" not in h["hint"], h["hint"]


def test_a_bare_number_added_to_an_energy_is_a_units_mistake():
    result = judge(step_problem("simple-pendulum", "hamiltonian", None),
                   "m*R**2*theta_dot**2/2 - m*g*R*cos(theta) + 7")  # fmt: skip
    assert result["verdict"] == "incorrect" and "7 has no unit and cannot be added to an energy" in result["hint"]
    # a pure number beside a pure number is fine (1 − cos θ), and so is another zero of U written with units
    fine = judge(step_problem("simple-pendulum", "hamiltonian", None),
                 "m*R**2*theta_dot**2/2 - m*g*R*cos(theta) + 7*m*g*R")  # fmt: skip
    assert fine["verdict"] == "equivalent", fine


@pytest.mark.parametrize(
    ("reply", "named"),
    [
        # student-e, 8: the lower bob's T as if it swung from a fixed pivot
        ("m2*l2**2*theta2_dot**2/2", "leaves out the part of the lower bob's velocity that comes from θ̇₁"),
        ("m2*(l1**2*theta1_dot**2 + l2**2*theta2_dot**2)/2", "leaves out the cross term in θ̇₁ θ̇₂"),
        (
            "m2*l1**2*theta1_dot**2 + m2*l2**2*theta2_dot**2 + 2*m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2)",
            "without its ½",
        ),
    ],
)
def test_a_wrong_reply_to_a_follow_up_is_diagnosed_by_the_steps_own_mistakes(reply, named):
    pb = step_problem("double-pendulum", "kinetic", None)
    first = judge(pb, "m1*l1**2*theta1_dot**2/2")
    assert first["follow_up"]["question"] == "What is the kinetic energy of the lower bob alone?"
    wrong = judge_follow_up(pb, first["follow_up"]["key"], reply)
    assert wrong["verdict"] == "incorrect" and wrong["hint"].startswith("Your reply"), wrong["hint"]
    assert named in wrong["hint"], wrong["hint"]
    if "θ̇₁" in named and "cross" not in named:
        assert "The upper bob carries the lower bob along with it." in wrong["hint"]


@pytest.mark.parametrize(
    ("scene", "typed", "said", "with_unit"),
    [
        # student-h 3: a bare number inside a bracket took the bracket's units, and the answer read as another zero
        # of U ("plus the constant 3mg", a force)
        ("helix-bead", "m*g*(z + 3)", "3 has no unit and cannot be added to a length", "m*g*(z + 3*R)"),
        (
            "simple-pendulum",
            "m*g*(R*(1 - cos(theta)) + 2)",
            "2 has no unit and cannot be added to a length",
            "m*g*(R*(1 - cos(theta)) + 2*R)",
        ),
        # issue 40: the pulley names its lengths (d, c), so it is held to the same rule; it was exempt while its
        # own middle height read −(y₁ + y₂)/2 − 1
        (
            "pulley",
            "g*(m1*y1 + m2*y2) - M*g*(y1 + y2 + 3)/2",
            "3 has no unit and cannot be added to a length",
            "g*(m1*y1 + m2*y2) - M*g*(y1 + y2 + 3*c)/2",
        ),
    ],
)
def test_a_bare_number_inside_a_bracket_is_a_units_mistake(scene, typed, said, with_unit):
    result = judge(step_problem(scene, "potential", None), typed)
    assert result["verdict"] == "incorrect" and said in result["hint"], result
    # the same zero moved with its unit is another zero of U
    fine = judge(step_problem(scene, "potential", None), with_unit)
    assert fine["verdict"] == "equivalent", fine


@pytest.mark.parametrize(
    ("reply", "said"),
    [
        # student-h 9: the derivative of cos(θ₁ − θ₂) without the argument's rate got only "work it out on its own"
        ("-sin(theta1 - theta2)", "left out the chain rule's factor θ̇₁ − θ̇₂"),
        ("sin(theta1 - theta2)*(theta1_dot - theta2_dot)", "the opposite sign"),
    ],
)
def test_a_wrong_reply_to_a_chain_rule_question_is_named(reply, said):
    pb = step_problem("double-pendulum", "equation", "theta1")
    slip = next(m for m, _, _ in pb.mistakes if m.key == "equation.chain_rule.theta2")
    first = judge(pb, sp.sstr(slip.expr))
    assert first["follow_up"]["key"] == "equation.chain_rule.theta2", first
    wrong = judge_follow_up(pb, first["follow_up"]["key"], reply)
    assert wrong["verdict"] == "incorrect" and said in unicodedata.normalize("NFC", wrong["hint"]), wrong["hint"]


@pytest.mark.parametrize(
    ("scene", "typed", "question"),
    [
        ("helix-bead", "1/2*m*z_dot**2", "What is the bead's speed along x and y?"),
        ("rotating-parabola", "1/2*m*(rho_dot**2 + rho**2*omega**2)", "What is the bead's speed along z?"),
    ],
)
def test_the_line_above_a_follow_up_does_not_print_its_answer(scene, typed, question):
    # issue 41, 2: "the bead's motion in the x–y plane, of speed R α ż", then "What is the bead's speed along x and y?"
    pb = step_problem(scene, "kinetic", None)
    first = judge(pb, typed)
    assert first["follow_up"]["question"] == question, first
    answer = pb.mistake(first["follow_up"]["key"]).follow_up.answer_text
    assert answer not in read(first), read(first)


@pytest.mark.parametrize("scene", ["helix-bead", "rotating-parabola", "rail-two-body", "simple-pendulum"])
def test_no_question_is_asked_whose_answer_its_words_print(scene):
    from app.engine.tutor.diagnose import sentence
    from app.engine.tutor.mistake_families import states_answer

    pb = step_problem(scene, "potential" if scene == "rail-two-body" else "kinetic", None)
    asked = [(m, hint) for m, hint, _ in pb.mistakes if m.follow_up is not None]
    assert asked
    for m, hint in asked:
        words = " ".join((hint, m.name, m.where, sentence(m, pb.label)))
        assert not states_answer(words, m.follow_up), (m.key, words)
        assert m.follow_up.answer_text not in m.name


def test_a_question_whose_answer_is_printed_before_it_is_not_asked():
    from app.engine.tutor.mistake_families import FollowUp, states_answer

    r, a, zd, xd = sp.symbols("R alpha z_dot X_dot")
    speed = FollowUp("What is its speed?", "kinetic", r * a * zd, "magnitude", "R α ż")
    assert states_answer("the motion in the x–y plane, of speed R α ż", speed)
    assert states_answer("of speed −R α ż", speed)  # either sign, for a speed
    assert not states_answer("the motion in the x–y plane", speed)
    assert not states_answer("of speed R α żz", speed)  # part of a longer formula
    # a lone name says where a part comes from, not what it is
    assert not states_answer("the part that comes from Ẋ", FollowUp("?", "kinetic", xd, "magnitude", "Ẋ"))


def test_a_reply_of_other_units_to_a_follow_up_is_told_its_units():
    # issue 41, 2: R α for the bead's speed got only "Not yet"
    pb = step_problem("helix-bead", "kinetic", None)
    first = judge(pb, "1/2*m*z_dot**2")
    wrong = judge_follow_up(pb, first["follow_up"]["key"], "R*alpha")
    assert wrong["message"] == "Not yet: its units do not agree, as said below.", wrong
    assert wrong["hint"].startswith("Check the units. Your reply is a pure number, but it should be a speed (m/s)."), (
        wrong
    )
    assert wrong["follow_up"]["question"] == first["follow_up"]["question"]
    # a reply of the right units is not told about units
    other = judge_follow_up(pb, first["follow_up"]["key"], "R*alpha*z_dot*2")
    assert other["verdict"] == "incorrect" and "units" not in other["hint"] and "units" not in other["message"]
