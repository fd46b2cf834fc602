"""Expression strings -> small JSON trees the browser evaluates (static/js/expr.js).

The derivation JSON carries every expression as a ``sympy`` string in the
project's symbol convention.  The pages need a few of them as numbers in the
browser (the potential along a run, the effective potential over a range, the
particles' positions for the animation), so each string is parsed by Python's
``ast`` module against an allowlist and written as a tree:

    number            -> the number
    symbol            -> its name (a string)
    a + b + c         -> ["+", a, b, c]        a * b -> ["*", a, b]
    -a                -> ["neg", a]            a / b -> ["/", a, b]
    a ** b            -> ["pow", a, b]         sin(a) -> ["sin", a]
    atan2(y, x)       -> ["atan2", y, x]

Nothing is evaluated here and no ``eval`` or ``sympify`` runs on the text.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Iterable
from typing import Any

from app.engine.parse import ARITY
from app.engine.parse import FUNCTIONS as INPUT_FUNCTIONS

# The functions users may write (their one home is the parser), plus sign, which SymPy's derivatives add.
FUNCTIONS = frozenset(INPUT_FUNCTIONS) | {"sign"}
CONSTANTS = {"pi": math.pi, "E": math.e}
MAX_NODES = 5000
_RECIPROCALS = {"cot": "tan", "sec": "cos", "csc": "sin"}

Tree = float | int | str | list[Any]


class TreeError(ValueError):
    """Text outside the allowlist (the caller leaves that figure out)."""


def _build(node: ast.AST, names: frozenset[str] | None) -> Tree:
    if isinstance(node, ast.Expression):
        return _build(node.body, names)
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
        return node.value
    if isinstance(node, ast.Name):
        if node.id == "pi":
            return math.pi
        if names is not None and node.id not in names and node.id in CONSTANTS:
            return CONSTANTS[node.id]
        if names is None or node.id in names:
            return node.id
        raise TreeError(f"unknown name {node.id!r}")
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        inner = _build(node.operand, names)
        if isinstance(node.op, ast.UAdd):
            return inner
        return -inner if isinstance(inner, (int, float)) else ["neg", inner]
    if isinstance(node, ast.BinOp):
        left, right = _build(node.left, names), _build(node.right, names)
        if isinstance(node.op, ast.Add):
            return _flat("+", left, right)
        if isinstance(node.op, ast.Mult):
            return _flat("*", left, right)
        if isinstance(node.op, ast.Sub):
            return _flat("+", left, ["neg", right])
        if isinstance(node.op, ast.Div):
            return ["/", left, right]
        if isinstance(node.op, ast.Pow):
            return ["pow", left, right]
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in FUNCTIONS:
        if len(node.args) == ARITY.get(node.func.id, 1) and not node.keywords:
            return [node.func.id, *(_build(a, names) for a in node.args)]
    raise TreeError(f"{type(node).__name__} is not supported in a figure expression")


def _flat(op: str, left: Tree, right: Tree) -> list[Any]:
    # a + (b + c) -> ["+", a, b, c]: shallower trees evaluate faster in the browser
    items: list[Any] = []
    for part in (left, right):
        if isinstance(part, list) and part and part[0] == op:
            items.extend(part[1:])
        else:
            items.append(part)
    return [op, *items]


def tree(text: str, names: Iterable[str] | None = None) -> Tree:
    """The tree of one expression string; ``names`` (if given) are the only symbols allowed."""
    if not isinstance(text, str) or not text.strip():
        raise TreeError("empty expression")
    try:
        parsed = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        raise TreeError(f"syntax error: {exc.msg}") from None
    if sum(1 for _ in ast.walk(parsed)) > MAX_NODES:
        raise TreeError("expression too large for a figure")
    return _build(parsed, frozenset(names) if names is not None else None)


def maybe_tree(text: str | None, names: Iterable[str] | None = None) -> Tree | None:
    """The tree, or None when the text is missing or outside the allowlist."""
    if text is None:
        return None
    try:
        return tree(text, names)
    except TreeError:
        return None


def evaluate(node: Tree, env: dict[str, float]) -> float:
    """Evaluate a tree in Python (the tests compare it with the browser's evaluator)."""
    if isinstance(node, (int, float)):
        return float(node)
    if isinstance(node, str):
        return float(env[node])
    op, *args = node
    values = [evaluate(a, env) for a in args]
    if op == "+":
        return math.fsum(values)
    if op == "*":
        return math.prod(values)
    if op == "neg":
        return -values[0]
    if op == "/":
        return values[0] / values[1]
    if op == "pow":
        return values[0] ** values[1]
    if op == "Abs":
        return abs(values[0])
    if op == "sign":
        return math.copysign(1.0, values[0]) if values[0] else 0.0
    if op in _RECIPROCALS:
        # cot = 1/tan, sec = 1/cos, csc = 1/sin
        return 1.0 / getattr(math, _RECIPROCALS[op])(values[0])
    if op == "atan2":
        return math.atan2(values[0], values[1])
    return getattr(math, op)(values[0])
