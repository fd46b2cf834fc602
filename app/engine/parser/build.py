"""Gate 3 of the parser (app/engine/parser/parse.py): what ``read`` checked, built into SymPy.

The compact tree is built node by node (decimal literals as the exact rationals they name), and a result
that is undefined or not real (``1/(x - x)``, ``sqrt(-x**2)``, ``asin(2 + x - x)``) is refused with the
part at fault and its columns, as gate 2 refuses.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy as sp

from app.engine.parser.checker import Checker
from app.engine.parser.read import Node, Parsed, names_in_order, placed, read
from app.engine.parser.rules import CONSTANTS, FUNCTIONS, MAX_BITS, MAX_DEGREE, MAX_DIGITS, ExpressionError


@dataclass(frozen=True)
class _Span:
    """Where a compact node stands, as a refusal reads it from an ``ast`` node."""

    col_offset: int
    end_col_offset: int | None


class Builder:
    """Gate 3: a checked tree (in the compact form) into SymPy."""

    def __init__(self, text: str, offset: int, names: Mapping[str, sp.Symbol]):
        self.checker = Checker(text, offset, names)
        self.names = names

    def build(self, node: Node) -> sp.Expr:
        kind = node[0]
        if kind == "num":
            # A decimal literal becomes the exact rational it names, so derivations stay exact.
            value = node[3]
            return sp.Integer(value) if isinstance(value, int) else sp.Rational(repr(value))
        if kind == "name":
            return self.names[node[3]] if node[3] in self.names else CONSTANTS[node[3]]
        if kind in ("neg", "pos"):
            return -self.build(node[3]) if kind == "neg" else self.build(node[3])
        if kind == "chain":
            result = self.build(node[3])
            for op, operand in node[4]:
                right = self.build(operand)
                if op == "/" and right == 0:
                    raise self.refuse(operand, "division by zero (this denominator is 0)")
                result = _COMBINE[op](result, right)
            return result
        if kind == "pow":
            return self.real(node, self.build(node[3]) ** self.build(node[4]))
        assert kind == "call"
        args = [self.build(a) for a in node[4]]
        if node[3] == "exp":
            self.exp_powers(node, args[0])
        return self.real(node, FUNCTIONS[node[3]](*args))

    def exp_powers(self, node: Node, argument: sp.Expr) -> None:
        """Refuse exp(c log u + …) whose power u**c, which SymPy forms at once, is past the limits: gate 2 bounds
        the c it can read as a number, but a c that is one only once built (``(x - x + 10**15)*log(2)``) meets
        its bound here, before SymPy computes 2**(10**15)."""
        for term in sp.Add.make_args(argument):
            c, rest = term.as_coeff_Mul()
            logs = [f for f in sp.Mul.make_args(rest) if isinstance(f, sp.log)]
            if len(logs) != 1 or abs(c) <= 1:
                continue
            if abs(c) > MAX_DEGREE:
                raise self.refuse(
                    node, f"the powers here grow too large (degree {abs(c)} once combined; at most {MAX_DEGREE})"
                )
            u = logs[0].args[0]
            if u.is_Rational and max(abs(u.p).bit_length(), u.q.bit_length()) * abs(c) > MAX_BITS:
                raise self.refuse(node, f"this number is too large (more than {MAX_DIGITS} digits)")

    def refuse(self, node: Node, why: str) -> ExpressionError:
        return self.checker.refuse(_Span(node[1], node[2]), why)  # type: ignore[arg-type]

    def real(self, node: Node, value: sp.Expr) -> sp.Expr:
        """A power or function value, refused when it is a constant that is not real (asin(2 + x - x))."""
        if value.is_number and value.is_finite is not False and value.is_extended_real is False:
            raise self.refuse(node, "this number is not real")
        return value


_COMBINE: dict[str, Callable[[sp.Expr, sp.Expr], sp.Expr]] = {
    "+": lambda a, b: a + b,
    "-": lambda a, b: a - b,
    "*": lambda a, b: a * b,
    "/": lambda a, b: a / b,
}


def parse_expression(text: str, names: Mapping[str, sp.Symbol]) -> sp.Expr:
    """Parse ``text`` into a SymPy expression over the symbols in ``names``."""
    return build(read(text, names), names)


def build(parsed: Parsed, names: Mapping[str, sp.Symbol]) -> sp.Expr:
    """Gate 3: an expression read by ``read`` built into SymPy over the symbols in ``names``."""
    if not parsed.names <= names.keys():
        missing = ", ".join(sorted(parsed.names - names.keys()))
        raise ValueError(f"{parsed.text[:60]!r} was checked against names this namespace lacks: {missing}")
    stripped, offset = placed(parsed.text)
    expr = Builder(stripped, offset, names).build(parsed.tree)
    if expr.has(sp.zoo, sp.oo, sp.nan, -sp.oo):
        raise ExpressionError(f"the expression is undefined (a division by zero?): {stripped[:60]!r}", stripped[:60])
    if expr.has(sp.I):
        raise ExpressionError(f"the expression is not real: {stripped[:60]!r}", stripped[:60])
    return expr


def _summands(node: Node, sign: int) -> list[tuple[int, Node]]:
    """The terms of a sum as typed, each with its sign: a − (b + c) is +a, −b, −c; a product is one term."""
    kind = node[0]
    if kind in ("neg", "pos"):
        return _summands(node[3], -sign if kind == "neg" else sign)
    if kind == "chain" and node[4] and node[4][0][0] in ("+", "-"):
        out = _summands(node[3], sign)
        for op, operand in node[4]:
            out += _summands(operand, sign if op == "+" else -sign)
        return out
    return [(sign, node)]


def typed_terms(parsed: Parsed, names: Mapping[str, sp.Symbol]) -> list[sp.Expr]:
    """The terms of an answer as typed that another term could cancel, each built on its own (a term that another
    cancels is still there: ``m g sin α − m g sin α`` is two terms here, nothing once built whole); the terms whose
    names no other term holds are left out."""
    stripped, offset = placed(parsed.text)
    summands = _summands(parsed.tree, 1)
    # two terms cancel only if they hold the same names: without such a pair nothing is built (the answer is then
    # built once, whole, by its check: typing m g sin α twice is rare, every answer's terms are not)
    held = [frozenset(n[3] for n in names_in_order(node)) for _, node in summands]
    if len(set(held)) == len(held):
        return []
    builder = Builder(stripped, offset, names)
    return [sign * builder.build(node) for (sign, node), h in zip(summands, held, strict=True) if held.count(h) > 1]
