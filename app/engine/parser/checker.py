"""Gate 2 of the parser (app/engine/parser/parse.py): the allowlist walk over Python's ``ast`` tree, in pure Python.

The walk accepts numbers, declared names, ``+ - * / **``, unary signs and calls of the allowed functions,
and bounds what SymPy's automatic evaluation could do with them: nesting, exponents, nested calls, the
size of constants (folded exactly with ``fractions.Fraction``, or in floating point), the index of roots,
the degree of combined powers and the number of terms a full expansion can produce.  Each refusal names
the offending part and its columns.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Callable, Collection
from dataclasses import dataclass
from fractions import Fraction

from app.engine.parser.rules import (
    ALLOWED,
    ARITY,
    FLOAT_CONSTANTS,
    FUNCTIONS,
    MAX_BITS,
    MAX_CALLS,
    MAX_CONSTANT,
    MAX_DEGREE,
    MAX_DEPTH,
    MAX_DIGITS,
    MAX_EXPONENT,
    MAX_LITERAL,
    MAX_ROOT,
    MAX_TERMS,
    ExpressionError,
    typed_function,
)
from app.engine.parser.typed import Typed

OPERATORS = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**"}
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


def product_of_names(word: str, names: Collection[str]) -> list[str] | None:
    """``word`` as a product of the fewest of ``names`` written together (mgl: m, g, l), if it is one."""
    if "_" in word or len(word) > 16:
        return None
    # best[i]: the fewest names spelling word[:i]
    best: list[list[str] | None] = [[]] + [None] * len(word)
    for i in range(1, len(word) + 1):
        for j in range(i):
            name, before = word[j:i], best[j]
            if before is not None and name in names and (best[i] is None or len(before) + 1 < len(best[i])):  # type: ignore[arg-type]
                best[i] = [*before, name]
    found = best[len(word)]
    return found if found is not None and len(found) > 1 else None


@dataclass(frozen=True)
class Facts:
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


def chain(node: ast.AST, ops: tuple[type, ...]) -> list[tuple[type | None, ast.AST, ast.AST]]:
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


SUMS = (ast.Add, ast.Sub)
PRODUCTS = (ast.Mult, ast.Div)
# the real domain of functions that are not real everywhere, for an exact (rational) argument
_DOMAINS: dict[str, Callable[[Fraction], bool]] = {
    "asin": lambda a: -1 <= a <= 1,
    "acos": lambda a: -1 <= a <= 1,
    "log": lambda a: a > 0,
    "sqrt": lambda a: a >= 0,
}


class Checker:
    """Gate 2: the allowlist walk, in pure Python.

    Sums and products are walked as flat lists (their length is bounded by
    MAX_NODES, their nesting by nothing), so the recursion follows only real
    nesting (parentheses, calls, signs, powers), which MAX_DEPTH bounds.
    """

    def __init__(self, text: str, offset: int, names: Collection[str], typed: Typed | None = None):
        self.text = text
        self.offset = offset
        self.names = names
        self.typed = typed  # the text as typed, when ``text`` is its rewriting (app/engine/parser/typed.py)
        self.memo: dict[int, Facts] = {}

    def refuse(self, node: ast.AST, why: str) -> ExpressionError:
        start = getattr(node, "col_offset", 0)
        end = getattr(node, "end_col_offset", None) or len(self.text)
        if self.typed is not None:
            # the columns and the words of what the student typed, not of its rewriting
            start, end = self.typed.span(start, end)
            part = self.typed.given[start:end]
        else:
            part = self.text[start:end]
            start, end = self.offset + start, self.offset + end
        shown = part if len(part) <= 60 else part[:57] + "..."
        return ExpressionError(f"{why}: {shown!r} at column {start + 1}", shown, start, end)

    def check(self, node: ast.AST, depth: int = 0) -> Facts:
        if id(node) not in self.memo:
            self.memo[id(node)] = self._check(node, depth)
        return self.memo[id(node)]

    def _check(self, node: ast.AST, depth: int) -> Facts:
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
            return Facts(-inner.value, exact, inner.terms, inner.inside, inner.degree, inner.calls)
        if isinstance(node, ast.BinOp):
            if type(node.op) not in OPERATORS:
                why = _REFUSED_OPERATORS.get(type(node.op), "only + - * / ** are allowed")
                raise self.refuse(node, why)
            if isinstance(node.op, ast.Pow):
                base, exponent = self.check(node.left, depth + 1), self.check(node.right, depth + 1)
                if isinstance(_strip_signs(node.right)[0], ast.BinOp) and isinstance(
                    _strip_signs(node.right)[0].op, ast.Pow  # type: ignore[attr-defined]
                ):
                    raise self.refuse(node, "towers of exponents are not allowed")
                return self.power(node, base, exponent)
            return self.sum(node, depth) if isinstance(node.op, SUMS) else self.product(node, depth)
        if isinstance(node, ast.Call):
            return self.call(node, depth)
        why = _REFUSED_NODES.get(type(node), f"{type(node).__name__} is not allowed in an expression")
        raise self.refuse(node, why)

    def literal(self, node: ast.Constant) -> Facts:
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
        return Facts(float(value), self.exactly(node, exact), 1)

    def name(self, node: ast.Name) -> Facts:
        name = node.id
        if name in self.names:
            return Facts(None, None, 1, degree=1)
        if name in FLOAT_CONSTANTS:
            # SymPy keeps pi symbolic and combines its powers as a symbol's: (pi**5)**c is pi**(5*c)
            return Facts(FLOAT_CONSTANTS[name], None, 1, degree=1)
        if name in FUNCTIONS:
            raise self.refuse(node, f"{typed_function(name)} is a function: write {typed_function(name)}(...)")
        if name.endswith("_ddot"):
            raise self.refuse(node, "accelerations never appear in a declaration; the engine derives them")
        if name.endswith("_dot") and name[:-4] in self.names:
            raise self.refuse(node, "a velocity is not allowed here (only in T, L and forces)")
        declared = ", ".join(sorted(self.names)) or "none"
        hint = ""
        split = product_of_names(name, {*self.names, *FLOAT_CONSTANTS})
        if split:
            # letters written together are one name, never split: say how to write the product
            hint = f"; letters written together are one name: for a product write {' '.join(split)}"
        elif name == "e":
            hint = "; write exp(x) for e^x"
        raise self.refuse(node, f"unknown name (allowed here: {declared}, pi{hint})")

    def sum(self, node: ast.BinOp, depth: int) -> Facts:
        items = chain(node, SUMS)
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
        return Facts(
            value,
            exact,
            _cap(sum(f.terms for f in facts)),
            max(f.inside for f in facts),
            max(f.degree for f in facts),
            max(f.calls for f in facts),
        )

    def product(self, node: ast.BinOp, depth: int) -> Facts:
        items = chain(node, PRODUCTS)
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
        return Facts(value, exact, terms, max(f.inside for f in facts), degree, max(f.calls for f in facts))

    def power(self, node: ast.AST, base: Facts, exponent: Facts) -> Facts:
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
                if bits * p > MAX_BITS:
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
        return Facts(value, exact, _cap(terms), base.inside, degree, base.calls)

    def call(self, node: ast.Call, depth: int) -> Facts:
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
            allowed = ", ".join(sorted(typed_function(f) for f in FUNCTIONS))  # as typed: abs, never Abs
            if isinstance(node.func, ast.Constant | ast.Call | ast.BinOp) or (
                isinstance(node.func, ast.Name) and node.func.id in self.names
            ):
                # "k(x+1)": a name directly followed by "(" reads as a call; "θ(t)" as the coordinate in time
                if [getattr(a, "id", None) for a in node.args] == ["t"] and isinstance(node.func, ast.Name):
                    raise self.refuse(node, "a coordinate already depends on time: write it alone, without (t)")
                source = ast.get_source_segment(self.text, node) or ""
                head = ast.get_source_segment(self.text, node.func) or ""
                if self.typed is not None:
                    # the student's own characters (½m(ẋ₁²+ẋ₂²)), never the rewriting (x1_dot**2) they did not type
                    at = self.typed.span(node.col_offset, node.end_col_offset)
                    source = self.typed.given[at[0] : at[1]]
                    head = self.typed.given[slice(*self.typed.span(node.func.col_offset, node.func.end_col_offset))]
                spaced = head + " " + source[len(head) :].lstrip() if head and source.startswith(head) else ""
                hint = (f"put a space (or *) between {head} and the bracket: {spaced}" if spaced
                        else "a * between factors is needed")
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
        powers: list[Facts] = []
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
                return Facts(value, rational, 1, inside, 0, calls)
            # SymPy keeps sin(1) unevaluated and combines its powers as a symbol's ((sin(1)**5)**52 is sin(1)**260);
            # exp(c*log(u)) of a constant u is u**c, a power of degree c in u (its ** tan(-52) combines further)
            return Facts(value, None, 1, inside, degree, calls)
        return Facts(None, None, terms, inside, degree, calls)

    def exact_call(self, node: ast.Call, name: str, powers: list[Facts], depth: int) -> Fraction | None:
        """The exact rational SymPy turns a constant call into, when it does: exp(c*log(u)) is u**c, and
        log(exp(v)) is v (then ``((10**15 - 1))**-exp(-log(10**15))`` meets the root-index cap instead of
        sending SymPy after a root of index 10**15)."""
        argument = node.args[0]
        if name == "exp" and len(powers) == 1 and len(chain(_strip_signs(argument)[0], SUMS)) == 1:
            return powers[0].exact
        inner = _strip_signs(argument)[0] if name == "log" else None
        if isinstance(inner, ast.Call) and getattr(inner.func, "id", "") == "exp" and inner is argument:
            return self.check(inner.args[0], depth + 2).exact if len(inner.args) == 1 else None
        return None

    def exp_log_powers(self, argument: ast.AST, depth: int) -> list[tuple[ast.AST, Facts, Facts]]:
        """The summands c*log(u) (c constant) of an exp's argument, each as (summand, u, c)."""
        found = []
        whole, whole_sign = _strip_signs(argument)
        for op, summand, _ in chain(whole, SUMS):
            term, sign = _strip_signs(summand)
            sign *= whole_sign * (-1 if op is ast.Sub else 1)
            logs, value, exact = [], float(sign), Fraction(sign)
            for factor_op, factor, _ in chain(term, PRODUCTS):
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
                    found.append((summand, u, Facts(value, exact, 1)))
        return found

    def exactly(self, node: ast.AST, value: Fraction) -> Fraction:
        """An exact rational constant, refused when its numerator or denominator is too long to keep."""
        if max(value.numerator.bit_length(), value.denominator.bit_length()) > MAX_BITS:
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
