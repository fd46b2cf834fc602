"""Expression strings -> small JSON trees the browser evaluates (static/js/expr.js).

The derivation JSON carries every expression as a ``sympy`` string in the
project's symbol convention.  The pages need a few of them as numbers in the
browser (the potential along a run, the effective potential over a range, the
particles' positions for the animation), so each string is read against an
allowlist and written as a tree:

    number            -> the number
    symbol            -> its name (a string)
    a + b + c         -> ["+", a, b, c]        a * b -> ["*", a, b]
    -a                -> ["neg", a]            a / b -> ["/", a, b]
    a ** b            -> ["pow", a, b]         sin(a) -> ["sin", a]
    atan2(y, x)       -> ["atan2", y, x]

Nothing is evaluated here and no ``eval`` or ``sympify`` runs on the text.
The reader is an operator-precedence (shunting-yard) loop over tokens, with no
recursion: a derived expression of thousands of terms reads in one pass, and
trees deeper than ``MAX_DEPTH`` or larger than ``MAX_TOKENS`` are refused (the
figure is then left out), so nothing that walks a tree can overflow.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from functools import cache
from typing import Any

from app.engine.parse import ALLOWED, ARITY
from app.engine.parse import FUNCTIONS as INPUT_FUNCTIONS

# The functions users may write (their one home is the parser), plus sign, which SymPy's derivatives add.
FUNCTIONS = frozenset(INPUT_FUNCTIONS) | {"sign"}
CONSTANTS = {"pi": math.pi, "E": math.e}
MAX_TOKENS = 20_000
MAX_DEPTH = 100
_RECIPROCALS = {"cot": "tan", "sec": "cos", "csc": "sin"}

Tree = float | int | str | list[Any]

_TOKEN = re.compile(
    r"\s*(?:(?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
    r"|(?P<op>\*\*|[-+*/(),]))"
)
# binding strength of each operator; ** binds right to left, and a sign binds less tightly than ** on its right
_BINARY = {"+": 1, "-": 1, "*": 2, "/": 2, "**": 4}
_PREFIX = 3


class TreeError(ValueError):
    """Text outside the allowlist (the caller leaves that figure out)."""


def _tokens(text: str) -> list[tuple[str, str]]:
    tokens, position, end = [], 0, len(text.rstrip())
    while position < end:
        match = _TOKEN.match(text, position)
        if match is None or match.end() == position:
            raise TreeError(f"character {text[position : position + 1]!r} is not supported in a figure expression")
        kind = match.lastgroup or ""
        tokens.append((kind, match.group(kind)))
        position = match.end()
        if len(tokens) > MAX_TOKENS:
            raise TreeError("expression too large for a figure")
    return tokens


def _flat(op: str, left: Tree, right: Tree) -> list[Any]:
    # a + (b + c) -> ["+", a, b, c]: shallower trees evaluate faster in the browser.  Every list
    # here was built by this reader and is used once, so it is extended in place.
    items: list[Any] = left if isinstance(left, list) and left and left[0] == op else [op, left]
    if isinstance(right, list) and right and right[0] == op:
        items.extend(right[1:])
    else:
        items.append(right)
    return items


class _Reader:
    """The shunting-yard state: operands (each with its depth) and pending operators."""

    def __init__(self, names: frozenset[str] | None):
        self.names = names
        self.operands: list[tuple[Tree, int]] = []
        self.pending: list[str] = []  # "+", "-", "*", "/", "**", "neg", "pos", "(", "call:f"
        self.arguments: list[int] = []  # for each open call, the number of its arguments read so far

    def leaf(self, kind: str, text: str) -> Tree:
        if kind == "number":
            return int(text) if text.isdigit() else float(text)
        if text == "pi":
            return math.pi
        if self.names is not None and text not in self.names and text in CONSTANTS:
            return CONSTANTS[text]
        if self.names is None or text in self.names:
            return text
        raise TreeError(f"unknown name {text!r}")

    def apply(self, op: str, count: int = 1) -> None:
        if op.startswith("call:"):
            # a call takes its ``count`` arguments off the operand stack, in the order they were read
            if len(self.operands) < count:
                raise TreeError("a function without its arguments")
            taken = self.operands[-count:]
            del self.operands[-count:]
            self.push([op[5:], *(node for node, _ in taken)], max(depth for _, depth in taken) + 1)
            return
        if op in ("neg", "pos"):
            if not self.operands:
                raise TreeError("an operator without an operand")
            inner, depth = self.operands.pop()
            node: Tree = inner if op == "pos" else (-inner if isinstance(inner, (int, float)) else ["neg", inner])
            self.push(node, depth + 1)
            return
        if len(self.operands) < 2:
            raise TreeError("an operator without an operand")
        (right, d_right), (left, d_left) = self.operands.pop(), self.operands.pop()
        if op == "+":
            node = _flat("+", left, right)
        elif op == "-":
            node = _flat("+", left, ["neg", right])
        elif op == "*":
            node = _flat("*", left, right)
        else:
            node = ["/" if op == "/" else "pow", left, right]
        # a sum or product extended in place is no deeper than before, except through its new operand
        self.push(node, max(d_left if node is left else d_left + 1, d_right + 2))

    def push(self, node: Tree, depth: int) -> None:
        if depth > MAX_DEPTH:
            raise TreeError(f"expression nested deeper than {MAX_DEPTH} levels for a figure")
        self.operands.append((node, depth))

    def binary(self, op: str) -> None:
        strength = _BINARY[op]
        while self.pending and self.pending[-1] != "(" and not self.pending[-1].startswith("call:"):
            top = self.pending[-1]
            top_strength = _PREFIX if top in ("neg", "pos") else _BINARY[top]
            if top_strength > strength or (top_strength == strength and op != "**"):
                self.apply(self.pending.pop())
            else:
                break
        self.pending.append(op)

    def reduce_group(self) -> None:
        """Apply the operators pending inside the innermost parenthesis or call."""
        while self.pending and self.pending[-1] != "(" and not self.pending[-1].startswith("call:"):
            self.apply(self.pending.pop())
        if not self.pending:
            raise TreeError("unbalanced parentheses")

    def comma(self) -> None:
        """One argument of a call read; the next follows (atan2(y, x))."""
        self.reduce_group()
        if not self.pending[-1].startswith("call:"):
            raise TreeError("a comma outside a function's arguments is not supported in a figure expression")
        self.arguments[-1] += 1

    def close(self) -> None:
        self.reduce_group()
        opener = self.pending.pop()
        if opener != "(":
            count, name = self.arguments.pop(), opener[5:]
            if count != ARITY.get(name, 1):
                raise TreeError(f"{name} takes {ARITY.get(name, 1)} argument(s) in a figure expression")
            self.apply(opener, count)

    def read(self, tokens: list[tuple[str, str]]) -> Tree:
        expect_operand, i = True, 0
        while i < len(tokens):
            kind, text = tokens[i]
            i += 1
            if expect_operand:
                if kind == "name" and i < len(tokens) and tokens[i][1] == "(":
                    if text not in FUNCTIONS:
                        raise TreeError(f"function {text!r} is not supported in a figure expression")
                    self.pending.append(f"call:{text}")  # stands for the call's opening parenthesis too
                    self.arguments.append(1)
                    i += 1
                elif kind in ("number", "name"):
                    self.push(self.leaf(kind, text), 0)
                    expect_operand = False
                elif text in ("+", "-"):
                    self.pending.append("neg" if text == "-" else "pos")
                elif text == "(":
                    self.pending.append("(")
                else:
                    raise TreeError(f"{text!r} is not supported where a term should start")
            elif text == ")":
                self.close()
            elif text == ",":
                self.comma()
                expect_operand = True
            elif kind == "op" and text in _BINARY:
                self.binary(text)
                expect_operand = True
            else:
                raise TreeError(f"{text!r} is not supported in a figure expression (a comma, or two terms in a row)")
        if expect_operand:
            raise TreeError("the expression ends where a term should be")
        while self.pending:
            op = self.pending.pop()
            if op == "(" or op.startswith("call:"):
                raise TreeError("unbalanced parentheses")
            self.apply(op)
        if len(self.operands) != 1:
            raise TreeError("not a single expression")
        return self.operands[0][0]


def tree(text: str, names: Iterable[str] | None = None) -> Tree:
    """The tree of one expression string; ``names`` (if given) are the only symbols allowed."""
    if not isinstance(text, str) or not text.strip():
        raise TreeError("empty expression")
    if len(text) > 20 * MAX_TOKENS:
        raise TreeError("expression too large for a figure")
    return _Reader(frozenset(names) if names is not None else None).read(_tokens(text.strip()))


def maybe_tree(text: str | None, names: Iterable[str] | None = None) -> Tree | None:
    """The tree, or None when the text is missing or outside the allowlist."""
    if text is None:
        return None
    try:
        return tree(text, names)
    except TreeError:
        return None


@cache
def function_tex() -> dict[str, str]:
    """Each function users may write, as LaTeX with its arguments written #1, #2 (for the browser's live
    typesetting, static/js/practice.js): SymPy's printer, with arcsin for asin as a textbook writes it."""
    import sympy as sp

    arguments = sp.symbols("a1 a2")
    names = {a: f"#{i + 1}" for i, a in enumerate(arguments)}
    return {
        name: sp.latex(f.symbolic(*arguments[: f.arity]), symbol_names=names, inv_trig_style="full")
        for name, f in ALLOWED.items()
    }


def leaves(node: Tree) -> set[str]:
    """Every name in a tree (iteratively: a tree is as deep as the expression allows)."""
    found: set[str] = set()
    stack = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, str):
            found.add(item)
        elif isinstance(item, list):
            stack.extend(item[1:])  # item[0] is the operator or function
    return found


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
