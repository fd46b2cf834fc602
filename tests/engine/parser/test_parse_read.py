"""Reading once (app/engine/parser/read.py): ``narrowed`` holds what was read to fewer names, as reading again would."""

from itertools import combinations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.engine.parser.parse import ExpressionError, Parsed, narrowed, read

NAMES = ("x", "x_dot", "x_ddot", "y", "p_y", "m", "t")
SETTINGS = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def outcome(work) -> tuple:
    """What a reading gives: the Parsed's every field, or the refusal's words and span."""
    try:
        p: Parsed = work()
    except ExpressionError as exc:
        return ("refused", str(exc), exc.part, exc.start, exc.end)
    return ("read", p.text, p.tree, p.size, p.names)


def same_as_reading_again(text: str, fewer: frozenset[str]) -> None:
    wide = read(text, NAMES)
    assert outcome(lambda: narrowed(wide, fewer)) == outcome(lambda: read(text, fewer))


TEXTS = [
    "m*x_dot**2/2 - m*y",
    "  sin(x)**2 + p_y*t\t",
    "exp(2*log(x_ddot)) + (y + x)**3 - pi",
    "atan2(y, x) / (1 + p_y**2)",
    "-(-(x + y*(m - t)))",
    "x_dot*x_ddot + m",
]


@pytest.mark.slow
@pytest.mark.parametrize("text", TEXTS)
def test_every_narrower_set_of_names_gives_what_reading_again_gives(text):
    for k in range(len(NAMES) + 1):
        for fewer in combinations(NAMES, k):
            same_as_reading_again(text, frozenset(fewer))


def test_the_refusal_is_the_first_name_left_out_in_the_order_of_the_text():
    wide = read("m*(x + 1) + p_y*y", NAMES)
    with pytest.raises(ExpressionError) as refused:
        narrowed(wide, {"x", "m"})
    assert str(refused.value) == "unknown name (allowed here: m, x, pi): 'p_y' at column 13"
    assert (refused.value.part, refused.value.start, refused.value.end) == ("p_y", 12, 15)


def test_the_same_names_give_the_same_reading_and_more_names_are_refused():
    wide = read("x + y", NAMES)
    assert narrowed(wide, frozenset(NAMES)) is wide
    with pytest.raises(ValueError, match="was not read against these names: z"):
        narrowed(wide, {*NAMES, "z"})


leaves = st.sampled_from([*NAMES, "pi", "2", "0.5", "(x - x)"])
functions = st.sampled_from(["sin", "cos", "exp", "log", "sqrt", "asin", "Abs"])
expressions = st.recursive(
    leaves,
    lambda inner: st.one_of(
        st.tuples(inner, st.sampled_from(["+", "-", "*", "/"]), inner).map(lambda p: f"({p[0]}){p[1]}({p[2]})"),
        st.tuples(inner, st.sampled_from(["2", "-1", "0.5", "3"])).map(lambda p: f"({p[0]})**{p[1]}"),
        st.tuples(functions, inner).map(lambda p: f"{p[0]}({p[1]})"),
        st.tuples(inner, inner).map(lambda p: f"atan2({p[0]}, {p[1]})"),
    ),
    max_leaves=12,
)


@pytest.mark.slow
@SETTINGS
@given(expressions, st.sets(st.sampled_from(NAMES)))
def test_narrowing_any_expression_is_reading_it_again(text, fewer):
    try:
        read(text, NAMES)
    except ExpressionError:
        return  # nothing read to narrow
    same_as_reading_again(text, frozenset(fewer))
