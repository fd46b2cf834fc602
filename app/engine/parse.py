"""Turn expression text into SymPy without ever calling ``eval``.

``sympify`` and ``parse_expr`` evaluate Python code, so they are never used on
text.  Instead the text is parsed by Python's ``ast`` module and the tree is
walked against an allowlist: numbers, declared names, ``+ - * / **``, unary
minus and plus, parentheses and calls of a fixed set of functions on exactly
one argument.  Everything else is refused with a message naming the offending
part.  Size limits are checked before SymPy sees anything.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Mapping

import sympy as sp

from app.engine.errors import DerivationError

MAX_LENGTH = 2000
MAX_DEPTH = 40
MAX_NODES = 600
MAX_EXPONENT = 64
MAX_INT_DIGITS = 15

FUNCTIONS: dict[str, type[sp.Function]] = {
    "sin": sp.sin,
    "cos": sp.cos,
    "tan": sp.tan,
    "asin": sp.asin,
    "acos": sp.acos,
    "atan": sp.atan,
    "sinh": sp.sinh,
    "cosh": sp.cosh,
    "tanh": sp.tanh,
    "exp": sp.exp,
    "log": sp.log,
    "sqrt": sp.sqrt,
    "Abs": sp.Abs,
}
CONSTANTS: dict[str, sp.Expr] = {"pi": sp.pi}
RESERVED = frozenset(FUNCTIONS) | frozenset(CONSTANTS) | {"t", "E", "I", "oo", "nan", "zoo"}
NAME_PATTERN = re.compile(r"^[A-Za-z][A-Za-z0-9]{0,15}$")

_BINARY = {
    ast.Add: lambda a, b: a + b,
    ast.Sub: lambda a, b: a - b,
    ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b,
    ast.Pow: lambda a, b: a**b,
}


class ExpressionError(DerivationError):
    """Text that is not an allowed expression; ``part`` names what was wrong."""


def check_name(name: str, what: str = "name") -> str:
    """A declared name: letters then letters or digits, not a function or constant."""
    if not isinstance(name, str) or not NAME_PATTERN.match(name):
        raise ExpressionError(
            f"{what} {str(name)[:40]!r} is not allowed: use a letter followed by up to 15 "
            "letters or digits (no underscores)",
            str(name)[:40],
        )
    if name in RESERVED:
        raise ExpressionError(f"{what} {name!r} clashes with a reserved name", name)
    return name


def _snippet(text: str, node: ast.AST) -> str:
    part = ast.get_source_segment(text, node) or type(node).__name__
    return part if len(part) <= 60 else part[:57] + "..."


class _Builder:
    def __init__(self, text: str, names: Mapping[str, sp.Symbol]):
        self.text = text
        self.names = names

    def refuse(self, node: ast.AST, why: str) -> ExpressionError:
        part = _snippet(self.text, node)
        return ExpressionError(f"{why}: {part!r}", part)

    def build(self, node: ast.AST, depth: int = 0) -> sp.Expr:
        if depth > MAX_DEPTH:
            raise self.refuse(node, f"expression nested deeper than {MAX_DEPTH} levels")
        if isinstance(node, ast.Expression):
            return self.build(node.body, depth + 1)
        if isinstance(node, ast.Constant):
            return self.number(node)
        if isinstance(node, ast.Name):
            if node.id in self.names:
                return self.names[node.id]
            if node.id in CONSTANTS:
                return CONSTANTS[node.id]
            allowed = ", ".join(sorted(self.names)) or "none"
            raise self.refuse(node, f"unknown name (declared names: {allowed})")
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            value = self.build(node.operand, depth + 1)
            return -value if isinstance(node.op, ast.USub) else value
        if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
            left = self.build(node.left, depth + 1)
            right = self.build(node.right, depth + 1)
            if isinstance(node.op, ast.Pow):
                self.check_power(node, right)
            if isinstance(node.op, ast.Div) and right == 0:
                raise self.refuse(node, "division by zero")
            return _BINARY[type(node.op)](left, right)
        if isinstance(node, ast.Call):
            return self.call(node, depth)
        raise self.refuse(node, f"{type(node).__name__} is not allowed in an expression")

    def number(self, node: ast.Constant) -> sp.Expr:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.refuse(node, "only numbers are allowed as literals")
        if isinstance(value, int):
            if len(str(abs(value))) > MAX_INT_DIGITS:
                raise self.refuse(node, f"integer literal longer than {MAX_INT_DIGITS} digits")
            return sp.Integer(value)
        if value != value or value in (float("inf"), float("-inf")) or abs(value) > 1e15:
            raise self.refuse(node, "number out of range (at most 1e15 in magnitude)")
        # A decimal literal becomes the exact rational it names, so derivations stay exact.
        return sp.nsimplify(sp.Float(repr(value)), rational=True)

    def check_power(self, node: ast.BinOp, exponent: sp.Expr) -> None:
        if not exponent.is_number:
            raise self.refuse(node, "exponents must be numbers")
        if isinstance(node.right, ast.BinOp) and isinstance(node.right.op, ast.Pow):
            raise self.refuse(node, "towers of exponents are not allowed")
        if abs(float(exponent)) > MAX_EXPONENT:
            raise self.refuse(node, f"exponent larger than {MAX_EXPONENT} in magnitude")

    def call(self, node: ast.Call, depth: int) -> sp.Expr:
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
            allowed = ", ".join(sorted(FUNCTIONS))
            raise self.refuse(node, f"only these functions may be called: {allowed}")
        if node.keywords or len(node.args) != 1 or isinstance(node.args[0], ast.Starred):
            raise self.refuse(node, "a function takes exactly one argument")
        argument = self.build(node.args[0], depth + 1)
        return FUNCTIONS[node.func.id](argument)


def parse_expression(text: str, names: Mapping[str, sp.Symbol]) -> sp.Expr:
    """Parse ``text`` into a SymPy expression over the symbols in ``names``."""
    if not isinstance(text, str):
        raise ExpressionError("an expression must be a string")
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"expression longer than {MAX_LENGTH} characters", text[:40] + "...")
    if not text.strip():
        raise ExpressionError("empty expression")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        raise ExpressionError(f"syntax error at column {exc.offset}: {exc.msg}", text[:60]) from None
    count = sum(1 for _ in ast.walk(tree))
    if count > MAX_NODES:
        raise ExpressionError(f"expression has {count} parts; at most {MAX_NODES} are allowed")
    return _Builder(text.strip(), names).build(tree)
