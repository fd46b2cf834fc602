"""Gate 0 of the parser: expressions as students type them (tests/data/typed_expressions.json), read as meant
or refused with both readings; and what gate 0 writes stays inside the allowlist's grammar."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from app.engine.check import CheckError, check_answer, name_kinds, parse_answer
from app.engine.parse import ALLOWED_CHARACTERS, ExpressionError, build, check_name, parse_expression, read, typed

DATA = json.loads((Path(__file__).parents[1] / "data" / "typed_expressions.json").read_text())
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


def test_the_worker_builds_what_the_web_process_read():
    # the reading crosses to the worker as a Parsed (never the text) and builds the same expression there
    import pickle

    from app.engine.check import problem
    from app.engine.derive import derive
    from app.scenes import SCENES

    pb = problem(derive(SCENES["simple-pendulum"].system), "kinetic")
    parsed = check_answer("(1/2) m R^2 θ'^2", "kinetic", pb.kinds)
    expr = parse_answer(pb, pickle.loads(pickle.dumps(parsed)))
    assert sp.simplify(expr - parse_expression("m*R**2*theta_dot**2/2", pb.namespace)) == 0


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
