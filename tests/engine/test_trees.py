"""The display-tree reader: Python's precedence, long derived sums, and bounded depth."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.viz.exprtree import MAX_DEPTH, TreeError, evaluate, tree

ENV = {"x": 0.7, "y": -1.3, "x_dot": 0.4}
FUNCTIONS = {"sin": math.sin, "cos": math.cos, "exp": math.exp, "atan": math.atan, "Abs": abs}


@pytest.mark.parametrize(
    "text",
    ["-x**2", "2**-x**2", "x**-y*x", "-x*y", "x - y - x_dot", "x/y/x", "x**2**0.5", "-(x + y)*3", "+x", "--x",
     "1.5e-3*x", "sin(x)**2 + cos(-x)", "exp(-x/2)*(x + 1)", "((x + y))*2", "x*(y*(x + 1))", "Abs(y)**0.5"],
)  # fmt: skip
def test_reads_like_python(text):
    assert math.isclose(evaluate(tree(text, ENV), ENV), eval(text, FUNCTIONS, dict(ENV)), rel_tol=1e-12)


def test_a_long_derived_sum_reads_flat():
    # a sum of thousands of terms (as a derivation may print) once overflowed Python's ast recursion
    text = "log(" + " + ".join(f"{i}*x*x_dot" for i in range(1, 3301)) + ")"
    result = tree(text, ["x", "x_dot"])
    assert result[0] == "log" and result[1][0] == "+" and len(result[1]) == 3301
    assert math.isclose(evaluate(result, ENV), math.log(sum(i * 0.7 * 0.4 for i in range(1, 3301))))


def test_deep_nesting_is_refused_not_overflowed():
    with pytest.raises(TreeError, match="deeper"):
        tree("sin(" * (MAX_DEPTH + 1) + "x" + ")" * (MAX_DEPTH + 1), ["x"])
    with pytest.raises(TreeError, match="deeper"):
        tree("-" * 5000 + "x", ["x"])


@pytest.mark.parametrize("text", ["x y", "(x", "x)", "sin()", "()", "x +", "*x", "sin(x, y)", "x; y", "x.y"])
def test_malformed_text_is_refused(text):
    with pytest.raises(TreeError):
        tree(text, ["x", "y"])


leaves = st.sampled_from(["x", "y", "x_dot", "2", "0.5", "3"])
expressions = st.recursive(
    leaves,
    lambda c: st.one_of(
        st.tuples(c, st.sampled_from(["+", "-", "*", "/"]), c).map(lambda p: f"{p[0]} {p[1]} {p[2]}"),
        st.tuples(c, st.sampled_from(["", "-"]), leaves).map(lambda p: f"({p[0]})**{p[1]}{p[2]}"),
        c.map(lambda e: f"-({e})"),
        st.tuples(st.sampled_from(sorted(FUNCTIONS)), c).map(lambda p: f"{p[0]}({p[1]})"),
    ),
    max_leaves=12,
)


@settings(max_examples=200, deadline=None)
@given(expressions)
def test_agrees_with_python_on_generated_expressions(text):
    try:
        expected = eval(text, FUNCTIONS, dict(ENV))
    except (ZeroDivisionError, OverflowError, ValueError, TypeError):
        # TypeError: a negative base to a fractional power is complex in Python, and math.sin refuses it
        return
    if isinstance(expected, complex) or not math.isfinite(expected):
        return
    try:
        got = evaluate(tree(text, ENV), ENV)
    except (ZeroDivisionError, OverflowError, ValueError, TypeError):
        # TypeError: a complex intermediate (Abs(x + y**x) with y < 0), which Python's abs makes real again
        # but a figure, like the browser, cannot draw
        return
    assert math.isclose(got, expected, rel_tol=1e-9, abs_tol=1e-12), text


def test_every_allowed_function_has_its_latex_with_one_slot_per_argument():
    from app.engine.parse import ALLOWED
    from app.viz.exprtree import function_tex

    tex = function_tex()
    assert set(tex) == set(ALLOWED)
    for name, f in ALLOWED.items():
        assert [f"#{i + 1}" in tex[name] for i in range(3)] == [i < f.arity for i in range(3)], name
    assert tex["asin"].startswith(r"\arcsin") and tex["sqrt"] == r"\sqrt{#1}"
