"""Expression trees from SymPy objects and from checked text: Python's precedence, long derived sums,
bounded depth, and the same values as SymPy and Python."""

import math

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from app.engine.document.trees import MAX_DEPTH, TreeError, of_sympy, of_text
from app.engine.parser.parse import ExpressionError, parse_expression
from app.viz.exprtree import evaluate

ENV = {"x": 0.7, "y": -1.3, "x_dot": 0.4}
FUNCTIONS = {"sin": math.sin, "cos": math.cos, "exp": math.exp, "atan": math.atan, "Abs": abs}
x, y, x_dot = sp.symbols("x y x_dot")
SYMBOLS = {"x": x, "y": y, "x_dot": x_dot}


@pytest.mark.parametrize(
    "text",
    ["-x**2", "2**-3*x", "x**-2*y", "-x*y", "x - y - x_dot", "x/y/x", "(x + y)**3/2", "-(x + y)*3", "+x", "--x",
     "1.5e-3*x", "sin(x)**2 + cos(-x)", "exp(-x/2)*(x + 1)", "((x + y))*2", "x*(y*(x + 1))", "Abs(y)**0.5"],
)  # fmt: skip
def test_text_reads_like_python(text):
    assert math.isclose(evaluate(of_text(text, ENV), ENV), eval(text, FUNCTIONS, dict(ENV)), rel_tol=1e-12)


@pytest.mark.slow
def test_a_long_derived_sum_is_one_flat_node():
    # a sum of thousands of terms, as a derivation may produce
    expr = sp.log(sp.Add(*(i * x * x_dot for i in range(1, 3301))) + y**2)
    result = of_sympy(expr)
    assert result[0] == "log" and result[1][0] == "+"
    assert math.isclose(evaluate(result, ENV), float(expr.subs({x: 0.7, y: -1.3, x_dot: 0.4})), rel_tol=1e-12)


def test_a_long_sum_of_text_is_one_flat_node():
    text = " - ".join(f"{i}*x" for i in range(1, 120))
    result = of_text(text, ["x"])
    assert result[0] == "+" and len(result) == 120
    assert math.isclose(evaluate(result, ENV), eval(text, {}, dict(ENV)), rel_tol=1e-12)


@pytest.mark.slow
def test_deep_nesting_is_refused_not_overflowed():
    deep = x
    for _ in range(MAX_DEPTH + 1):
        deep = sp.sin(deep)
    with pytest.raises(TreeError, match="deeper"):
        of_sympy(deep)
    with pytest.raises(TreeError):
        of_text("sin(" * 50 + "x" + ")" * 50, ["x"])
    with pytest.raises(TreeError):
        of_text("-" * 5000 + "x", ["x"])


@pytest.mark.parametrize(
    "text", ["x y z", "(x", "x)", "sin()", "()", "x +", "*x", "sin(x, y)", "x; y", "x.y", "__import__('os')", "z"]
)
def test_malformed_or_unknown_text_is_refused(text):
    with pytest.raises(TreeError):
        of_text(text, ["x", "y"])


@pytest.mark.parametrize("expr", [sp.I * x, sp.oo + x, sp.Piecewise((x, x > 0), (0, True)), sp.Max(x, y), sp.zoo])
def test_what_the_browser_cannot_evaluate_has_no_tree(expr):
    with pytest.raises(TreeError):
        of_sympy(expr)


def test_text_beyond_the_parsers_length_is_refused_before_it_is_parsed():
    with pytest.raises(TreeError, match="at most"):
        of_text("x + " * 100_000 + "x")
    with pytest.raises(TreeError):
        of_text(None)  # type: ignore[arg-type]


def test_any_name_when_none_are_given():
    assert of_text("qmin_x - 0.25*(qmax_x - qmin_x)") == [
        "+", "qmin_x", ["neg", ["*", 0.25, ["+", "qmax_x", ["neg", "qmin_x"]]]]
    ]  # fmt: skip
    with pytest.raises(TreeError):
        of_text("sin + x")  # a function's name is not a name


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


@pytest.mark.slow
@settings(max_examples=200, deadline=None)
@given(expressions)
def test_both_ways_agree_with_python_on_generated_expressions(text):
    try:
        expected = eval(text, FUNCTIONS, dict(ENV))
    except (ZeroDivisionError, OverflowError, ValueError, TypeError):
        # TypeError: a negative base to a fractional power is complex in Python, and math.sin refuses it
        return
    if isinstance(expected, complex) or not math.isfinite(expected):
        return
    try:
        trees = [of_text(text, ENV)]
        expr = parse_expression(text, SYMBOLS)
        trees.append(of_sympy(expr))
    except (TreeError, ExpressionError):
        return  # refused by the parser's gates (a tower of exponents, an undefined value): no figure
    for tree in trees:
        try:
            got = evaluate(tree, ENV)
        except (ZeroDivisionError, OverflowError, ValueError, TypeError):
            # TypeError: a complex intermediate, which Python's abs makes real again but a figure, like the
            # browser, cannot draw
            continue
        assert math.isclose(got, expected, rel_tol=1e-9, abs_tol=1e-12), (text, tree)
