"""Expressions as the JSON trees the browser evaluates (static/js/expr.js): the one writer of that format.

A tree is a number, a symbol's name (a string), or a list ``[op, *arguments]``:

    a + b + c -> ["+", a, b, c]      a * b * c -> ["*", a, b, c]      -a -> ["neg", a]
    a / b     -> ["/", a, b]         a ** b    -> ["pow", a, b]       sin(a) -> ["sin", a]
    atan2(y, x) -> ["atan2", y, x]

Two ways in, no parser of our own:

* ``of_sympy``: a SymPy expression the engine derived (the derivation document carries each of its
  expressions as a tree beside its LaTeX and ``sympy`` string, app/engine/document/report.py);
* ``of_text``: text that passed the expression gates of app/engine/parser/parse.py (its allowlist, its
  limits, Python's own ``ast`` parser; pure Python, no SymPy, so a web process may call it on a
  user's declaration): the checked syntax tree written as a tree.

The functions are the parser's allowlist plus ``sign`` (SymPy's derivatives of Abs bring it in).
Trees deeper than ``MAX_DEPTH`` or larger than ``MAX_NODES`` are refused with ``TreeError`` (the
figure or plot that needed them is then left out), so nothing that walks a tree can overflow.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Collection
from typing import Any

import sympy as sp

from app.engine.parser.parse import FUNCTIONS as INPUT_FUNCTIONS
from app.engine.parser.parse import MAX_LENGTH, ExpressionError, check_expression, typed

Tree = float | int | str | list[Any]

FUNCTIONS = frozenset(INPUT_FUNCTIONS) | {"sign"}
MAX_DEPTH = 100
MAX_NODES = 20_000


class TreeError(ValueError):
    """An expression with no tree (outside the allowlist, or too large for a figure)."""


def _flat(op: str, items: list[Tree]) -> list[Any]:
    # (a + b) + c -> ["+", a, b, c]: shallower trees evaluate faster in the browser
    out: list[Any] = [op]
    for item in items:
        if isinstance(item, list) and item and item[0] == op:
            out.extend(item[1:])
        else:
            out.append(item)
    return out


class _Budget:
    """Counts the nodes written; refuses depth beyond MAX_DEPTH and size beyond MAX_NODES."""

    def __init__(self) -> None:
        self.nodes = 0

    def enter(self, depth: int) -> None:
        self.nodes += 1
        if self.nodes > MAX_NODES:
            raise TreeError("expression too large for a figure")
        if depth > MAX_DEPTH:
            raise TreeError(f"expression nested deeper than {MAX_DEPTH} levels for a figure")


def of_sympy(expr: sp.Basic) -> Tree:
    """The tree of a SymPy expression (its symbols by name, its numbers as floats or ints)."""
    budget = _Budget()

    def walk(e: sp.Basic, depth: int) -> Tree:
        budget.enter(depth)
        if isinstance(e, sp.Integer):
            return int(e)
        if isinstance(e, (sp.Rational, sp.Float, sp.NumberSymbol)):
            # p/q, a float, pi or E: a float (a non-finite one has no tree)
            value = float(e)
            if not math.isfinite(value):
                raise TreeError(f"{e} is not a finite number")
            return value
        if isinstance(e, sp.Symbol):
            return e.name
        if isinstance(e, sp.Add):
            return _flat("+", [walk(a, depth + 1) for a in e.args])
        if isinstance(e, sp.Mul):
            if e.args[0] == -1:
                # -a b: as a reader writes it
                rest = sp.Mul(*e.args[1:], evaluate=False)
                return ["neg", walk(rest, depth + 1)]
            return _flat("*", [walk(a, depth + 1) for a in e.args])
        if isinstance(e, sp.Pow):
            base = walk(e.base, depth + 1)
            if e.exp == -1:
                return ["/", 1, base]
            return ["pow", base, walk(e.exp, depth + 1)]
        if isinstance(e, sp.Function):
            name = type(e).__name__
            if name not in FUNCTIONS:
                raise TreeError(f"function {name!r} is not supported in a figure expression")
            return [name, *(walk(a, depth + 1) for a in e.args)]
        raise TreeError(f"{type(e).__name__} is not supported in a figure expression")

    return walk(sp.sympify(expr), 0)


def maybe_of_sympy(expr: sp.Basic) -> Tree | None:
    """The tree, or None when the expression has none (its figure is then left out)."""
    try:
        return of_sympy(expr)
    except TreeError:
        return None


_OPERATORS = {ast.Div: "/", ast.Pow: "pow"}


def of_text(text: str, names: Collection[str] | None = None) -> Tree:
    """The tree of an expression the parser's gates accept (pure Python: no SymPy).

    ``names`` are the names it may use; None allows every name that is not a function or
    ``pi`` (the figures' own expressions, written in this repository, name their helpers freely)."""
    if not isinstance(text, str) or len(text) > MAX_LENGTH:
        raise TreeError(f"an expression of at most {MAX_LENGTH} characters is needed")
    if names is None:
        try:
            parsed = ast.parse(typed(text).text, mode="eval")
        except (SyntaxError, ExpressionError) as exc:
            raise TreeError(f"not an expression: {text!r}") from exc
        names = {n.id for n in ast.walk(parsed) if isinstance(n, ast.Name)} - set(FUNCTIONS) - {"pi"}
    try:
        checked = check_expression(text, names)
    except ExpressionError as exc:
        raise TreeError(str(exc)) from exc
    budget = _Budget()

    def walk(node: ast.AST, depth: int) -> Tree:
        budget.enter(depth)
        if isinstance(node, ast.Constant):
            if isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
                return node.value
            raise TreeError(f"{node.value!r} is not a number")  # the gates refuse it first
        if isinstance(node, ast.Name):
            return math.pi if node.id == "pi" else node.id
        if isinstance(node, ast.UnaryOp):
            inner = walk(node.operand, depth + 1)
            if isinstance(node.op, ast.UAdd):
                return inner
            return -inner if isinstance(inner, (int, float)) else ["neg", inner]
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub, ast.Mult)):
            # a + b - c + ... (or a * b * c ...) is a left-deep chain as long as the text: walked as one list
            family = (ast.Add, ast.Sub) if isinstance(node.op, (ast.Add, ast.Sub)) else (ast.Mult,)
            operands: list[tuple[bool, ast.AST]] = []
            while isinstance(node, ast.BinOp) and isinstance(node.op, family):
                operands.append((isinstance(node.op, ast.Sub), node.right))
                node = node.left
            items = [walk(node, depth + 1)]
            for negated, operand in reversed(operands):
                item = walk(operand, depth + 1)
                if negated:
                    item = -item if isinstance(item, (int, float)) else ["neg", item]
                items.append(item)
            return _flat("+" if family[0] is ast.Add else "*", items)
        if isinstance(node, ast.BinOp):
            left, right = walk(node.left, depth + 1), walk(node.right, depth + 1)
            return [_OPERATORS[type(node.op)], left, right]
        if isinstance(node, ast.Call):
            return [node.func.id, *(walk(a, depth + 1) for a in node.args)]  # type: ignore[attr-defined]
        raise TreeError(f"{type(node).__name__} is not supported in a figure expression")  # the gates refuse it first

    return walk(checked.body, 0)


def maybe_of_text(text: str | None, names: Collection[str] | None = None) -> Tree | None:
    """The tree, or None when the text is missing or refused."""
    if text is None:
        return None
    try:
        return of_text(text, names)
    except TreeError:
        return None
