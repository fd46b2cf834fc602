"""An expression as running text prints it: R φ̇ sin(θ), m₂ l₁ l₂ cos(θ₁ − θ₂), never ** or *.

The one writer of a formula inside a sentence (a tutor's hint, a unit's reason, a mistake's name): each
product's constants first, then its coordinates, each name in its Unicode form (app/engine/display/names.py).
"""

from __future__ import annotations

import re
from collections.abc import Iterable

import sympy as sp

from app.engine.display.names import unicode

_SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_FUNCTIONS = frozenset(
    {"sin", "cos", "tan", "arccos", "arcsin", "arctan", "exp", "log", "sqrt", "Abs", "sinh", "cosh", "tanh", "pi"}
)


_GREEK = frozenset(
    "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau upsilon phi chi psi "
    "omega".split()
)


def _rank(factor: sp.Expr, coordinates: frozenset[sp.Symbol] = frozenset()) -> tuple[int, int, str]:
    """A factor's place in a product as a textbook writes it: numbers, masses, sums of masses, other constants
    (Latin letters before Greek), rates, then functions: m₂ l₁ l₂ θ̇₁ θ̇₂ cos(θ₁ − θ₂), 2 g α, m g R cos θ,
    (M + m) Ẋ²/2. Where the coordinates are known, they follow the constants (κ x₂, not x₂ κ)."""
    if factor.is_number:
        return (0, 0, "")
    if factor.is_Add:
        return (1, 1, sp.sstr(factor))
    base = factor.base if factor.is_Pow else factor
    if isinstance(base, sp.Symbol):
        name = base.name
        if name.endswith("_dot") or name.endswith("_ddot"):
            return (3, 0, name.lower())
        stem = name.rstrip("0123456789_").lower()
        if stem == "m":
            return (1, 0, name.lower())
        if base in coordinates:
            return (2, 2, name.lower())
        # the time last, after its rate: an angle that grows with time is ω t, never t ω (cos(ω t))
        if name == "t":
            return (2, 3, name)
        return (2, int(stem in _GREEK), name.lower())
    return (4, 0, sp.sstr(factor))


def _arranged(expr: sp.Basic, coordinates: frozenset[sp.Symbol] = frozenset()) -> sp.Basic:
    """The same expression, unevaluated, with each product's factors in ``_rank`` order and each sum's positive
    terms first (x₂ − x₁ − l₀ rather than −l₀ − x₁ + x₂)."""
    if not isinstance(expr, sp.Basic) or expr.is_Atom:
        return expr
    args = [_arranged(a, coordinates) for a in expr.args]
    if expr.is_Mul:
        return sp.Mul(*sorted(args, key=lambda a: _rank(a, coordinates)), evaluate=False)
    if expr.is_Add:
        positive = [a for a in args if not a.could_extract_minus_sign()]
        return sp.Add(*positive, *(a for a in args if a.could_extract_minus_sign()), evaluate=False)
    try:
        return expr.func(*args, evaluate=False)
    except TypeError:  # a class that takes no evaluate flag
        return expr.func(*args)


def spoken(expr: sp.Expr, coordinates: Iterable[sp.Symbol] = (), factored: bool = True) -> str:
    """An expression as running text prints it: R φ̇ sin(θ), m₂ l₁ l₂ cos(θ₁ − θ₂) (never ** or *); with the
    ``coordinates`` named, each product's coordinates after its constants (κ x₂/m). A student's own sum is quoted
    ``factored=False``, term by term as it was written (m R² θ̈ + m g R θ̇ sin(θ), never m (R θ̈ + g θ̇ sin(θ)) R)."""
    # a sign pulled out of a sum: −g l₁ (m₁ + m₂), not g l₁ (−m₁ − m₂)
    shown = sp.factor_terms(expr) if isinstance(expr, sp.Expr) and factored else expr
    try:
        text = sp.sstr(_arranged(shown, frozenset(coordinates)), order="none")
    except (TypeError, ValueError, AttributeError):  # an expression the rearranging cannot rebuild: SymPy's order
        text = sp.sstr(shown)
    # sin(θ)**2 as sin²(θ)
    text = re.sub(
        r"\b(sin|cos|tan)(\([^()]*\))\*\*(\d+)",
        lambda m: m.group(1) + m.group(3).translate(_SUPERSCRIPTS) + m.group(2),
        text,
    )
    text = re.sub(r"\*\*(\d+)", lambda m: m.group(1).translate(_SUPERSCRIPTS), text)
    text = re.sub(r"\*\*\(?([^()\s*]+)\)?", r"^\1", text)
    text = text.replace("*", " ").replace(" - ", " − ").replace("-", "−")
    # arccos, not acos: an inverse function as a textbook names it
    text = re.sub(r"\ba(cos|sin|tan)\(", r"arc\1(", text)
    return _IDENT.sub(lambda m: m.group(0) if m.group(0) in _FUNCTIONS else unicode(m.group(0)), text)
