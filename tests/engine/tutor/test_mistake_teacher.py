"""A named mistake put in the third person for the teacher, each phrasing the engine speaks to a student in."""

import pytest

from app.engine.tutor.mistake_teacher import for_teacher


@pytest.mark.parametrize(("student", "teacher"), [
    ("sin and cos swapped in your term m g R sin(θ)", "sin and cos swapped in the term m g R sin(θ)"),
    ("the M terms four times too big: that body's velocity is doubled (it moves half as far as you have it)",
     "the M terms four times too big: that body's velocity is doubled (it moves half as far as the answer has it)"),
    ("one of your terms (m₁ g y₂ where m₂ belongs)", "one of the terms (m₁ g y₂ where m₂ belongs)"),
    ("you differentiated L with respect to θ̇₂", "the answer differentiates L with respect to θ̇₂"),
    ("In your U, the sign of your gravitational energy is wrong", "In the U, the sign of the gravitational energy is wrong"),
    ("Your term m R² θ̇² without its ½", "The term m R² θ̇² without its ½"),
    ("a T that leaves out the θ̇² part of T", "a T that leaves out the θ̇² part of T"),  # already third person
    ("the young pendulum", "the young pendulum"),  # "you" only as a word
])
def test_the_student_is_spoken_about(student, teacher):
    assert for_teacher(student) == teacher
