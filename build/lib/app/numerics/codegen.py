"""SymPy expressions to Python (and browser JavaScript) source: common subexpressions out, scalar calls in.

The engine's symbols carry user-chosen names; generated code never uses them.
Every symbol is renamed to a fixed pattern (``q0``, ``v0``, ``p0``, ``k0``,
``t``) before printing, so no name from a declaration ever reaches the source.
Nothing here simplifies: ``cse`` only names repeated subexpressions.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

import sympy as sp
from sympy.printing.jscode import JavascriptCodePrinter
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.pycode import PythonCodePrinter


class _Floats:
    """A printer's numbers as Python floats: a Float by its shortest repr."""

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))


class _FloatRationals(_Floats):
    """... and a Rational as the float p / q (plain float arithmetic, no ``Rational`` in the code)."""

    def _print_Rational(self, expr: sp.Rational) -> str:
        return repr(float(expr.p) / float(expr.q))


class ScalarPrinter(_FloatRationals, PythonCodePrinter):
    """Prints ``math.sin(x)`` and plain float arithmetic (works in Python and in numba)."""

    def __init__(self) -> None:
        super().__init__({"standard": "python3", "fully_qualified_modules": True, "strict": True})


class ArrayPrinter(_FloatRationals, NumPyPrinter):
    """Prints ``numpy.sin(x)`` for expressions evaluated on whole arrays of samples."""

    def __init__(self) -> None:
        super().__init__({"fully_qualified_modules": True, "strict": True})


class BrowserPrinter(_Floats, JavascriptCodePrinter):
    """Prints ``Math.sin(x)`` for the browser's live preview; like the others, refuses what it cannot print."""

    def __init__(self) -> None:
        super().__init__({"strict": True})


@dataclass
class Block:
    """Straight-line code: ``name = expression`` lines, common subexpressions first.

    ``javascript`` blocks declare each new name with ``let`` and end lines with ``;``.
    """

    lines: list[str] = field(default_factory=list)
    javascript: bool = False

    def set(self, target: str, text: str) -> None:
        if self.javascript:
            declare = "" if "[" in target else "let "
            self.lines.append(f"{declare}{target} = {text};")
        else:
            self.lines.append(f"{target} = {text}")

    def assign(self, targets: Sequence[str], exprs: Sequence[sp.Expr], printer, prefix: str) -> None:
        # Repeated subexpressions become temporaries prefix0, prefix1, ...
        temps = sp.numbered_symbols(prefix)
        replacements, reduced = sp.cse(list(exprs), symbols=temps, order="none")
        for symbol, value in replacements:
            self.set(symbol.name, printer.doprint(value))
        for target, value in zip(targets, reduced, strict=True):
            self.set(target, printer.doprint(value))

    def raw(self, *lines: str) -> None:
        self.lines.extend(lines)


def function_source(name: str, arguments: str, block: Block) -> str:
    body = "\n".join(f"    {line}" for line in block.lines) or "    pass"
    return f"def {name}({arguments}):\n{body}\n"


def ldl_solve(
    block: Block, matrix: sp.Matrix, rhs: Sequence[str], result: Sequence[str], tag: str, printer=None
) -> None:
    """Lines solving M x = r for a symmetric M given as entry names, by M = L D L^T.

    A mass matrix is symmetric positive definite, so the factorisation needs no
    pivoting.  Entries that are structurally zero are dropped, so a diagonal M
    costs one division per coordinate.
    """
    n = matrix.shape[0]
    entry = {}
    for i in range(n):
        for j in range(i + 1):
            entry[i, j] = sp.Symbol(f"{tag}m{i}_{j}") if matrix[i, j] != 0 else sp.Integer(0)
    L: dict[tuple[int, int], sp.Expr] = {}
    D: list[sp.Expr] = []
    printer = printer or ScalarPrinter()

    def define(name: str, value: sp.Expr) -> sp.Expr:
        if value == 0:
            return sp.Integer(0)
        block.set(name, printer.doprint(value))
        return sp.Symbol(name)

    for j in range(n):
        # d_j = M_jj - sum_{k<j} L_jk^2 d_k
        D.append(define(f"{tag}d{j}", entry[j, j] - sum((L[j, k] ** 2 * D[k] for k in range(j)), sp.Integer(0))))
        for i in range(j + 1, n):
            # L_ij = (M_ij - sum_{k<j} L_ik L_jk d_k) / d_j
            num = entry[i, j] - sum((L[i, k] * L[j, k] * D[k] for k in range(j)), sp.Integer(0))
            L[i, j] = define(f"{tag}l{i}_{j}", num / D[j])
    # forward: z_i = r_i - sum_{k<i} L_ik z_k
    z: list[sp.Expr] = []
    for i in range(n):
        z.append(define(f"{tag}z{i}", sp.Symbol(rhs[i]) - sum((L[i, k] * z[k] for k in range(i)), sp.Integer(0))))
    # back: x_i = z_i / d_i - sum_{k>i} L_ki x_k
    x: dict[int, sp.Expr] = {}
    for i in reversed(range(n)):
        value = z[i] / D[i] - sum((L[k, i] * x[k] for k in range(i + 1, n)), sp.Integer(0))
        block.set(result[i], printer.doprint(value))
        x[i] = sp.Symbol(result[i])


def matrix_entries(matrix: sp.Matrix, tag: str) -> tuple[list[str], list[sp.Expr]]:
    """Names and expressions of the lower triangle's structurally non-zero entries."""
    names, exprs = [], []
    n = matrix.shape[0]
    for i in range(n):
        for j in range(i + 1):
            if matrix[i, j] != 0:
                names.append(f"{tag}m{i}_{j}")
                exprs.append(matrix[i, j])
    return names, exprs


def unpack(vector: str, names: Iterable[str], offset: int = 0) -> list[str]:
    return [f"{name} = {vector}[{i + offset}]" for i, name in enumerate(names)]
