"""Expression trees (app/engine/document/trees.py writes them) as the figures and the browser read them.

The derivation document carries each expression as a tree beside its LaTeX and ``sympy`` string,
built from the SymPy object; the scenes' and the figures' own expressions (particle positions, the
drawings' helpers) become trees through the parser's gates (``app.engine.document.trees.of_text``).  Here:
the tree of a document's expression restricted to the names a page gives values to
(``document_tree``), the names in a tree (``leaves``), and its value in Python (``evaluate``, which
the tests compare with the browser's static/js/expr.js).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any, Protocol

from app.engine.document.trees import Tree

_RECIPROCALS = {"cot": "tan", "sec": "cos", "csc": "sin"}


class Expression(Protocol):
    """One of the document's expressions (app.engine.document.model: a Pair, a Root, a conserved quantity...)."""

    tree: Any


def document_tree(pair: Expression | None, names: Iterable[str] | None = None) -> Tree | None:
    """The tree of one of the document's expressions, or None when it has none or uses a name outside
    ``names`` (the figure that needed it is then left out)."""
    tree = None if pair is None else pair.tree
    if tree is None:
        return None
    return tree if names is None or leaves(tree) <= set(names) else None


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
