"""The parser's rules (app/engine/parser/parse.py): its limits, the allowlist of functions, the names a user may
declare, and the error every refusal raises.

These are the facts the three gates read and the rest of the project quotes (the schemas' help, the pages'
menus, the figure trees): one home, no SymPy work.
"""

from __future__ import annotations

import keyword
import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import sympy as sp

from app.engine.errors import DerivationError

MAX_LENGTH = 2000  # characters in one expression
MAX_DEPTH = 40  # nesting of the expression tree
MAX_NODES = 600  # parts of the expression tree
MAX_EXPONENT = 64  # magnitude of a numeric exponent
MAX_LITERAL = 1e15  # magnitude of a number as written (integers: at most 15 digits)
MAX_CONSTANT = 1e100  # magnitude of any constant sub-expression, such as 10**20 or exp(50)
MAX_TERMS = 2000  # terms a full expansion of the expression (or of a function's argument) may produce
MAX_DIGITS = 400  # digits of the numerator or denominator of an exact rational constant (a float literal: under 340)
MAX_ROOT = 64  # index of a root SymPy extracts from a constant (x**(p/q) with x constant: q)
MAX_DEGREE = 256  # exponent of any one factor once SymPy combines powers ((x**8)**8, x**40*x**40, exp(9*log(x)))
MAX_CALLS = 8  # functions nested inside one another (each level multiplies the size of the derivatives)
MAX_BITS = math.ceil(MAX_DIGITS * math.log2(10))


@dataclass(frozen=True)
class Allowed:
    """A function users may write: SymPy's, the same in floating point (to bound constant
    sub-expressions before SymPy sees them), and how many arguments it takes."""

    symbolic: Callable[..., Any]
    floating: Callable[..., float]
    arity: int = 1


# The function allowlist: its one home.  Everything else (the schemas' help, the pages' menus,
# the figure trees of app/engine/document/trees.py) reads it from here.
ALLOWED: dict[str, Allowed] = {
    "sin": Allowed(sp.sin, math.sin),
    "cos": Allowed(sp.cos, math.cos),
    "tan": Allowed(sp.tan, math.tan),
    "cot": Allowed(sp.cot, lambda x: 1.0 / math.tan(x)),
    "sec": Allowed(sp.sec, lambda x: 1.0 / math.cos(x)),
    "csc": Allowed(sp.csc, lambda x: 1.0 / math.sin(x)),
    "asin": Allowed(sp.asin, math.asin),
    "acos": Allowed(sp.acos, math.acos),
    "atan": Allowed(sp.atan, math.atan),
    # atan2(y, x) is the angle of the point (x, y)
    "atan2": Allowed(sp.atan2, math.atan2, arity=2),
    "sinh": Allowed(sp.sinh, math.sinh),
    "cosh": Allowed(sp.cosh, math.cosh),
    "tanh": Allowed(sp.tanh, math.tanh),
    "exp": Allowed(sp.exp, math.exp),
    "log": Allowed(sp.log, math.log),
    "sqrt": Allowed(sp.sqrt, math.sqrt),
    "Abs": Allowed(sp.Abs, abs),
}
FUNCTIONS: dict[str, Callable[..., Any]] = {name: f.symbolic for name, f in ALLOWED.items()}
# a function as a student types it where SymPy's name is another: |x| is typed abs(x), as in Python
TYPED_FUNCTIONS = {"abs": "Abs"}
ARITY: dict[str, int] = {name: f.arity for name, f in ALLOWED.items() if f.arity != 1}
CONSTANTS: dict[str, sp.Expr] = {"pi": sp.pi}
FLOAT_CONSTANTS = {"pi": math.pi}
# Names an output string may contain, or that SymPy reads as something else.
_SYMPY_NAMES = {"E", "I", "S", "N", "O", "Q", "oo", "nan", "zoo", "sign", "re", "im", "arg"}
_SYMPY_NAMES |= {"sec", "csc", "cot", "asec", "acsc", "acot", "asinh", "acosh", "atanh", "coth", "sech", "csch"}
_SYMPY_NAMES |= {"atan2", "Max", "Min", "Piecewise", "Heaviside", "DiracDelta", "Integral", "Derivative", "Subs"}
_SYMPY_NAMES |= {"Symbol", "Function", "Integer", "Float", "Rational", "Matrix", "floor", "ceiling"}
_SYMPY_NAMES |= set(TYPED_FUNCTIONS)
RESERVED = frozenset(FUNCTIONS) | frozenset(CONSTANTS) | frozenset(_SYMPY_NAMES) | {"t"} | frozenset(keyword.kwlist)
NAME_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9]{0,15}")  # always matched whole (fullmatch)
# A name ending in "dot" would print like a velocity (SymPy typesets xdot as x with a dot).
_DOTTED = re.compile(r"d{1,4}ot\Z")
ALLOWED_CHARACTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.+-*/(), ")


def typed_function(name: str) -> str:
    """A function of the allowlist as a student types it (Abs: abs; sin: sin)."""
    return next((typed for typed, own in TYPED_FUNCTIONS.items() if own == name), name)


class ExpressionError(DerivationError):
    """Text that is not an allowed expression.

    ``part`` is the offending piece of the text; ``start`` and ``end`` are its
    character offsets in the text as given (``None`` when no single piece is at
    fault, such as a text that is too long).  ``readings`` are the two ways an
    ambiguous text could be read (``1/2m``: ``(1/2) m`` and ``1/(2 m)``), else empty.
    """

    def __init__(
        self,
        message: str,
        part: str = "",
        start: int | None = None,
        end: int | None = None,
        readings: tuple[str, ...] = (),
    ):
        super().__init__(message, part)
        self.start = start
        self.end = end
        self.readings = tuple(readings)

    def __reduce__(self):  # keep part, offsets and readings across a process boundary
        return (type(self), (str(self), self.part, self.start, self.end, self.readings))


def check_name(name: str, what: str = "name") -> str:
    """A declared name: a letter then up to 15 letters or digits, not a function, constant or keyword."""
    if not isinstance(name, str) or not NAME_PATTERN.fullmatch(name):
        shown = str(name)[:40]
        raise ExpressionError(
            f"{what} {shown!r} is not allowed: use a letter followed by up to 15 ASCII letters or digits "
            "(no underscores or spaces)",
            shown,
        )
    if name in RESERVED:
        kind = "a Python keyword" if keyword.iskeyword(name) else "a reserved function or constant name"
        kind = "time, which every expression may use" if name == "t" else kind
        raise ExpressionError(f"{what} {name!r} is {kind}; choose another name", name)
    if _DOTTED.search(name) and name[: _DOTTED.search(name).start()]:  # type: ignore[union-attr]
        raise ExpressionError(f"{what} {name!r} would print like a velocity; choose another name", name)
    return name
