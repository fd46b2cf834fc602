"""Hypothesis properties of the expression parser."""

import math

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.engine.parser.parse import (
    ALLOWED_CHARACTERS,
    FUNCTIONS,
    RESERVED,
    ExpressionError,
    check_name,
    parse_expression,
)

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

NAMES = {n: sp.Symbol(n, real=True) for n in ("x", "x_dot", "y", "m", "t")}
SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# A grammar of allowed expressions, generated with the SymPy expression each should build.
leaves = st.one_of(
    st.sampled_from(sorted(NAMES)).map(lambda n: (n, NAMES[n])),
    st.integers(0, 999).map(lambda k: (str(k), sp.Integer(k))),
    st.sampled_from(["0.5", "2.25", "0.125"]).map(lambda s: (s, sp.Rational(s))),
    st.just(("pi", sp.pi)),
)
SAFE_FUNCTIONS = ("sin", "cos", "atan", "tanh", "Abs")  # defined and real everywhere


def _extend(children):
    binary = st.tuples(children, st.sampled_from(["+", "-", "*"]), children).map(
        lambda t: (f"({t[0][0]}) {t[1]} ({t[2][0]})", _apply(t[1], t[0][1], t[2][1]))
    )
    power = st.tuples(children, st.integers(0, 3)).map(lambda t: (f"({t[0][0]})**{t[1]}", t[0][1] ** t[1]))
    call = st.tuples(st.sampled_from(SAFE_FUNCTIONS), children).map(
        lambda t: (f"{t[0]}({t[1][0]})", FUNCTIONS[t[0]](t[1][1]))
    )
    negate = children.map(lambda c: (f"-({c[0]})", -c[1]))
    return st.one_of(binary, power, call, negate)


def _apply(op, a, b):
    return {"+": a + b, "-": a - b, "*": a * b}[op]


expressions = st.recursive(leaves, _extend, max_leaves=12)


@SETTINGS
@given(expressions)
def test_allowed_expressions_build_what_they_say(pair):
    text, expected = pair
    try:
        result = parse_expression(text, NAMES)
    except ExpressionError as exc:
        # only the size limits may refuse a generated expression
        assert "expand into more than" in str(exc) or "too large" in str(exc), (text, str(exc))
        return
    assert result == expected


@SETTINGS
@given(expressions)
def test_printed_expressions_parse_back(pair):
    text, expected = pair
    printed = sp.sstr(expected)
    try:
        again = parse_expression(printed, NAMES)
    except ExpressionError as exc:
        # arithmetic on literals can print a number longer than a typed literal may be
        limits = ("expand into more than", "too large", "exponent", "15 digits", "out of range")
        assert any(words in str(exc) for words in limits), (printed, str(exc))
        return
    # equal as functions (SymPy may leave equal forms apart, such as Abs(Abs(m)) and Abs(m))
    for point in (
        {"x": 0.3, "x_dot": -1.7, "y": 2.1, "m": -0.6, "t": 1.3},
        {"x": -2.2, "x_dot": 0.4, "y": -0.9, "m": 1.1, "t": 0.2},
    ):
        values = {NAMES[k]: sp.Float(v) for k, v in point.items()}
        a, b = complex(again.xreplace(values).evalf(30)), complex(expected.xreplace(values).evalf(30))
        assert abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b)), (text, printed)


@SETTINGS
@given(st.text(max_size=80))
def test_any_text_is_an_expression_or_a_located_refusal(text):
    try:
        result = parse_expression(text, NAMES)
    except ExpressionError as exc:
        assert str(exc)
        if exc.start is not None:
            # the refusal points inside the text, at the part it names
            assert 0 <= exc.start <= exc.end <= len(text)
            assert exc.part.rstrip(".")[:10] in text.translate({9: " ", 10: " ", 13: " "})
        return
    assert isinstance(result, sp.Expr)
    assert result.free_symbols <= set(NAMES.values())
    assert not result.has(sp.I, sp.zoo, sp.nan)


code_like = st.text(alphabet=sorted(ALLOWED_CHARACTERS) + list("'\"[]{}:;=<>!@#$%^&|~`\\"), max_size=60)


@SETTINGS
@given(code_like)
def test_text_near_the_grammar_never_raises_anything_else(text):
    try:
        result = parse_expression(text, NAMES)
    except ExpressionError:
        return
    assert result.free_symbols <= set(NAMES.values())


@SETTINGS
@given(st.from_regex(r"[A-Za-z][A-Za-z0-9]{0,15}", fullmatch=True))
def test_names_of_the_pattern_pass_unless_reserved(name):
    try:
        assert check_name(name) == name
        assert name not in RESERVED
    except ExpressionError:
        assert name in RESERVED or name.endswith("dot")


@SETTINGS
@given(st.text(max_size=20).filter(lambda s: not s.isascii() or not s.isalnum() or "_" in s or not s[:1].isalpha()))
def test_names_off_the_pattern_are_refused(name):
    try:
        check_name(name)
    except ExpressionError:
        return
    raise AssertionError(f"{name!r} should be refused")


@SETTINGS
@given(st.floats(allow_nan=False, allow_infinity=False, min_value=-1e15, max_value=1e15))
def test_decimal_literals_are_exact(value):
    text = repr(abs(value))
    result = parse_expression(text, NAMES)
    assert result == sp.Rational(text)
    assert math.isclose(float(result), abs(value), rel_tol=1e-15, abs_tol=0.0)
