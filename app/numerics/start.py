"""Why a system's equations of motion cannot be evaluated at its initial state, in words that name the cause.

The simulation refuses a start where the right-hand side is not finite.  Saying only "a division by
zero, move it slightly" blamed the coordinates for every cause; this module finds the actual one, in
the order a reader would look:

1. the system as typed (T, U, L, the forces), evaluated node by node from the leaves: the smallest
   subexpression that is outside its function's domain (``acos(x)`` at x = 2), overflows a double
   (``exp(exp(exp(x)))`` at x = 5) or divides by zero (``1/r`` at r = 0), with the values it saw;
2. the mass matrix M (the coefficients of the accelerations): singular there, because a parameter is
   0 (a zero mass) or because of where the coordinates are (a radius of 0, a pole of a sphere);
3. the same walk over the forcing terms and the accelerations, which hold the derivatives of (1);
4. else the old, general sentence.

It runs only on that refusal path, on the expressions the engine derived (SymPy objects, walked with
floats; only a function without a float twin here is evaluated by SymPy, once, on numbers).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping

import numpy as np
import sympy as sp
from sympy.printing.str import StrPrinter

from app.engine.derivation.derive import Derivation
from app.engine.display.names import unicode

DOUBLE_MAX = "1.8·10³⁰⁸"
GENERAL = (
    "the equations of motion cannot be evaluated at this initial state (the coordinates are singular "
    "there, e.g. a radius of 0 or a pole of the sphere); move it slightly"
)


class _Undefined(ArithmeticError):
    """A node whose value is not a finite real number although its arguments are."""

    def __init__(self, node: sp.Basic, why: str, detail: str = ""):
        super().__init__(why)
        self.node, self.why, self.detail = node, why, detail


# the float twins of the functions the parser allows (app/engine/parser/parse.py), with the domain each has
_FUNCTIONS: dict[str, Callable[..., float]] = {
    "sin": math.sin, "cos": math.cos, "tan": math.tan, "exp": math.exp, "log": math.log,
    "asin": math.asin, "acos": math.acos, "atan": math.atan, "sinh": math.sinh, "cosh": math.cosh,
    "tanh": math.tanh, "asinh": math.asinh, "acosh": math.acosh, "atanh": math.atanh, "Abs": abs,
    "atan2": math.atan2, "sec": lambda a: 1 / math.cos(a), "csc": lambda a: 1 / math.sin(a),
    "cot": lambda a: 1 / math.tan(a), "sign": lambda a: float(np.sign(a)),
}  # fmt: skip
_DOMAINS = {
    "asin": "arguments in [−1, 1]", "acos": "arguments in [−1, 1]", "log": "positive arguments",
    "acosh": "arguments ≥ 1", "atanh": "arguments in (−1, 1)",
}  # fmt: skip


class _Printer(StrPrinter):
    """Expressions as a reader writes them in a sentence: x², θ̇, m·g, sqrt(1 − x²)."""

    def _print_Symbol(self, expr: sp.Symbol) -> str:
        return unicode(expr.name)


_SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def written(expr: sp.Basic, limit: int = 80) -> str:
    """An expression for a sentence: whole powers as superscripts (x²), other powers with ^, products with ·."""
    text = _Printer().doprint(expr)
    text = re.sub(r"\*\*(\d+)", lambda m: m.group(1).translate(_SUPERSCRIPTS), text)
    text = text.replace("**", "^").replace("*", "·").replace(" - ", " − ")
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _number(x: float) -> str:
    return f"{x:.6g}".replace("-", "−")


def _pow(base: float, exponent: float, node: sp.Basic) -> float:
    if base == 0 and exponent < 0:
        raise _Undefined(node, "division")
    value = base**exponent
    if isinstance(value, complex):
        what = "square root" if exponent == 0.5 or exponent == -0.5 else "fractional power"
        raise _Undefined(node, "domain", f"a {what} of the negative number {_number(base)}")
    return value


def value_of(node: sp.Basic, values: Mapping[sp.Symbol, float]) -> float:
    """The float value of ``node`` at ``values``, or _Undefined at the smallest node that has none."""
    if node.is_Symbol:
        return values[node]
    if node.is_number and not node.args:
        return float(node)
    args = [value_of(a, values) for a in node.args]
    try:
        if node.is_Add:
            result = math.fsum(args)
        elif node.is_Mul:
            result = math.prod(args)
        elif node.is_Pow:
            result = _pow(args[0], args[1], node)
        elif isinstance(node, sp.Function) and type(node).__name__ in _FUNCTIONS:
            result = _FUNCTIONS[type(node).__name__](*args)
        else:  # no float twin here: SymPy evaluates the node on the numbers
            evaluated = complex(node.func(*(sp.Float(a) for a in args)).evalf())
            if evaluated.imag:
                raise _Undefined(node, "domain")
            result = evaluated.real
    except ZeroDivisionError:
        raise _Undefined(node, "division") from None
    except OverflowError:
        raise _Undefined(node, "overflow") from None
    except (ValueError, TypeError):
        name = type(node).__name__
        detail = f"{name} takes {_DOMAINS[name]}, not {_number(args[0])}" if name in _DOMAINS and args else ""
        raise _Undefined(node, "domain", detail) from None
    if math.isinf(result):
        raise _Undefined(node, "overflow")
    if math.isnan(result):
        raise _Undefined(node, "domain")
    return float(result)


def _at(node: sp.Basic, values: Mapping[sp.Symbol, float]) -> str:
    used = sorted((s for s in node.free_symbols if s in values), key=lambda s: s.name)
    return ", ".join(f"{unicode(s.name)} = {_number(values[s])}" for s in used) or "every value"


def _sentence(found: _Undefined, values: Mapping[sp.Symbol, float], where: str) -> str:
    expr, at = written(found.node), _at(found.node, values)
    if found.why == "overflow":
        return (
            f"{where}: {expr} overflows at {at} (it exceeds {DOUBLE_MAX}, the largest number a double holds); "
            "start where it is smaller, or write the system in smaller units"
        )
    if found.why == "division":
        return f"{where}: {expr} divides by zero at {at}; start elsewhere or change the parameters"
    detail = f" ({found.detail})" if found.detail else ""
    return f"{where}: {expr} is not defined at {at}{detail}; start inside its domain"


def _first_undefined(exprs: Iterable[sp.Basic], values: Mapping[sp.Symbol, float]) -> _Undefined | None:
    for expr in exprs:
        try:
            value_of(sp.sympify(expr), values)
        except _Undefined as found:
            return found
        except KeyError:  # a symbol without a value here (none is expected): this expression says nothing
            continue
    return None


def _singular(matrix: np.ndarray) -> bool:
    """M has no inverse to double precision: a zero row, or a smallest singular value ~0 relative to the largest."""
    if not np.all(np.isfinite(matrix)):
        return False
    s = np.linalg.svd(matrix, compute_uv=False)
    return bool(s[0] == 0 or s[-1] <= 1e-12 * s[0])


def why_not_at_start(d: Derivation, y0: np.ndarray, k: np.ndarray) -> str:
    """The cause, in words, of an initial state at which the equations of motion have no finite value."""
    table, mech, eqs = d.table, d.mechanics, d.equations
    values: dict[sp.Symbol, float] = {table.t: 0.0}
    values |= dict(zip((*table.q, *table.qd), map(float, y0), strict=True))
    values |= dict(zip(table.params, map(float, k), strict=True))
    typed = [e for e in (mech.T, mech.U) if e is not None] if mech.T is not None else [mech.L]
    found = _first_undefined([*typed, *mech.Q], values)
    if found is not None:
        return _sentence(found, values, "the system cannot start at this initial state")
    try:
        mass = np.array([[value_of(e, values) for e in row] for row in eqs.mass_matrix.tolist()], dtype=float)
    except _Undefined as undefined:
        return _sentence(undefined, values, "the mass matrix cannot be evaluated at this initial state")
    except KeyError:
        mass = np.full((1, 1), math.nan)
    if _singular(mass):
        used = eqs.mass_matrix.free_symbols
        zero = [p for p in table.params if p in used and values[p] == 0]
        if zero:
            names = ", ".join(f"{unicode(p.name)} = 0" for p in zero)
            return (
                f"the mass matrix is singular at this initial state because of {names}: a zero mass (or inertia) "
                "leaves an acceleration undetermined; give it a positive value"
            )
        moving = sorted((q for q in table.q if q in used), key=lambda s: s.name)
        at = ", ".join(f"{unicode(q.name)} = {_number(values[q])}" for q in moving)
        return (
            f"the mass matrix is singular at this initial state{f' ({at})' if at else ''}: the kinetic energy "
            "does not involve every velocity there (e.g. a radius of 0 or a pole of the sphere); move it slightly"
        )
    found = _first_undefined([*eqs.forcing, *eqs.accelerations], values)
    if found is not None:
        return _sentence(found, values, "the equations of motion cannot be evaluated at this initial state")
    return GENERAL
