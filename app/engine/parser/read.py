"""Gates 1 and 2 of the parser (app/engine/parser/parse.py): an expression's text read once, in pure Python.

``read`` checks the characters (``app.engine.parser.hints`` explains a refused one), reads the text with
``ast.parse`` (the one place it is read), walks the tree against the allowlist (``app.engine.parser.checker``)
and keeps what it read as a picklable ``Parsed``: the checked tree in a compact form of plain tuples, its
size bounds and the names it was checked against.  ``narrowed`` holds a ``Parsed`` to fewer names without
reading the text again (docs/parsing.md).
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Collection, Iterator
from dataclasses import dataclass, field

from app.engine.parser.checker import OPERATORS, PRODUCTS, SUMS, Checker, Facts, chain
from app.engine.parser.hints import character_error, first_bad_character
from app.engine.parser.rules import MAX_LENGTH, MAX_NODES, MAX_TERMS, ExpressionError
from app.engine.parser.typed import Typed, typed

# tabs and line breaks count as spaces (one for one, so columns stay right)
SPACES = {9: " ", 10: " ", 13: " "}


def check_expression(text: str, names: Collection[str]) -> ast.Expression:
    """Gates 1 and 2: refuse anything but an allowed expression, without SymPy.

    ``names`` are the names the expression may use (``pi`` is always allowed).
    Returns the checked tree (of the text with surrounding spaces removed).
    """
    return _checked(text, names)[0]


@dataclass(frozen=True)
class Size:
    """Upper bounds for a checked expression: terms of its full expansion, and its degree (x**2*y: 3)."""

    terms: int
    degree: float


# A checked tree in our own compact form, plain tuples (quick to pickle to a worker, and only these kinds can
# be built): ("num", start, end, value), ("name", start, end, name), ("neg" or "pos", start, end, operand),
# ("chain", start, end, first, ((operator, operand), ...)) for a left-deep run of + and - or of * and /,
# ("pow", start, end, base, exponent) and ("call", start, end, function, (argument, ...)); start and end are
# the node's columns in the stripped text.
Node = tuple


def _compact(node: ast.AST, place: Callable[[int, int | None], tuple[int, int]]) -> Node:
    """A checked ``ast`` tree in the compact form; ``place`` gives a node's columns in the stripped text as
    typed from its columns in the text gate 2 read."""
    start, end = place(getattr(node, "col_offset", 0), getattr(node, "end_col_offset", None))
    if isinstance(node, ast.Constant):
        return ("num", start, end, node.value)
    if isinstance(node, ast.Name):
        return ("name", start, end, node.id)
    if isinstance(node, ast.UnaryOp):
        return ("neg" if isinstance(node.op, ast.USub) else "pos", start, end, _compact(node.operand, place))
    if isinstance(node, ast.BinOp) and isinstance(node.op, (*SUMS, *PRODUCTS)):
        # a long sum or product is a flat list, not a recursion as deep as it is long
        items = chain(node, SUMS if isinstance(node.op, SUMS) else PRODUCTS)
        rest = tuple((OPERATORS[op], _compact(operand, place)) for op, operand, _ in items[1:])  # type: ignore[index]
        return ("chain", start, end, _compact(items[0][1], place), rest)
    if isinstance(node, ast.BinOp):
        return ("pow", start, end, _compact(node.left, place), _compact(node.right, place))
    assert isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
    return ("call", start, end, node.func.id, tuple(_compact(a, place) for a in node.args))


@dataclass(frozen=True)
class Parsed:
    """An expression's text read once (gates 1 and 2): its checked tree and size bounds, picklable.

    ``build`` turns it into SymPy (gate 3) without reading the text again, so a web process can read a
    user's text in pure Python and a worker build what it read.  ``names`` are the names it was checked
    against; only a namespace giving each of them a symbol may build it.
    """

    text: str  # as given
    tree: Node = field(repr=False, compare=False)  # the checked tree in the compact form
    size: Size
    names: frozenset[str] = field(repr=False)


def read(text: str, names: Collection[str]) -> Parsed:
    """Gates 1 and 2 on ``text``: the one place an expression's text is read (``ast.parse``)."""
    tree, facts, written = _checked(text, names)
    # one set shared by many texts is pickled once
    allowed = names if isinstance(names, frozenset) else frozenset(names)
    offset = placed(text)[1]

    def place(start: int, end: int | None) -> tuple[int, int]:
        first, last = written.span(start, end)
        return first - offset, last - offset

    return Parsed(text, _compact(tree.body, place), Size(facts.terms, facts.degree), allowed)


def expression_size(text: str, names: Collection[str]) -> Size:
    """Check an expression as ``check_expression`` does and return its size bounds."""
    facts = _checked(text, names)[1]
    return Size(facts.terms, facts.degree)


# an operator that needs something after it: a formula cannot end with one
_DANGLING = ("**", "+", "-", "*", "/", "^")


def _unreadable(text: str, stripped: str, written: Typed, exc: SyntaxError) -> ExpressionError:
    """Python's complaint about a formula, in a student's words and at the place it names.

    Python reports a formula that ends with an operator (``m g l +``) at its first column; the place that
    is wrong is the operator at the end, so that one is named.
    """
    end = stripped.rstrip()
    dangling = next((op for op in _DANGLING if end.endswith(op)), None)
    if dangling is not None:
        column = len(end) - len(dangling)
    else:
        column = min(max((exc.offset or 1) - 1, 0), max(len(stripped) - 1, 0))
    at = written.span(column, column + 1)[0]
    first, last = max(at - 10, 0), min(at + 10, len(text))
    near = text[first:last]
    if dangling is not None:
        typed_end = text.rstrip()
        op = dangling if typed_end.endswith(dangling) else typed_end[-1]  # ^ as typed, not the ** it became
        why = f"the formula ends with {op!r} at column {at + 1}: something is missing after it"
    elif "was never closed" in exc.msg:
        why = f"the {text[at]!r} at column {at + 1} is never closed: a ')' is missing"
    elif exc.msg.startswith("unmatched"):
        why = f"the {text[at]!r} at column {at + 1} has no opening bracket before it"
    elif exc.msg in ("invalid syntax", "invalid decimal literal"):
        why = f"this cannot be read as a formula at column {at + 1}"
    else:  # gate 0's own advice (write m1*l1: a * between factors) or Python's plain reason
        why = f"this cannot be read as a formula at column {at + 1} ({exc.msg})"
    return ExpressionError(f"{why}, near {near!r}", near, first, last)


def _checked(text: str, names: Collection[str]) -> tuple[ast.Expression, Facts, Typed]:
    if not isinstance(text, str):
        raise ExpressionError("an expression must be a string")
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"expression is {len(text)} characters long; at most {MAX_LENGTH} are allowed")
    text = text.translate(SPACES)
    if not text.strip():
        raise ExpressionError("empty expression (write 0 for nothing)")
    # gate 0: the text as students type it (^, θ, θ', 2x, m g l) in the grammar the allowlist walk reads
    written = typed(text)
    stripped = written.text
    bad = first_bad_character(stripped)
    if bad is not None:  # never: gate 0 writes only these characters
        raise character_error(text, written.span(bad, bad + 1)[0])
    offset = len(text) - len(text.lstrip())
    try:
        tree = ast.parse(stripped, mode="eval")
    except SyntaxError as exc:
        raise _unreadable(text, stripped, written, exc) from None
    except (RecursionError, MemoryError, ValueError):
        raise ExpressionError("expression could not be read (too deeply nested?)") from None
    count = sum(isinstance(node, ast.expr) for node in ast.walk(tree))
    if count > MAX_NODES:
        raise ExpressionError(f"expression has {count} parts; at most {MAX_NODES} are allowed")
    facts = Checker(stripped, offset, names, written).check(tree.body)
    if facts.terms > MAX_TERMS or facts.inside > MAX_TERMS:
        where = "expression" if facts.terms > MAX_TERMS else "a function's argument"
        whole = text.strip()
        raise ExpressionError(
            f"{where} would expand into more than {MAX_TERMS} terms; write it in a smaller form",
            whole[:60],
            offset,
            offset + len(whole),
        )
    return tree, facts, written


def placed(text: str) -> tuple[str, int]:
    """The text as the gates read it (spaces stripped) and the column it starts at in the text as given."""
    spaced = text.translate(SPACES)
    return spaced.strip(), len(spaced) - len(spaced.lstrip())


def names_in_order(node: Node) -> Iterator[Node]:
    """The ("name", ...) nodes of a compact tree, left to right: the order in which the checker meets them."""
    kind = node[0]
    if kind == "name":
        yield node
    elif kind in ("neg", "pos"):
        yield from names_in_order(node[3])
    elif kind == "chain":
        yield from names_in_order(node[3])
        for _, operand in node[4]:
            yield from names_in_order(operand)
    elif kind == "pow":
        yield from names_in_order(node[3])
        yield from names_in_order(node[4])
    elif kind == "call":
        for argument in node[4]:
            yield from names_in_order(argument)


def narrowed(parsed: Parsed, names: Collection[str]) -> Parsed:
    """``read(parsed.text, names)`` for ``names`` among those ``parsed`` was read against, without reading the
    text again: the same ``Parsed``, or the same refusal.

    Every node's facts depend on the names only through its leaves, and a declared name's facts are the
    same whichever names are declared, so the walk against fewer names goes as the first walk went until it
    meets the first name (left to right) it no longer allows, and refuses that name as the checker refuses it.
    """
    allowed = names if isinstance(names, frozenset) else frozenset(names)
    if allowed == parsed.names:
        return parsed
    if not allowed <= parsed.names:
        extra = ", ".join(sorted(allowed - parsed.names))
        raise ValueError(f"{parsed.text[:60]!r} was not read against these names: {extra}")
    stripped, offset = placed(parsed.text)
    checker = Checker(stripped, offset, allowed)
    for _, start, end, name in names_in_order(parsed.tree):
        if name not in allowed:
            checker.name(ast.Name(id=name, ctx=ast.Load(), col_offset=start, end_col_offset=end))
    return Parsed(parsed.text, parsed.tree, parsed.size, allowed)
