"""A verdict quotes what the student wrote and blames the step the slip is in (review student-m, issue 41): the
student's own term, never the engine's unsimplified or constant-padded one."""

from __future__ import annotations

from app.engine.check import judge
from tests.engine.test_check_slips import step_problem


def test_a_coupling_terms_sign_is_quoted_as_the_student_multiplied_it_out():
    # ∂/∂x₁ of ½ κ (x₂ − x₁)² is κ (2 x₁ − 2 x₂)/2 in the engine's form: the student wrote κ x₂, never a 2
    result = judge(step_problem("coupled-oscillators", "equation", "x1"), "m*x1_ddot + (k+kappa)*x1 + kappa*x2")
    name = result["mistake"]["name"]
    assert name.startswith("your term +κ x₂, which should be −κ x₂"), name
    assert "2" not in name.replace("x₂", "").replace("₂", ""), name
    assert "the term +κ x₂, which should be −κ x₂" in result["hint"], result["hint"]


def test_a_sum_the_student_kept_whole_is_quoted_without_the_engines_common_factor():
    result = judge(step_problem("coupled-oscillators", "equation", "x1"), "m*x1_ddot + k*x1 + kappa*(x1 + x2)")
    assert result["mistake"]["name"].startswith("x₁ + x₂ where x₁ − x₂ belongs: the sign of x₂"), result["mistake"]


def test_a_doubled_group_in_u_is_quoted_without_the_constant_the_student_never_wrote():
    result = judge(step_problem("pulley", "potential", None), "m1*g*y1 + m2*g*y2 - M*g*(y1+y2)")
    name = result["mistake"]["name"]
    assert name == "the M terms, −M (y₁ + y₂) g, twice what they should be", name
    assert "c" not in name.replace("twice", "").replace("should", ""), name
