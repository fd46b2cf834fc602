"""A student's answer typeset as it was typed: the parser's checked tree printed, never evaluated.

The practice boxes' preview lets a student check their own typing, so it prints the structure they wrote
(``1/2*(M+m)*X_dot**2`` is ½ (M + m) Ẋ², never (M/2 + m/2) Ẋ²): no term is distributed, expanded,
reordered or cancelled. Only a textbook's conventions are applied: a quotient in a product is a fraction of
what precedes it, factors are set side by side (a dot between two numbers), a sum inside a product, a
power's base or after a minus keeps its parentheses, sin²θ for sin(θ)², names written as
``app.engine.display.names`` writes them.
"""

from __future__ import annotations

from fractions import Fraction

from app.engine.display.names import latex as name_latex
from app.engine.parser.read import Node, Parsed

# functions printed as operators before their argument (sin θ, sin²θ)
_OPERATORS = {"sin", "cos", "tan", "sinh", "cosh", "tanh", "asin", "acos", "atan"}
_ARC = {"asin": r"\arcsin", "acos": r"\arccos", "atan": r"\arctan"}


def typed_latex(parsed: Parsed) -> str:
    """The LaTeX of an answer as typed (what ``check_answer`` read), structure kept."""
    return _node(parsed.tree)


def typed_equation(parsed: Parsed) -> str:
    """An equation typed lhs = rhs (read as lhs − (rhs), app/engine/tutor/answer_sides.py) printed lhs = rhs."""
    tree = parsed.tree
    rest = tree[4][:-1]
    lhs = _node(("chain", tree[1], tree[2], tree[3], rest)) if rest else _node(tree[3])
    return f"{lhs} = {_node(tree[4][-1][1])}"


def _number(value: int | float) -> str:
    if isinstance(value, int):
        return str(value)
    text = repr(value)
    return text if "e" not in text else str(Fraction(text))


def _is_sum(node: Node) -> bool:
    return node[0] == "chain" and node[4][0][0] in "+-"


def _paren(text: str) -> str:
    return rf"\left({text}\right)"


def _function(name: str) -> str:
    if name in _ARC:
        return _ARC[name]
    return rf"\{name}" if name in _OPERATORS or name in {"exp", "log"} else rf"\operatorname{{{name}}}"


def _argument(arg: Node) -> str:
    """A trigonometric function's argument: bare when a single name or number (sin θ), else in parentheses."""
    text = _node(arg)
    return f" {text}" if arg[0] in ("name", "num") else _paren(text)


def _call(node: Node, power: str | None = None) -> str:
    name, args = node[3], node[4]
    if name == "sqrt":
        body = rf"\sqrt{{{_node(args[0])}}}"
        return body if power is None else rf"{_paren(body)}^{{{power}}}"
    if name == "Abs":  # |x|, typed abs(x) (app/engine/parser/rules.py: TYPED_FUNCTIONS)
        body = rf"\left|{_node(args[0])}\right|"
        return body if power is None else rf"{body}^{{{power}}}"
    if name == "exp":
        body = rf"e^{{{_node(args[0])}}}"
        return body if power is None else rf"{_paren(body)}^{{{power}}}"
    head = _function(name) if name != "log" else r"\ln"
    if name in _OPERATORS and len(args) == 1:
        # sin(θ)² is printed sin²θ, as a textbook prints it
        return (head if power is None else f"{head}^{{{power}}}") + _argument(args[0])
    body = head + _paren(", ".join(_node(a) for a in args))
    return body if power is None else rf"{_paren(body)}^{{{power}}}"


def _factor(node: Node, first: bool) -> str:
    """One factor of a product: a sum, or a sign after the first factor, in parentheses."""
    text = _node(node)
    if _is_sum(node) or (not first and node[0] in ("neg", "pos")):
        return _paren(text)
    return text


def _applied(node: Node) -> bool:
    """A function applied (sin θ, sin²θ): what follows it is set a thin space apart."""
    return node[0] == "call" or (node[0] == "pow" and node[3][0] == "call")


def _join(factors: list[tuple[Node, str]]) -> str:
    """Factors side by side; a dot between two numbers (2 · 3), a thin space after a function's argument."""
    out = ""
    for k, (node, text) in enumerate(factors):
        if k:
            before = factors[k - 1][0]
            leading_number = node[0] == "num" or (node[0] == "pow" and node[3][0] == "num")
            out += r" \cdot " if leading_number else (r"\, " if _applied(before) else " ")
        out += text
    return out


def _product(node: Node) -> str:
    if node[3][0] in ("neg", "pos"):
        # a sign on the first factor is the product's sign: -g/R*sin(theta) is −(g/R) sin θ, printed -g/R sin θ
        sign = "-" if node[3][0] == "neg" else "+"
        return sign + _product(("chain", node[1], node[2], node[3][3], node[4]))
    # a quotient divides everything before it: 1/2*(M+m)*X_dot**2 is ½ (M + m) Ẋ², m*g/(2*R) is mg/(2R)
    numerator: list[tuple[Node, str]] = [(node[3], _factor(node[3], True))]
    for op, operand in node[4]:
        if op == "*":
            numerator.append((operand, _factor(operand, False)))
        else:
            top = _join(numerator)
            bottom = _node(operand)
            # the fraction stands as one factor: a number-like one, so what follows is set beside it
            numerator = [(("frac",), rf"\frac{{{top}}}{{{bottom}}}")]
    return _join(numerator)


def _sum(node: Node) -> str:
    out = _node(node[3])
    for op, operand in node[4]:
        text = _node(operand)
        # a sum after a sign, or a signed term, keeps its parentheses: a - (b - c), a + (-b)
        if _is_sum(operand) or operand[0] in ("neg", "pos"):
            text = _paren(text)
        out += f" {op} {text}"
    return out


def _power(node: Node) -> str:
    base, exponent = node[3], node[4]
    top = _node(exponent)
    if base[0] == "call":
        return _call(base, top)
    text = _node(base)
    if base[0] in ("chain", "neg", "pos", "pow") or (base[0] == "num" and float(base[3]) < 0):
        text = _paren(text)
    return f"{text}^{{{top}}}"


def _node(node: Node) -> str:
    kind = node[0]
    if kind == "num":
        return _number(node[3])
    if kind == "name":
        return name_latex(node[3]) if node[3] != "pi" else r"\pi"
    if kind in ("neg", "pos"):
        operand = node[3]
        text = _node(operand)
        if _is_sum(operand) or operand[0] in ("neg", "pos"):
            text = _paren(text)
        return ("-" if kind == "neg" else "+") + text
    if kind == "chain":
        return _sum(node) if _is_sum(node) else _product(node)
    if kind == "pow":
        return _power(node)
    assert kind == "call"
    return _call(node)
