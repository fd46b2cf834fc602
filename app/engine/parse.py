"""Turn expression text into SymPy without ever calling ``eval``.

``sympify`` and ``parse_expr`` evaluate Python code, so they are never used on
text.  The text goes through three gates, each refusing with a message that
names the offending part and where it starts:

1. characters: ASCII letters, digits, ``_ . + - * / ( ) ,`` and spaces only,
   and at most ``MAX_LENGTH`` of them (quotes, brackets, colons and the like
   are the raw material of code, strings, lambdas and f-strings);
2. structure (pure Python, no SymPy): Python's ``ast`` tree walked against an
   allowlist of numbers, declared names, ``+ - * / **``, unary signs and calls
   of a fixed set of functions (``FUNCTIONS``, one argument each but
   ``atan2(y, x)``); limits on nesting depth, node
   count, literal size, exponents and nested calls; constant sub-expressions
   folded exactly (``fractions.Fraction``, with caps on digits and on the index
   of a root SymPy would extract) or in floating point, so that
   ``exp(exp(exp(3)))``, ``12**(1 - 1/3**40)`` or ``asin(2)`` are refused
   instead of sending SymPy's automatic evaluation into a hang or a non-real
   value; towers of exponents refused even behind signs; ``exp(c*log(u))``
   bounded as the power ``u**c`` SymPy turns it into; the degree of powers
   once combined bounded; and an upper bound on the number of terms a full
   expansion can produce, of the whole and of every function's argument;
3. construction: the checked tree is built into SymPy, and a result that is
   undefined or not real (``1/(x - x)``, ``sqrt(-x**2)``, ``asin(2 + x - x)``)
   is refused.

``check_expression`` runs gates 1 and 2 only, so a web process can refuse
hostile text without touching SymPy; ``parse_expression`` runs all three.
``read`` (gates 1 and 2) keeps what it read as a picklable ``Parsed`` and
``build`` (gate 3) makes SymPy of it, so that text read in one process is built
in another without being read again (docs/parsing.md).
"""

from __future__ import annotations

import ast
import io
import keyword
import math
import re
import tokenize
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
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
_MAX_BITS = math.ceil(MAX_DIGITS * math.log2(10))


@dataclass(frozen=True)
class Allowed:
    """A function users may write: SymPy's, the same in floating point (to bound constant
    sub-expressions before SymPy sees them), and how many arguments it takes."""

    symbolic: Callable[..., Any]
    floating: Callable[..., float]
    arity: int = 1


# The function allowlist: its one home.  Everything else (the schemas' help, the pages' menus,
# the figure trees of app/engine/trees.py) reads it from here.
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
ARITY: dict[str, int] = {name: f.arity for name, f in ALLOWED.items() if f.arity != 1}
CONSTANTS: dict[str, sp.Expr] = {"pi": sp.pi}
_FLOAT_CONSTANTS = {"pi": math.pi}
# Names an output string may contain, or that SymPy reads as something else.
_SYMPY_NAMES = {"E", "I", "S", "N", "O", "Q", "oo", "nan", "zoo", "sign", "re", "im", "arg"}
_SYMPY_NAMES |= {"sec", "csc", "cot", "asec", "acsc", "acot", "asinh", "acosh", "atanh", "coth", "sech", "csch"}
_SYMPY_NAMES |= {"atan2", "Max", "Min", "Piecewise", "Heaviside", "DiracDelta", "Integral", "Derivative", "Subs"}
_SYMPY_NAMES |= {"Symbol", "Function", "Integer", "Float", "Rational", "Matrix", "floor", "ceiling"}
RESERVED = frozenset(FUNCTIONS) | frozenset(CONSTANTS) | frozenset(_SYMPY_NAMES) | {"t"} | frozenset(keyword.kwlist)
NAME_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9]{0,15}")  # always matched whole (fullmatch)
# A name ending in "dot" would print like a velocity (SymPy typesets xdot as x with a dot).
_DOTTED = re.compile(r"d{1,4}ot\Z")
ALLOWED_CHARACTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.+-*/(), ")

_OPERATORS = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**"}
_REFUSED_OPERATORS = {
    ast.BitXor: "'^' is not a power here: write x**2",
    ast.FloorDiv: "'//' is not allowed: write a/b",
    ast.Mod: "'%' is not allowed",
    ast.MatMult: "'@' is not allowed",
}
_REFUSED_NODES = {
    ast.Attribute: "attribute access with '.' is not allowed",
    ast.Subscript: "indexing is not allowed",
    ast.Lambda: "a lambda is not allowed",
    ast.JoinedStr: "an f-string is not allowed",
    ast.Compare: "a comparison is not allowed",
    ast.BoolOp: "'and'/'or' are not allowed",
    ast.IfExp: "a conditional expression is not allowed",
    ast.Tuple: "a comma is only allowed between a function's arguments (only atan2 takes two)",
    ast.Starred: "'*' unpacking is not allowed",
    ast.NamedExpr: "':=' is not allowed",
    ast.GeneratorExp: "a generator is not allowed",
}


class ExpressionError(DerivationError):
    """Text that is not an allowed expression.

    ``part`` is the offending piece of the text; ``start`` and ``end`` are its
    character offsets in the text as given (``None`` when no single piece is at
    fault, such as a text that is too long).
    """

    def __init__(self, message: str, part: str = "", start: int | None = None, end: int | None = None):
        super().__init__(message, part)
        self.start = start
        self.end = end

    def __reduce__(self):  # keep part and offsets across a process boundary
        return (type(self), (str(self), self.part, self.start, self.end))


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


@dataclass(frozen=True)
class _Facts:
    """What the checker knows about a sub-expression."""

    value: float | None  # its value in floating point when it is a constant
    exact: Fraction | None  # its exact value when it is a rational constant
    terms: int  # an upper bound on the terms of its full expansion (capped)
    inside: int = 1  # the same bound for the largest function argument within (expand expands those too)
    degree: float = 0  # an upper bound on the exponent SymPy may give any one factor after combining powers
    calls: int = 0  # how deeply function calls nest inside it


def _cap(n: int) -> int:
    return min(n, MAX_TERMS + 1)


def _strip_signs(node: ast.AST) -> tuple[ast.AST, int]:
    """The operand under a run of unary signs, and the sign they amount to."""
    sign = 1
    while isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        sign = -sign if isinstance(node.op, ast.USub) else sign
        node = node.operand
    return node, sign


def _chain(node: ast.AST, ops: tuple[type, ...]) -> list[tuple[type | None, ast.AST, ast.AST]]:
    """A left-deep run of operators of one family (a + b - c, a * b / c) as a flat list, without recursion.

    Each item is (operator or None for the first operand, operand, the partial expression it ends).
    """
    items: list[tuple[type | None, ast.AST, ast.AST]] = []
    while isinstance(node, ast.BinOp) and type(node.op) in ops:
        items.append((type(node.op), node.right, node))
        node = node.left
    items.append((None, node, node))
    items.reverse()
    return items


_SUMS = (ast.Add, ast.Sub)
_PRODUCTS = (ast.Mult, ast.Div)
# the real domain of functions that are not real everywhere, for an exact (rational) argument
_DOMAINS: dict[str, Callable[[Fraction], bool]] = {
    "asin": lambda a: -1 <= a <= 1,
    "acos": lambda a: -1 <= a <= 1,
    "log": lambda a: a > 0,
    "sqrt": lambda a: a >= 0,
}


class _Checker:
    """Gate 2: the allowlist walk, in pure Python.

    Sums and products are walked as flat lists (their length is bounded by
    MAX_NODES, their nesting by nothing), so the recursion follows only real
    nesting (parentheses, calls, signs, powers), which MAX_DEPTH bounds.
    """

    def __init__(self, text: str, offset: int, names: Collection[str]):
        self.text = text
        self.offset = offset
        self.names = names
        self.memo: dict[int, _Facts] = {}

    def refuse(self, node: ast.AST, why: str) -> ExpressionError:
        start = getattr(node, "col_offset", 0)
        end = getattr(node, "end_col_offset", None) or len(self.text)
        part = self.text[start:end]
        shown = part if len(part) <= 60 else part[:57] + "..."
        return ExpressionError(
            f"{why}: {shown!r} at column {self.offset + start + 1}",
            shown,
            self.offset + start,
            self.offset + end,
        )

    def check(self, node: ast.AST, depth: int = 0) -> _Facts:
        if id(node) not in self.memo:
            self.memo[id(node)] = self._check(node, depth)
        return self.memo[id(node)]

    def _check(self, node: ast.AST, depth: int) -> _Facts:
        if depth > MAX_DEPTH:
            raise self.refuse(node, f"nested deeper than {MAX_DEPTH} levels")
        if isinstance(node, ast.Constant):
            return self.literal(node)
        if isinstance(node, ast.Name):
            return self.name(node)
        if isinstance(node, ast.UnaryOp):
            if not isinstance(node.op, (ast.USub, ast.UAdd)):
                raise self.refuse(node, "only the signs + and - may stand before a term")
            inner = self.check(node.operand, depth + 1)
            if isinstance(node.op, ast.UAdd) or inner.value is None:
                return inner
            exact = None if inner.exact is None else -inner.exact
            return _Facts(-inner.value, exact, inner.terms, inner.inside, inner.degree, inner.calls)
        if isinstance(node, ast.BinOp):
            if type(node.op) not in _OPERATORS:
                why = _REFUSED_OPERATORS.get(type(node.op), "only + - * / ** are allowed")
                raise self.refuse(node, why)
            if isinstance(node.op, ast.Pow):
                base, exponent = self.check(node.left, depth + 1), self.check(node.right, depth + 1)
                if isinstance(_strip_signs(node.right)[0], ast.BinOp) and isinstance(
                    _strip_signs(node.right)[0].op, ast.Pow  # type: ignore[attr-defined]
                ):
                    raise self.refuse(node, "towers of exponents are not allowed")
                return self.power(node, base, exponent)
            return self.sum(node, depth) if isinstance(node.op, _SUMS) else self.product(node, depth)
        if isinstance(node, ast.Call):
            return self.call(node, depth)
        why = _REFUSED_NODES.get(type(node), f"{type(node).__name__} is not allowed in an expression")
        raise self.refuse(node, why)

    def literal(self, node: ast.Constant) -> _Facts:
        value = node.value
        if isinstance(value, complex):
            raise self.refuse(node, "imaginary numbers are not allowed")
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.refuse(node, "only numbers are allowed as literals")
        if isinstance(value, int) and abs(value) >= 10**15:
            raise self.refuse(node, "integer literal longer than 15 digits")
        if isinstance(value, float) and not (math.isfinite(value) and abs(value) <= MAX_LITERAL):
            raise self.refuse(node, f"number out of range (at most {MAX_LITERAL:.0e} in magnitude)")
        # a decimal literal stands for the exact rational it names (as the builder makes it)
        exact = Fraction(value) if isinstance(value, int) else Fraction(repr(value))
        return _Facts(float(value), self.exactly(node, exact), 1)

    def name(self, node: ast.Name) -> _Facts:
        name = node.id
        if name in self.names:
            return _Facts(None, None, 1, degree=1)
        if name in _FLOAT_CONSTANTS:
            # SymPy keeps pi symbolic and combines its powers as a symbol's: (pi**5)**c is pi**(5*c)
            return _Facts(_FLOAT_CONSTANTS[name], None, 1, degree=1)
        if name in FUNCTIONS:
            raise self.refuse(node, f"{name} is a function: write {name}(...)")
        if name.endswith("_ddot"):
            raise self.refuse(node, "accelerations never appear in a declaration; the engine derives them")
        if name.endswith("_dot") and name[:-4] in self.names:
            raise self.refuse(node, "a velocity is not allowed here (only in T, L and forces)")
        declared = ", ".join(sorted(self.names)) or "none"
        raise self.refuse(node, f"unknown name (allowed here: {declared}, pi)")

    def sum(self, node: ast.BinOp, depth: int) -> _Facts:
        items = _chain(node, _SUMS)
        facts = [self.check(operand, depth + 1) for _, operand, _ in items]
        value, exact = facts[0].value, facts[0].exact
        for (op, _, partial), f in zip(items[1:], facts[1:], strict=True):
            sign = 1 if op is ast.Add else -1
            if value is not None and f.value is not None:
                if exact is not None and f.exact is not None:
                    exact = self.exactly(partial, exact + sign * f.exact)
                    value = self.fold(partial, lambda e=exact: float(e))  # type: ignore[misc]
                else:
                    exact, value = None, self.fold(partial, lambda a=value, b=f.value, s=sign: a + s * b)  # type: ignore[misc]
            else:
                value = exact = None
        return _Facts(
            value,
            exact,
            _cap(sum(f.terms for f in facts)),
            max(f.inside for f in facts),
            max(f.degree for f in facts),
            max(f.calls for f in facts),
        )

    def product(self, node: ast.BinOp, depth: int) -> _Facts:
        items = _chain(node, _PRODUCTS)
        facts = [self.check(operand, depth + 1) for _, operand, _ in items]
        value, exact, terms = facts[0].value, facts[0].exact, facts[0].terms
        for (op, _, partial), f in zip(items[1:], facts[1:], strict=True):
            if op is ast.Div and f.value == 0:
                raise self.refuse(partial, "division by zero")
            # a product (or a quotient, whose denominator expands too) multiplies the terms
            terms = _cap(terms * f.terms)
            if value is not None and f.value is not None:
                if exact is not None and f.exact is not None:
                    exact = self.exactly(partial, exact * f.exact if op is ast.Mult else exact / f.exact)
                    value = self.fold(partial, lambda e=exact: float(e))  # type: ignore[misc]
                else:
                    exact = None
                    value = self.fold(partial, lambda a=value, b=f.value, o=op: a * b if o is ast.Mult else a / b)  # type: ignore[misc]
            else:
                value = exact = None
        degree = sum(f.degree for f in facts)
        if degree > MAX_DEGREE:
            raise self.refuse(
                node, f"the powers here grow too large (degree {degree:g} once combined; at most {MAX_DEGREE})"
            )
        return _Facts(value, exact, terms, max(f.inside for f in facts), degree, max(f.calls for f in facts))

    def power(self, node: ast.AST, base: _Facts, exponent: _Facts) -> _Facts:
        """base**exponent, also when written exp(exponent*log(base)) (which SymPy turns into a power)."""
        if exponent.value is None:
            raise self.refuse(node, "exponents must be numbers (write exp(y*log(x)) for x**y)")
        n = exponent.value
        if abs(n) > MAX_EXPONENT:
            raise self.refuse(node, f"exponent larger than {MAX_EXPONENT} in magnitude")
        if base.value == 0 and n < 0:
            raise self.refuse(node, "division by zero")
        whole_exponent = exponent.exact is not None and exponent.exact.denominator == 1
        exact = None
        if base.value is not None:
            # SymPy extracts roots of a constant exactly: a large root index makes it search for ever
            if exponent.exact is not None and exponent.exact.denominator > MAX_ROOT:
                raise self.refuse(
                    node, f"a root of index {exponent.exact.denominator} is too large (at most {MAX_ROOT})"
                )
            if base.value < 0 and not whole_exponent:
                raise self.refuse(node, "this number is not real (a fractional power of a negative number)")
            if base.exact is not None and whole_exponent:
                p = abs(exponent.exact.numerator)  # type: ignore[union-attr]
                bits = max(base.exact.numerator.bit_length(), base.exact.denominator.bit_length())
                if bits * p > _MAX_BITS:
                    raise self.refuse(node, f"this number is too large (more than {MAX_DIGITS} digits)")
                exact = self.exactly(node, base.exact**exponent.exact.numerator)  # type: ignore[union-attr]
        degree = base.degree * abs(n)
        if degree > MAX_DEGREE:
            raise self.refuse(
                node, f"the powers here grow too large (degree {degree:g} once combined; at most {MAX_DEGREE})"
            )
        # (a_1 + ... + a_k)**n expands into at most C(n + k - 1, n) terms
        whole = math.ceil(abs(n))
        terms = math.comb(whole + base.terms - 1, whole) if base.terms > 1 else 1
        value = None
        if base.value is not None:
            # an exact constant of up to MAX_DIGITS digits can still be far past a float's range: fold refuses it
            value = self.fold(node, (lambda: float(exact)) if exact is not None else (lambda: base.value**n))  # type: ignore[operator]
        return _Facts(value, exact, _cap(terms), base.inside, degree, base.calls)

    def call(self, node: ast.Call, depth: int) -> _Facts:
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
            allowed = ", ".join(sorted(FUNCTIONS))
            if isinstance(node.func, ast.Constant | ast.Call | ast.BinOp) or (
                isinstance(node.func, ast.Name) and node.func.id in self.names
            ):
                # "2(x+1)", "k(x+1)", "(a+b)(a-b)": factors side by side, not a call
                source = ast.get_source_segment(self.text, node) or ""
                head = ast.get_source_segment(self.text, node.func) or ""
                starred = head + "*" + source[len(head) :].lstrip() if source.startswith(head) else ""
                hint = f"write {starred} (a * between factors)" if starred else "a * between factors is needed"
                raise self.refuse(node.func, f"{head or 'this'} is not a function: {hint}")
            raise self.refuse(node.func, f"only these functions may be called: {allowed}")
        name = node.func.id
        arity = ARITY.get(name, 1)
        if node.keywords or len(node.args) != arity or any(isinstance(a, ast.Starred) for a in node.args):
            count = "exactly one argument" if arity == 1 else f"exactly {arity} arguments"
            raise self.refuse(node, f"{name} takes {count}")
        arguments = [self.check(a, depth + 1) for a in node.args]
        calls = max(a.calls for a in arguments) + 1
        if calls > MAX_CALLS:
            raise self.refuse(node, f"functions nested more than {MAX_CALLS} deep")
        inside = max(max(a.inside, a.terms) for a in arguments)
        terms, degree = 1, 1.0
        powers: list[_Facts] = []
        if name == "exp":
            # SymPy rewrites exp(c*log(u) + rest) as u**c * exp(rest), also for a constant u
            # (exp(10**15*log(0.5)) is 2**-10**15): bound those powers as powers
            powers = [self.power(summand, u, c) for summand, u, c in self.exp_log_powers(node.args[0], depth + 1)]
            for p in powers:
                terms, inside = _cap(terms * p.terms), max(inside, p.inside)
            degree = max(degree, sum(p.degree for p in powers))
        if all(a.value is not None for a in arguments):
            if name == "atan2" and arguments[0].value == 0 and arguments[1].value == 0:
                raise self.refuse(node, "atan2(0, 0) is undefined")
            exact = arguments[0].exact
            if arity == 1 and exact is not None and name in _DOMAINS and not _DOMAINS[name](exact):
                raise self.refuse(node, f"this number is undefined or not real ({name} of {self.fold(node, lambda: float(exact)):g})")
            function = ALLOWED[name].floating
            value = self.fold(node, lambda: function(*(a.value for a in arguments)))
            rational = self.exact_call(node, name, powers, depth)
            if rational is not None:
                return _Facts(value, rational, 1, inside, 0, calls)
            # SymPy keeps sin(1) unevaluated and combines its powers as a symbol's ((sin(1)**5)**52 is sin(1)**260)
            return _Facts(value, None, 1, inside, 1, calls)
        return _Facts(None, None, terms, inside, degree, calls)

    def exact_call(self, node: ast.Call, name: str, powers: list[_Facts], depth: int) -> Fraction | None:
        """The exact rational SymPy turns a constant call into, when it does: exp(c*log(u)) is u**c, and
        log(exp(v)) is v (then ``((10**15 - 1))**-exp(-log(10**15))`` meets the root-index cap instead of
        sending SymPy after a root of index 10**15)."""
        argument = node.args[0]
        if name == "exp" and len(powers) == 1 and len(_chain(_strip_signs(argument)[0], _SUMS)) == 1:
            return powers[0].exact
        inner = _strip_signs(argument)[0] if name == "log" else None
        if isinstance(inner, ast.Call) and getattr(inner.func, "id", "") == "exp" and inner is argument:
            return self.check(inner.args[0], depth + 2).exact if len(inner.args) == 1 else None
        return None

    def exp_log_powers(self, argument: ast.AST, depth: int) -> list[tuple[ast.AST, _Facts, _Facts]]:
        """The summands c*log(u) (c constant) of an exp's argument, each as (summand, u, c)."""
        found = []
        whole, whole_sign = _strip_signs(argument)
        for op, summand, _ in _chain(whole, _SUMS):
            term, sign = _strip_signs(summand)
            sign *= whole_sign * (-1 if op is ast.Sub else 1)
            logs, value, exact = [], float(sign), Fraction(sign)
            for factor_op, factor, _ in _chain(term, _PRODUCTS):
                inner, factor_sign = _strip_signs(factor)
                if isinstance(inner, ast.Call) and getattr(inner.func, "id", "") == "log" and factor_op is not ast.Div:
                    logs.append(inner)
                    value, exact = value * factor_sign, None if exact is None else exact * factor_sign
                    continue
                f = self.check(factor, depth)
                if f.value is None or f.value == 0:
                    break
                divide = factor_op is ast.Div
                value = value / f.value if divide else value * f.value
                exact = None if exact is None or f.exact is None else (exact / f.exact if divide else exact * f.exact)  # type: ignore[assignment]
            else:
                if len(logs) == 1:
                    u = self.check(logs[0].args[0], depth + 1)
                    found.append((summand, u, _Facts(value, exact, 1)))
        return found

    def exactly(self, node: ast.AST, value: Fraction) -> Fraction:
        """An exact rational constant, refused when its numerator or denominator is too long to keep."""
        if max(value.numerator.bit_length(), value.denominator.bit_length()) > _MAX_BITS:
            raise self.refuse(node, f"this number is too large to keep exactly (more than {MAX_DIGITS} digits)")
        return value

    def fold(self, node: ast.AST, compute: Callable[[], float]) -> float:
        """The value of a constant sub-expression, refused when huge or not real."""
        try:
            value = compute()
        except ZeroDivisionError:
            raise self.refuse(node, "division by zero") from None
        except OverflowError:
            raise self.refuse(node, f"this number is too large (at most {MAX_CONSTANT:.0e})") from None
        except (ValueError, TypeError):
            raise self.refuse(node, "this number is undefined or not real") from None
        if isinstance(value, complex):
            raise self.refuse(node, "this number is not real")
        if not math.isfinite(value) or abs(value) > MAX_CONSTANT:
            raise self.refuse(node, f"this number is too large (at most {MAX_CONSTANT:.0e})")
        return value


def _first_bad_character(text: str) -> int | None:
    for i, ch in enumerate(text):
        if ch not in ALLOWED_CHARACTERS:
            return i
    return None


def _character_error(text: str, i: int) -> ExpressionError:
    ch = text[i]
    if ch == "^":
        why = "'^' is not a power here: write x**2"
    elif ch == "=":
        why = "an equation is not an expression: write it as one expression equal to zero, e.g. a - (b) for a = b"
    elif ch in "'\"":
        why = "quotes are not allowed: an expression holds no strings"
    elif ord(ch) > 127:
        why = "only ASCII is allowed (write theta, not θ)"
    else:
        why = "only letters, digits, spaces, _ . , ( ) and + - * / ** are allowed"
    return ExpressionError(f"character {ch!r} at column {i + 1} is not allowed: {why}", ch, i, i + 1)


def _with_stars(text: str) -> str | None:
    """The text with a * put between factors written side by side ("m R**2 theta_dot"), if that makes it read.

    Two factors meet where a name, number or closing bracket is followed, after spaces, by a name, a number
    or an opening bracket; a name directly followed by "(" is a call and stays one."""
    out, last_end, gaps = [], 0, 0
    previous: tokenize.TokenInfo | None = None
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError, IndentationError):
        return None
    for tok in tokens:
        if tok.type in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER):
            continue
        ends = previous is not None and (
            previous.type in (tokenize.NAME, tokenize.NUMBER) or previous.string == ")"
        )
        starts = tok.type in (tokenize.NAME, tokenize.NUMBER) or tok.string == "("
        call = tok.string == "(" and previous is not None and previous.type == tokenize.NAME and previous.end == tok.start
        if ends and starts and not call and previous is not None:
            out.append(text[last_end : previous.end[1]] + "*")
            last_end = tok.start[1]
            gaps += 1
        previous = tok
    if not gaps:
        return None
    fixed = "".join(out) + text[last_end:]
    try:
        ast.parse(fixed, mode="eval")
    except SyntaxError:
        return None
    return fixed


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


def _compact(node: ast.AST) -> Node:
    """A checked ``ast`` tree in the compact form."""
    start, end = getattr(node, "col_offset", 0), getattr(node, "end_col_offset", None)
    if isinstance(node, ast.Constant):
        return ("num", start, end, node.value)
    if isinstance(node, ast.Name):
        return ("name", start, end, node.id)
    if isinstance(node, ast.UnaryOp):
        return ("neg" if isinstance(node.op, ast.USub) else "pos", start, end, _compact(node.operand))
    if isinstance(node, ast.BinOp) and isinstance(node.op, (*_SUMS, *_PRODUCTS)):
        # a long sum or product is a flat list, not a recursion as deep as it is long
        items = _chain(node, _SUMS if isinstance(node.op, _SUMS) else _PRODUCTS)
        rest = tuple((_OPERATORS[op], _compact(operand)) for op, operand, _ in items[1:])  # type: ignore[index]
        return ("chain", start, end, _compact(items[0][1]), rest)
    if isinstance(node, ast.BinOp):
        return ("pow", start, end, _compact(node.left), _compact(node.right))
    assert isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
    return ("call", start, end, node.func.id, tuple(_compact(a) for a in node.args))


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
    tree, facts = _checked(text, names)
    # one set shared by many texts is pickled once
    allowed = names if isinstance(names, frozenset) else frozenset(names)
    return Parsed(text, _compact(tree.body), Size(facts.terms, facts.degree), allowed)


def expression_size(text: str, names: Collection[str]) -> Size:
    """Check an expression as ``check_expression`` does and return its size bounds."""
    facts = _checked(text, names)[1]
    return Size(facts.terms, facts.degree)


def _checked(text: str, names: Collection[str]) -> tuple[ast.Expression, _Facts]:
    if not isinstance(text, str):
        raise ExpressionError("an expression must be a string")
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"expression is {len(text)} characters long; at most {MAX_LENGTH} are allowed")
    # tabs and line breaks count as spaces (one for one, so columns stay right)
    text = text.translate({9: " ", 10: " ", 13: " "})
    bad = _first_bad_character(text)
    if bad is not None:
        raise _character_error(text, bad)
    stripped = text.strip()
    if not stripped:
        raise ExpressionError("empty expression (write 0 for nothing)")
    offset = len(text) - len(text.lstrip())
    try:
        tree = ast.parse(stripped, mode="eval")
    except SyntaxError as exc:
        column = min(max((exc.offset or 1) - 1, 0), len(stripped))
        first, last = max(column - 10, 0), min(column + 10, len(stripped))
        near = stripped[first:last]
        starred = _with_stars(stripped)
        hint = f"write {starred} (a * between factors)" if starred else exc.msg
        raise ExpressionError(
            f"syntax error at column {offset + column + 1} ({hint}), near {near!r}",
            near,
            offset + first,
            offset + last,
        ) from None
    except (RecursionError, MemoryError, ValueError):
        raise ExpressionError("expression could not be read (too deeply nested?)") from None
    count = sum(isinstance(node, ast.expr) for node in ast.walk(tree))
    if count > MAX_NODES:
        raise ExpressionError(f"expression has {count} parts; at most {MAX_NODES} are allowed")
    facts = _Checker(stripped, offset, names).check(tree.body)
    if facts.terms > MAX_TERMS or facts.inside > MAX_TERMS:
        where = "expression" if facts.terms > MAX_TERMS else "a function's argument"
        raise ExpressionError(
            f"{where} would expand into more than {MAX_TERMS} terms; write it in a smaller form",
            stripped[:60],
            offset,
            offset + len(stripped),
        )
    return tree, facts


@dataclass(frozen=True)
class _Span:
    """Where a compact node stands, as a refusal reads it from an ``ast`` node."""

    col_offset: int
    end_col_offset: int | None


class _Builder:
    """Gate 3: a checked tree (in the compact form) into SymPy."""

    def __init__(self, text: str, offset: int, names: Mapping[str, sp.Symbol]):
        self.checker = _Checker(text, offset, names)
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
        return self.real(node, FUNCTIONS[node[3]](*(self.build(a) for a in node[4])))

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
    spaced = parsed.text.translate({9: " ", 10: " ", 13: " "})
    stripped = spaced.strip()
    offset = len(spaced) - len(spaced.lstrip())
    expr = _Builder(stripped, offset, names).build(parsed.tree)
    if expr.has(sp.zoo, sp.oo, sp.nan, -sp.oo):
        raise ExpressionError(f"the expression is undefined (a division by zero?): {stripped[:60]!r}", stripped[:60])
    if expr.has(sp.I):
        raise ExpressionError(f"the expression is not real: {stripped[:60]!r}", stripped[:60])
    return expr
