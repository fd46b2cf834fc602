"""Gate 0 of the parser: expressions as students type them (tests/data/typed_expressions.json), read as meant
or refused with both readings; and what gate 0 writes stays inside the allowlist's grammar."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from app.engine.parser.parse import (
    ALLOWED_CHARACTERS,
    ExpressionError,
    build,
    check_name,
    parse_expression,
    read,
    typed,
)
from app.engine.tutor.check import CheckError, check_answer, name_kinds, parse_answer

DATA = json.loads((Path(__file__).parents[2] / "data" / "typed_expressions.json").read_text())
CORPUS = DATA["corpus"]
KINDS = name_kinds(tuple(DATA["coordinates"]), tuple(DATA["parameters"]), ())
NAMES = {name: sp.Symbol(name, real=True) for name, kind in KINDS.items() if kind != "acceleration"}


def _id(case: dict) -> str:
    return case["typed"].encode("unicode_escape").decode()


def test_the_corpus_is_large_and_covers_each_way_of_typing():
    assert len(CORPUS) >= 60
    texts = [c["typed"] for c in CORPUS]
    assert sum("^" in t for t in texts) >= 10
    assert sum(any(ch in t for ch in "θφωαϕπ") for t in texts) >= 20
    assert sum(any(ch in t for ch in "'′’") for t in texts) >= 10
    assert sum("\u0307" in t or "ẋ" in t for t in texts) >= 4
    assert sum("readings" in c for c in CORPUS) >= 10


@pytest.mark.parametrize("case", [c for c in CORPUS if "reads" in c], ids=_id)
def test_read_as_meant(case):
    # the checker's reading of the answer (the step's name rules, then the parser), built in SymPy
    parsed = check_answer(case["typed"], "lagrangian", KINDS)
    got = build(parsed, NAMES)
    meant = parse_expression(case["reads"], NAMES)
    assert sp.simplify(got - meant) == 0, (got, meant)


@pytest.mark.parametrize("case", [c for c in CORPUS if "readings" in c], ids=_id)
def test_ambiguous_text_is_refused_with_both_readings(case):
    text = case["typed"]
    with pytest.raises(CheckError) as refused:
        check_answer(text, "lagrangian", KINDS)
    error = refused.value
    assert error.readings == tuple(case["readings"])
    first, second = case["readings"]
    assert f"could be read as {first} or as {second}" in str(error)
    # the refusal points at the part of the text that reads two ways
    assert 0 <= error.start < error.end <= len(text) and text[error.start : error.end] == error.part
    # and each reading, typed as shown, is read without a refusal: the student can take either
    for reading in case["readings"]:
        try:
            read(reading, NAMES)
        except ExpressionError as exc:
            assert "towers of exponents" in str(exc) or "exponents must be numbers" in str(exc), exc


@pytest.mark.parametrize("case", [c for c in CORPUS if "refused" in c], ids=_id)
def test_refused_with_what_to_write(case):
    with pytest.raises(CheckError) as refused:
        check_answer(case["typed"], "lagrangian", KINDS)
    assert case["refused"] in str(refused.value)
    assert not refused.value.readings


@pytest.mark.slow
def test_the_worker_builds_what_the_web_process_read():
    # the reading crosses to the worker as a Parsed (never the text) and builds the same expression there
    import pickle

    from app.engine.derivation.derive import derive
    from app.engine.tutor.check import problem
    from app.scenes import SCENES

    pb = problem(derive(SCENES["simple-pendulum"].system), "kinetic")
    parsed = check_answer("(1/2) m R^2 θ'^2", "kinetic", pb.kinds)
    expr = parse_answer(pb, pickle.loads(pickle.dumps(parsed)))
    assert sp.simplify(expr - parse_expression("m*R**2*theta_dot**2/2", pb.namespace)) == 0


# the instructor's forms (issue 45): a coefficient as a physicist writes one is read, what physicists write
# meaning either is refused with both readings
OTHER = {name: sp.Symbol(name, real=True) for name in ("m", "R", "theta_dot", "l", "g", "p", "k", "x", "M", "y2_dot")}
OTHER["theta"] = sp.Symbol("theta", real=True)


@pytest.mark.parametrize(
    ("text", "meant"),
    [
        ("1/2 m R^2", "m*R**2/2"),
        ("1/2 m R^2 θ̇^2", "m*R**2*theta_dot**2/2"),
        ("1/2 m (R θ̇)^2", "m*R**2*theta_dot**2/2"),
        ("3/4 m l^2", "3*m*l**2/4"),
        ("-1/2 k x^2", "-k*x**2/2"),
        ("m g - 1/2 k x^2", "m*g - k*x**2/2"),
        ("1/2 (m + M) x'^2", "(m + M)*x_dot**2/2"),
        ("-g/R sin(theta)", "-g*sin(theta)/R"),
        ("g/l sin θ", "g*sin(theta)/l"),
        ("m g/l sin θ", "m*g*sin(theta)/l"),
        ("g/l sin^2 θ", "g*sin(theta)**2/l"),
        ("g/l sin θ cos θ", "g*sin(theta)*cos(theta)/l"),
        # a quotient by one name ends at a space, as in Python and a textbook's −(g/R) θ (issue 41, item 1)
        ("-g/R theta", "-g*theta/R"),
        ("-g/R θ", "-g*theta/R"),
        ("k/m x", "k*x/m"),
        ("g/l^2 x", "g*x/l**2"),
        ("g/l x sin θ", "g*x*sin(theta)/l"),
        ("g/l sin θ x", "g*x*sin(theta)/l"),
        ("g/l sin(θ)x", "g*x*sin(theta)/l"),
    ],
)
def test_a_coefficient_as_a_physicist_writes_it_is_read(text, meant):
    names = OTHER | {"x_dot": sp.Symbol("x_dot", real=True)}
    assert sp.simplify(parse_expression(text, names) - parse_expression(meant, names)) == 0


@pytest.mark.parametrize(
    ("text", "readings"),
    [
        ("1/2m", ("(1/2) m", "1/(2 m)")),  # no space: glued, 1/(2m) is as likely
        ("1/2m R^2", ("(1/2) m R^2", "1/(2 m R^2)")),
        ("1/2(m + M)", ("(1/2) (m + M)", "1/(2 (m + M))")),
        ("p^2/2 m", ("(p^2/2) m", "p^2/(2 m)")),  # the numerator is not a number
        ("g/Rθ", ("(g/R) θ", "g/(R θ)")),  # no space: glued, as 2m is
        ("M/4 y2_dot", ("(M/4) y2_dot", "M/(4 y2_dot)")),  # a number's denominator after a name: p²/2m
        ("1/2^2 m", ("(1/2^2) m", "1/(2^2 m)")),  # the denominator is not a plain number
        ("g/(l x) sin θ x", ("(g/(l x)) sin θ x", "g/((l x) sin θ x)")),  # nor one name
    ],
)
def test_a_factor_after_a_quotient_that_reads_two_ways_is_refused_with_both(text, readings):
    with pytest.raises(ExpressionError) as refused:
        read(text, OTHER)
    assert refused.value.readings == readings
    assert str(refused.value).startswith("a factor after a quotient is ambiguous")


def test_a_glued_fraction_of_numbers_is_told_the_space_that_makes_it_a_coefficient():
    with pytest.raises(ExpressionError) as refused:
        read("1/2m R^2", OTHER)
    assert str(refused.value).endswith(
        "could be read as (1/2) m R^2 or as 1/(2 m R^2); for the first, put a space after 1/2"
    )
    with pytest.raises(ExpressionError) as refused:
        read("g/Rθ", OTHER)  # a quotient by one name: the space makes it the textbook's (g/R) θ
    assert str(refused.value).endswith("could be read as (g/R) θ or as g/(R θ); for the first, put a space after g/R")
    with pytest.raises(ExpressionError) as refused:
        read("p^2/2 m", OTHER)  # no space makes this one a coefficient: the brackets decide
    assert str(refused.value).endswith("write the one you mean, with its brackets")


@pytest.mark.parametrize(
    ("text", "start", "end"),
    [
        ("m g l θ'''", 6, 10),  # the name with its three primes
        ("x + 1/2m", 4, 8),  # the quotient and the factor after it
        ("θ + 2^x^2", 4, 9),
        ("   θ̇ + q", 8, 9),  # an unknown name after a combining dot: columns of the text as typed
    ],
)
def test_refusals_point_at_the_text_as_typed(text, start, end):
    with pytest.raises(ExpressionError) as refused:
        read(text, NAMES)
    assert (refused.value.start, refused.value.end) == (start, end)
    assert refused.value.part == text[start:end]


@pytest.mark.slow
@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.from_regex(r"[A-Za-z][A-Za-z0-9]{0,15}", fullmatch=True))
def test_a_declared_name_is_never_split(name):
    # after a number, e and E followed by digits are its exponent as Python writes it (2e1 is twenty)
    if name[0] in "eE" and name[1:2].isdigit():
        return
    try:
        check_name(name)
    except ExpressionError:
        return
    assert parse_expression(name, {name: sp.Symbol(name)}) == sp.Symbol(name)
    assert parse_expression(f"2{name}", {name: sp.Symbol(name)}) == 2 * sp.Symbol(name)


STUDENT = sorted(ALLOWED_CHARACTERS) + list("^'′’″θφωαπ·×−²³⁻₁\u0307\u0308ẋ{}[]=\"½ｓ")


@pytest.mark.slow
@settings(max_examples=600, deadline=None, derandomize=True)
@given(st.text(alphabet=STUDENT, max_size=40))
def test_student_text_is_read_within_the_allowlist_or_refused(text):
    # gate 0 writes only the characters gate 1 allows, or refuses with an ExpressionError; nothing else
    try:
        written = typed(text)
    except ExpressionError as exc:
        assert exc.start is None or 0 <= exc.start <= exc.end <= len(text)
        return
    assert set(written.text) <= ALLOWED_CHARACTERS
    assert len(written.starts) == len(written.ends) == len(written.text)
    assert all(0 <= s <= e <= len(text) for s, e in zip(written.starts, written.ends, strict=True))
    try:
        result = parse_expression(text, NAMES)
    except ExpressionError as exc:
        assert exc.start is None or 0 <= exc.start <= exc.end <= len(text)
        return
    assert result.free_symbols <= set(NAMES.values())


def test_a_phones_signs_are_read_as_typed():
    # issue 41, 3: ½, ², θ̇, −, · and × from a phone's keyboard or copied notes, read at once
    assert typed("½ m R² θ̇²").text == "(1/2)*m*R**2*theta_dot**2"
    assert typed("½m R²θ̇² − m·g×R").text == "(1/2)*m*R**2*theta_dot**2 - m*g*R"
    names = OTHER | {"theta_dot": sp.Symbol("theta_dot", real=True), "R": sp.Symbol("R", real=True)}
    assert parse_expression("½ m R² θ̇²", names) == parse_expression("m*R**2*theta_dot**2/2", names)
    # a fraction after a name is a factor, never an argument (R½ is R times ½, not a call of R)
    assert parse_expression("m R½", names) == parse_expression("m*R/2", names)


def test_every_refused_character_is_named_in_one_message():
    with pytest.raises(ExpressionError) as refused:
        read("m ≤ g ½ = l |x|", NAMES)
    said = str(refused.value)
    assert said.startswith("4 characters cannot be read: ")  # the ½ is read
    assert "'≤' at column 3 is not allowed: besides the keyboard's letters" in said
    assert "'=' at column 9 is not allowed: an equation is not an expression" in said
    assert "'|' at columns 13 and 15 is not allowed: an absolute value |x| is typed abs(x)" in said
    # the part marked runs from the first refused character to the last
    assert (refused.value.start, refused.value.end) == (2, 15)
    # one refused character is said as before
    with pytest.raises(ExpressionError) as one:
        read("m ≤ g", NAMES)
    assert str(one.value).startswith("character '≤' at column 3 is not allowed")


@pytest.mark.parametrize("text", ["1/2(", "x/2(m + x", "/0("])
def test_a_quotient_before_a_bracket_never_closed_is_refused_in_words(text):
    # (found by the property test once ½ was read: an IndexError, not a refusal)
    with pytest.raises(ExpressionError) as refused:
        read(text, OTHER)
    assert "(" in refused.value.part or "never closed" in str(refused.value) or "cannot be read" in str(refused.value)
