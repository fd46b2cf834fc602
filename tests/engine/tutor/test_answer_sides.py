"""An answer typed with '=' (app/engine/tutor/answer_sides.py): an equation as lhs = rhs, elsewhere refused plainly."""

from __future__ import annotations

import pytest

from app.engine.tutor.answer_sides import read_answer
from app.engine.tutor.check import CheckError, name_kinds

KINDS = name_kinds(("theta",), ("m", "g", "R"), ())


def test_an_equation_typed_lhs_equals_rhs_is_lhs_minus_rhs():
    parsed, equation = read_answer("theta_ddot = -g/R*sin(theta)", "equation", "theta", KINDS)
    assert equation and parsed.text == "theta_ddot  - ( -g/R*sin(theta))"


def test_an_acceleration_typed_with_its_name_is_its_right_hand_side():
    parsed, equation = read_answer("theta_ddot = -g/R*sin(theta)", "acceleration", "theta", KINDS)
    assert not equation and parsed.text.strip() == "-g/R*sin(theta)"


@pytest.mark.parametrize("text", ["omega^2 = g/R", "ω² = g/R", " omega**2= g/R"])
def test_a_frequency_typed_with_its_square_is_its_right_hand_side(text):
    # issue 41, 6 (student-k 11): the ω² box takes ω² = …, as the θ̈ box takes θ̈ = …
    parsed, equation = read_answer(text, "omega_squared", None, KINDS)
    assert not equation and parsed.text.strip() == "g/R"


def test_the_frequency_is_the_documents_letter_where_omega_is_a_parameter():
    # the rotating wire turns at the rate ω, so its frequency is Ω: Ω² = … is read, ω² = … is refused
    kinds = name_kinds(("rho",), ("m", "g", "alpha", "omega"), ())
    parsed, _ = read_answer("Omega^2 = 2*g*alpha - omega^2", "omega_squared", None, kinds)
    assert parsed.text.strip() == "2*g*alpha - omega^2"
    with pytest.raises(CheckError) as refused:
        read_answer("omega^2 = 2*g*alpha", "omega_squared", None, kinds)
    assert "the left of '=' must be Ω² (type Omega^2): write Ω² = …" in str(refused.value)
    assert refused.value.start == 0 and refused.value.end == len("omega^2 ")


@pytest.mark.parametrize(
    ("text", "step", "says", "marked"),
    [
        ("T = m*R**2*theta_dot**2/2", "kinetic", "type only the right-hand side", "="),
        ("m*g = 2", "lagrangian", "type only the right-hand side", "="),
        ("R*theta_ddot = -g*sin(theta)", "acceleration", "the left of '=' must be the acceleration θ̈ (type theta_ddot): write θ̈ = …", "R*theta_ddot "),
        ("a = b = c", "equation", "write one '=' only", "="),
        ("theta_ddot = ", "equation", "one side of '=' is empty", "="),
        # a side's refusal quotes what was typed, at its columns, without the side's own column
        ("theta_ddot = -g*sin(theta", "equation", "the '(' is never closed", " -g*sin(theta"),
        ("T - U", "lagrangian", "write T and U out in the coordinates", "T"),
        # a declared name typed in the other case is named, not taken for a quantity or an unknown
        ("m*r**2*theta_dot**2/2", "kinetic", "r is not a parameter here; did you mean R?", "r"),
        ("-m*g*R*cos(Theta)", "potential", "Theta is not a coordinate here; did you mean theta?", "Theta"),
        # the parser's refusals said as a tutor says them (student-e, 15)
        ("m*g*l*(1 - cos(theta))", "potential", "l is not a name in this problem; the names you may use are R, g, m, t, θ (type theta) and pi", "l"),
        ("diff(theta, t)", "equation", "a derivative cannot be typed here: work it out", "diff"),
        ("foo(theta)", "potential", "foo is not a function you may use here; the functions are abs, acos,", "foo"),
        ("m*g*R*ln(theta)", "potential", "the natural logarithm is typed log(x)", "ln"),
    ],
)
def test_what_cannot_be_read_is_said_plainly(text, step, says, marked):
    with pytest.raises(CheckError) as refused:
        read_answer(text, step, "theta", KINDS)
    error = refused.value
    assert says in str(error) and "column" not in str(error)
    assert text[error.start : error.end] == marked


def test_half_glued_to_a_factor_is_told_how_to_type_it():
    with pytest.raises(CheckError) as refused:
        read_answer("1/2m R^2 theta_dot^2", "kinetic", None, KINDS)
    said = str(refused.value)
    assert said.endswith("for the first, put a space after 1/2") and "column" not in said


@pytest.mark.parametrize(
    ("text", "step", "says", "marked"),
    [
        # student-d, 14: program words ("unknown name 'd'", "without any q_ddot") said as a tutor says them
        ("d/dt(m*R**2*theta_dot) + m*g*R*sin(theta)", "equation", "a derivative cannot be typed here: work it out", "d"),
        ("dL/dtheta_dot", "momentum", "a derivative cannot be typed here", "dL"),
        ("-g/R*sin(theta) + theta_ddot", "acceleration", "an acceleration cannot appear on the right: solve the "
         "equations of motion for θ̈ alone", "theta_ddot"),  # fmt: skip
        # ½ alone is read as (1/2); a whole number before it is refused, since 2½ could be a sum or a product
        ("2½*m*R**2*theta_dot**2", "kinetic", "write 2 + 1/2 for the sum or 2*(1/2) for a product", "2½"),
    ],
)
def test_a_derivative_an_acceleration_on_the_right_and_a_fraction_are_said_in_a_tutors_words(text, step, says, marked):
    with pytest.raises(CheckError) as refused:
        read_answer(text, step, "theta", KINDS)
    error = refused.value
    assert says in str(error) and "unknown name" not in str(error) and "q_ddot" not in str(error)
    assert text[error.start : error.end] == marked


def test_the_readings_of_an_ambiguous_text_write_python_powers_as_a_reader_does():
    with pytest.raises(CheckError) as refused:
        read_answer("1/2m R**2 theta_dot**2", "kinetic", None, KINDS)
    said = str(refused.value)
    assert "could be read as (1/2) m R² θ" in said or "could be read as (1/2) m R² theta" in said
    assert "**" not in said.split("could be read as")[1]


def test_names_typed_together_with_a_function_are_told_apart():
    from app.engine.tutor.answer_sides import read_answer

    with pytest.raises(CheckError) as caught:
        read_answer("mgRcos(theta)", "potential", None, KINDS)
    assert "write m g R cos(…), with a space or * between the names" in str(caught.value)
    with pytest.raises(CheckError) as caught:
        read_answer("xcos(theta)", "potential", None, KINDS)  # x is no name here: the functions are listed
    assert "is not a function you may use here" in str(caught.value)


def test_the_functions_are_listed_as_a_sentence_without_abs():
    with pytest.raises(CheckError) as caught:
        read_answer("foo(theta)", "potential", None, KINDS)
    said = str(caught.value)
    assert "Abs" not in said and said.endswith("tan and tanh"), said


@pytest.mark.parametrize(
    ("left", "coordinate"),
    [
        ("θ\u0308", "theta"),  # θ and a combining diaeresis (no precomposed θ̈ exists)
        ("theta\u0308", "theta"),
        ("θ''", "theta"),
        ("θddot", "theta"),
        ("\u1e8d", "x"),  # ẍ precomposed (NFC)
        ("x\u0308", "x"),  # x and a combining diaeresis (NFD)
        ("x''", "x"),
    ],
)
def test_an_acceleration_typed_as_printed_names_the_left_side(left, coordinate):
    # issue 41, item 2: θ̈ = … was refused in the acceleration box ("must be theta_ddot") while read everywhere else
    import unicodedata

    kinds = name_kinds((coordinate,), ("m", "g", "R", "k"), ())
    for form in ("NFC", "NFD"):
        text = unicodedata.normalize(form, f"{left} = -g/R sin({coordinate})")
        parsed, equation = read_answer(text, "acceleration", coordinate, kinds)
        assert not equation and parsed.text.strip() == f"-g/R sin({coordinate})", (form, parsed.text)
    # another coordinate's acceleration, or a velocity, is still not the left side
    for other in ("θ\u0307", "y\u0308"):
        with pytest.raises(CheckError) as refused:
            read_answer(f"{other} = -g/R", "acceleration", coordinate, kinds)
        assert "the left of '=' must be the acceleration" in str(refused.value)
