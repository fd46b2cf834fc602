"""Dimensions of parameters, coordinates and answers: the one home of units (kg, m, s) in the engine.

A parameter's dimension comes from the unit it declares (``parse_unit``: "N/m" is kg s⁻²).  A
coordinate that appears inside a sine or cosine is an angle (dimensionless); another one's follows
from the kinetic energy, an energy: ½ M_qq q̇² has kg m² s⁻², so [q]² = kg m² / [M_qq] (solved in
passes, since M_θθ = m r² needs r first).  A rate is [q]/s, an acceleration [q]/s².

``mismatch`` walks an answer: every term of a sum must have one dimension, the argument of a
function none; the first offence is returned in words ("m + g adds a mass to an acceleration").
Nothing is decided where a name's dimension is unknown (no unit declared): a missing verdict is
honest, a wrong one is not.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

import sympy as sp

from app.engine.display.names import unicode
from app.engine.display.spoken import spoken

if TYPE_CHECKING:
    from app.engine.derivation.derive import Derivation

Dims = dict[str, Fraction]  # exponents of kg, m, s and A (the ampere, for charges and fields)

_BASE: dict[str, Dims] = {
    "kg": {"kg": Fraction(1)},
    "m": {"m": Fraction(1)},
    "s": {"s": Fraction(1)},
    "N": {"kg": Fraction(1), "m": Fraction(1), "s": Fraction(-2)},
    "J": {"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-2)},
    "W": {"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-3)},
    "Pa": {"kg": Fraction(1), "m": Fraction(-1), "s": Fraction(-2)},
    "Hz": {"s": Fraction(-1)},
    # electromagnetic units through the ampere: a charge q in C and a field B in T make qB a mass rate (kg/s)
    "A": {"A": Fraction(1)},
    "C": {"A": Fraction(1), "s": Fraction(1)},
    "T": {"kg": Fraction(1), "A": Fraction(-1), "s": Fraction(-2)},
    "V": {"kg": Fraction(1), "m": Fraction(2), "A": Fraction(-1), "s": Fraction(-3)},
    "rad": {},
    "1": {},
}
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_FACTOR = re.compile(r"^([A-Za-z]+|1)(?:\^|\*\*)?(-?\d+)?$")
MAX_NODES = 400  # an answer longer than this is not walked (its dimensions say nothing new)

ENERGY: Dims = {"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-2)}

# the words for kg/s², and what a system without a spring is told instead (app.engine.tutor.mistakes.without_springs)
STIFFNESS_WORDS = "a spring constant (kg/s²)"
STIFFNESS_PLAIN = "a quantity in kg/s²"

# quantities a student recognises, by dimension
_WORDS = [
    ({}, "a pure number"),
    ({"kg": Fraction(1)}, "a mass"),
    ({"m": Fraction(1)}, "a length"),
    ({"s": Fraction(1)}, "a time"),
    ({"m": Fraction(1), "s": Fraction(-2)}, "an acceleration"),
    ({"m": Fraction(1), "s": Fraction(-1)}, "a speed"),
    ({"s": Fraction(-1)}, "a rate (1/s)"),
    ({"s": Fraction(-2)}, "a squared rate (1/s²)"),
    ({"s": Fraction(2)}, "a squared time (s²)"),
    ({"m": Fraction(2), "s": Fraction(-2)}, "a squared speed"),
    (ENERGY, "an energy"),
    ({"kg": Fraction(1), "m": Fraction(1), "s": Fraction(-2)}, "a force"),
    ({"kg": Fraction(1), "s": Fraction(-2)}, STIFFNESS_WORDS),
    ({"kg": Fraction(1), "m": Fraction(1), "s": Fraction(-1)}, "a momentum"),
    ({"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-1)}, "an angular momentum"),
    ({"kg": Fraction(1), "m": Fraction(2)}, "a moment of inertia"),
    ({"m": Fraction(-1)}, "an inverse length (1/m)"),
    ({"m": Fraction(2)}, "an area"),
    ({"kg": Fraction(1), "s": Fraction(-1)}, "a drag coefficient (kg/s)"),
    ({"A": Fraction(1), "s": Fraction(1)}, "a charge"),
    ({"kg": Fraction(1), "A": Fraction(-1), "s": Fraction(-2)}, "a magnetic field"),
    ({"kg": Fraction(1), "m": Fraction(2), "A": Fraction(-1), "s": Fraction(-3)}, "an electric potential"),
]
_SUPER = str.maketrans("-0123456789/", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹ᐟ")

# Words for a dimension that one step names its own way, before _WORDS: (dimension, words) pairs
Own = tuple[tuple[Dims, str], ...]

# a lone base unit spelled out: "(m)" beside a mass m reads as "multiply by the mass"
_SPELLED = {"m": "metres", "kg": "kilograms", "s": "seconds"}


def add_dims(a: Dims, b: Dims, times: Fraction = Fraction(1)) -> Dims:
    out = dict(a)
    for k, v in b.items():
        out[k] = out.get(k, Fraction(0)) + times * v
    return {k: v for k, v in out.items() if v}


def parse_unit(text: str) -> Dims | None:
    """ "N/m" -> kg s⁻²; "kg·m²" -> kg m²; "" or anything not understood -> None."""
    text = text.strip().translate(_SUPERSCRIPTS).replace("·", "*").replace("⋅", "*").replace(" ", "*")
    if not text:
        return None
    parts = text.split("/")
    out: Dims = {}
    for i, part in enumerate(parts):
        for factor in filter(None, part.replace("**", "^").split("*")):
            m = _FACTOR.match(factor)
            if not m or m.group(1) not in _BASE:
                return None
            power = Fraction(int(m.group(2) or 1))
            out = add_dims(out, _BASE[m.group(1)], power if i == 0 else -power)
    return out


_ORDER = ("kg", "m", "A", "s")


def unit_text(d: Dims) -> str:
    """kg·m²/s² for an energy; 1 for a pure number."""
    if not d:
        return "1"
    top = [(k, v) for k in _ORDER if (v := d.get(k, Fraction(0))) > 0]
    bottom = [(k, -v) for k in _ORDER if (v := d.get(k, Fraction(0))) < 0]

    def show(parts: list[tuple[str, Fraction]]) -> str:
        return "·".join(k + (str(v).translate(_SUPER) if v != 1 else "") for k, v in parts)

    # a denominator of several units in brackets, so that none reads as a factor of the top
    # ("1/m·s²" for 1/(m·s²))
    under = show(bottom) if len(bottom) == 1 else f"({show(bottom)})"
    return (show(top) or "1") + (f"/{under}" if bottom else "")


# the units a number is written with where the SI names one (1 J, 2 N, 0.5 m), else its base units
_NAMED_UNITS = ("J", "N", "W", "m", "kg", "s")


def unit_name(d: Dims) -> str:
    """The unit a number of dimension ``d`` is written with: J for an energy, N for a force, m for a length, else
    the base units (kg·m/s); "" for a pure number."""
    if not d:
        return ""
    return next((u for u in _NAMED_UNITS if _BASE[u] == d), unit_text(d))


def unit_latex(d: Dims) -> str:
    """The unit of a number in a formula, upright after a thin space, with negative powers: \\,\\mathrm{kg\\,m^{2}\\,s^{-1}}."""
    parts = [k + (f"^{{{v}}}" if v != 1 else "") for k in _ORDER if (v := d.get(k, Fraction(0))) != 0]
    return r"\,\mathrm{" + r"\,".join(parts) + "}" if parts else ""


# what a parameter is by the unit it declares, where its dimension alone cannot tell (rad and 1/s are both s⁻¹
# apart from the radian), before the words by dimension
_KIND_BY_UNIT = {"rad": "an angle", "rad/s": "an angular velocity", "1/s": "a rate", "s": "a time",
                 "N/m": "a spring constant", "kg/s": "a drag coefficient", "1": "a pure number"}  # fmt: skip


def kind_of_unit(unit: str) -> str | None:
    """What a quantity declared in ``unit`` is, in words ("a mass", "an angle", "a magnetic field"); None when
    the unit is not understood or names no quantity a student recognises."""
    text = unit.strip().replace("^2", "²").replace("**2", "²")
    if text in _KIND_BY_UNIT:
        return _KIND_BY_UNIT[text]
    dims = parse_unit(unit)
    if dims is None:
        return None
    words = quantity(dims)
    return None if words.startswith("a quantity in") else words.split(" (")[0]


def quantity(d: Dims, own: Own = ()) -> str:
    """A dimension in words: "a mass", or "a quantity in kg·m/s³"; ``own``: the step's own words first."""
    return next((w for dims, w in (*own, *_WORDS) if dims == d), f"a quantity in {unit_text(d)}")


def _term(d: Dims, own: Own) -> str:
    """A term's dimension in words where the term itself follows in brackets: a step's own words without their unit
    ("a torque (m R² θ̈)", never "a torque (N·m) (m R² θ̈)")."""
    words = quantity(d, own)
    return words.split(" (")[0] if any(dims == d for dims, _ in own) else words


def unit_words(d: Dims) -> str:
    """A unit as the tutor's words print it: a lone base unit spelled out (metres, never a bare m that reads as
    the mass), any other as kg·m/s²."""
    text = unit_text(d)
    return _SPELLED.get(text, text)


def equation_words(coordinate: str, coordinate_dims: Dims | None) -> Own:
    """What a term of the equation of motion of ``coordinate`` is called.  Each term of
    d/dt(∂L/∂q̇) − ∂L/∂q has the units of L over those of q: for an angle (no units) that is a torque, N·m,
    never "an energy"; for a length a force; else "a term of the q equation"."""
    if coordinate_dims is None:
        return ()
    # [term] = [L] / [q]
    term = add_dims(ENERGY, coordinate_dims, Fraction(-1))
    if not coordinate_dims:
        words = "a torque (N·m)"
    elif term == _BASE["N"]:
        words = "a force"
    else:
        words = f"a term of the {unicode(coordinate)} equation ({unit_text(term)})"
    # an energy that is not a term's dimension is named by its units alone in an equation of motion
    return ((term, words),) + (() if term == ENERGY else ((ENERGY, f"a quantity in {unit_text(ENERGY)}"),))


@dataclass(frozen=True)
class Offence:
    """Where an answer's dimensions break: the sum (or function argument) and what it says."""

    piece: sp.Expr
    words: str


class _Mismatch(Exception):
    def __init__(self, offence: Offence):
        self.offence = offence


def _dims(expr: sp.Expr, known: Mapping[sp.Symbol, Dims], own: Own = ()) -> Dims | None:
    if expr.is_Number or expr is sp.pi or expr is sp.E:
        return {}
    if expr.is_Symbol:
        return known.get(expr)
    if expr.is_Add:
        # a bare number beside other terms takes their units (a constant of U, written without its unit)
        found = [(a, _dims(a, known, own)) for a in expr.args if not a.is_Number]
        told = [(a, d) for a, d in found if d is not None]
        for a, d in told[1:]:
            if d != told[0][1]:
                first = told[0]
                # a short sum is quoted (m + g) term by term, as the student wrote it; a long one is the
                # student's own, shown under the words
                lead = spoken(expr, factored=False) if len(expr.args) <= 2 else "Your sum"
                words = (
                    f"{lead} adds {_term(first[1], own)} ({spoken(first[0])}) to {_term(d, own)} "
                    f"({spoken(a)}), and the terms of a sum must have the same units."
                )
                meant = _meant(a, d, add_dims(first[1], d, Fraction(-1)), expr, known)
                raise _Mismatch(Offence(expr, words + (f" {meant}" if meant else "")))
        return told[0][1] if told and len(told) == len(found) else None
    if expr.is_Mul:
        out: Dims = {}
        for a in expr.args:
            factor = _dims(a, known, own)
            if factor is None:
                return None
            out = add_dims(out, factor)
        return out
    if expr.is_Pow:
        base = _dims(expr.base, known, own)
        if base is None:
            return None
        if not expr.exp.is_Rational:
            exponent = _dims(expr.exp, known, own)
            if exponent:
                raise _Mismatch(Offence(expr, f"the power {spoken(expr.exp)} of {spoken(expr)} has units"))
            return None if base else {}
        return {k: v * Fraction(int(expr.exp.p), int(expr.exp.q)) for k, v in base.items()}
    if isinstance(expr, sp.Function):
        if isinstance(expr, sp.Abs):
            return _dims(expr.args[0], known, own)
        for a in expr.args:
            inside = _dims(a, known, own)
            if inside:
                raise _Mismatch(
                    Offence(expr, f"{spoken(expr)} takes {quantity(inside, own)} ({spoken(a)}) as its argument, which must "
                            "be a pure number (an angle)")
                )  # fmt: skip
        return {}
    return None


def dimension(expr: sp.Expr, known: Mapping[sp.Symbol, Dims]) -> Dims | None:
    """The dimension of a consistent expression (None when unknown or inconsistent)."""
    try:
        return _dims(expr, known)
    except _Mismatch:
        return None


def mismatch(
    expr: sp.Expr,
    known: Mapping[sp.Symbol, Dims],
    want: Dims | None,
    what: str,
    own: Own = (),
    examples: Iterable[sp.Symbol] = (),
) -> Offence | None:
    """The first place the answer's dimensions break, or where its whole has another dimension than
    ``want`` (the truth's; None: any), in words; None when all is consistent or cannot be told.  A bare number
    is looked for in every sum inside the answer too.  ``own``: the step's words for a dimension
    (``equation_words``); ``examples``: the problem's parameters, one of which names a missing factor ("a length
    such as R")."""
    if sp.count_ops(expr) > MAX_NODES:
        return None
    # a bare number beside terms with units, in the whole or in any sum inside it: m g (z + 3) adds 3 to a
    # length as surely as m g z + 3 adds it to an energy (it read as "another zero of U")
    bare = next((b for a in sp.preorder_traversal(expr) if (b := _bare_number(a, known, own)) is not None), None)
    if bare is not None:
        return bare
    try:
        got = _dims(expr, known, own)
    except _Mismatch as e:
        return e.offence
    if got is None or want is None or got == want:
        return None
    # the factor that would make it right, in words: a mass missing, a length too many; or upside down
    missing = add_dims(want, got, Fraction(-1))
    extra = add_dims(got, want, Fraction(-1))
    inverted = bool(want) and got == {k: -v for k, v in want.items()}
    # a factor too many is pointed at by the name in the answer that carries exactly its units (g for m/s²)
    carriers = sorted(s.name for s in expr.free_symbols if isinstance(s, sp.Symbol) and extra and known.get(s) == extra)
    factor = (
        "It is upside down: numerator and denominator are swapped"
        if inverted
        else _missing_factor(missing, known, own, examples)
        # (a missing factor a student can name, a force, is said so even where its unit has a negative power)
        if all(v > 0 for v in missing.values()) or not quantity(missing, own).startswith("a quantity in")
        else f"It has a factor {unicode(carriers[0])} ({unit_words(extra)}) too many"
        if len(carriers) == 1
        else f"It has a factor with the units of {described(extra, own)} too many"
        if all(v > 0 for v in extra.values())
        else f"It needs a factor in {unit_text(missing)}"
    )
    # short sentences, each with its full stop: what it is, what it should be, what would make it so
    return Offence(expr, f"Your {what} is {described(got, own)}, but it should be {described(want, own)}. {factor}.")


def _missing_factor(missing: Dims, known: Mapping[sp.Symbol, Dims], own: Own, examples: Iterable[sp.Symbol]) -> str:
    """A missing factor in words that never read as one of the problem's symbols ("a factor of length
    (m)" read as "multiply by the mass m"): its units spelled out, and a parameter of those units where there is
    one ("a length such as R")."""
    kind = quantity(missing, own)
    named = sorted(s.name for s in examples if known.get(s) == missing)
    said = (
        f"A factor in {unit_text(missing)} is missing"
        if kind.startswith("a quantity in")
        else f"A factor with the units of {described(missing, own)} is missing"
    )
    if not named:
        return said
    like = "one" if kind.startswith("a quantity in") else kind.split(" (")[0]
    return f"{said}: {like} such as {unicode(named[0])}"


def _bare_number(expr: sp.Expr, known: Mapping[sp.Symbol, Dims], own: Own = ()) -> Offence | None:
    """A pure number added to terms that have units (h + 7): the number has none.  (Inside a sum that is itself
    dimensionless, 1 − cos θ, a number is right; nested in a length, (y₁ + y₂ + 3), it reads as metres.)"""
    if not expr.is_Add:
        return None
    numbers = [a for a in expr.args if a.is_Number and a != 0]
    if len(numbers) != 1:
        return None
    rest = expr - numbers[0]
    got = dimension(rest, known)
    if not got:
        return None  # unknown, or a pure number beside a pure number
    n = numbers[0]
    words = f"{spoken(n)} has no unit and cannot be added to {quantity(got, own)}"
    # the rest of the sum short of a factor that makes it a pure number, as a number beside it must be
    meant = _meant(rest, got, {k: -v for k, v in got.items()}, expr, known) if rest.is_Mul else None
    return Offence(expr, f"{words}. {meant}" if meant else words)


def _meant(term: sp.Expr, got: Dims, missing: Dims, whole: sp.Expr, known: Mapping[sp.Symbol, Dims]) -> str | None:
    """What a term of a sum whose units disagree with the rest was likely meant to be: the term times
    one name of the sum, once or squared, whose units are exactly the ones it lacks, where that makes the term a
    square (α R² for α² R², a length beside 1; R² α² for R² α² ż², the square of the helix bead's x–y speed R α ż).
    None where no one name does that."""
    for s in sorted(whole.free_symbols, key=lambda x: (not x.name.endswith("_dot"), x.name)):
        dims = known.get(s)
        if not dims:
            continue
        for power in (1, 2):
            if add_dims({}, dims, Fraction(power)) != missing:
                continue
            meant = term * s**power
            powers = meant.as_powers_dict()
            if any(not (isinstance(e, sp.Integer) and e % 2 == 0) for b, e in powers.items() if not b.is_Number):
                continue  # not a square: no one likely meaning
            # the product whose square it is, a positive name at a time (R α ż, never |R| |α| |ż|)
            root = sp.sqrt(meant.as_coeff_Mul()[0]) * sp.Mul(*(b ** (e // 2) for b, e in powers.items() if not b.is_Number))
            if s.name.endswith("_dot"):
                # a velocity factor missing: a term of T is a mass times a squared speed
                return (f"A velocity factor is missing from {spoken(term)}: did you mean {spoken(meant)}, the "
                        f"square of the speed {spoken(root)}?")  # fmt: skip
            return (f"{spoken(s)} is in {unit_text(dims)}, so {spoken(term)} is {quantity(got)}: did you mean "
                    f"{spoken(meant)}?")  # fmt: skip
    return None


def number_beside_units(expr: sp.Expr, known: Mapping[sp.Symbol, Dims]) -> bool:
    """Whether any sum inside expr adds a pure number to terms with units ((1 − R) m R θ̇): a form a reader could
    not write, though the whole may be consistent (the number reads as a constant of the same units)."""
    for a in sp.preorder_traversal(expr):
        if isinstance(a, sp.Add) and _bare_number(a, known) is not None:
            return True
    return False


def described(d: Dims, own: Own = ()) -> str:
    """A dimension in words with its unit, once: "a mass (kilograms)", "a squared rate (1/s²)", "a quantity in s⁴"
    (a lone base unit spelled out, ``unit_words``)."""
    words = quantity(d, own)
    return words if "(" in words or words.startswith("a quantity in") or not d else f"{words} ({unit_words(d)})"


def known_dimensions(
    params: Mapping[sp.Symbol, str],
    q: tuple[sp.Symbol, ...],
    qd: tuple[sp.Symbol, ...],
    qdd: tuple[sp.Symbol, ...],
    lagrangian: sp.Expr,
    t: sp.Symbol,
) -> dict[sp.Symbol, Dims]:
    """Every name's dimension that can be told: parameters by their units, coordinates as above."""
    known: dict[sp.Symbol, Dims] = {s: d for s, u in params.items() if (d := parse_unit(u)) is not None}
    known[t] = {"s": Fraction(1)}
    trig = [a for f in lagrangian.atoms(sp.sin, sp.cos, sp.tan) for a in f.args]
    for c in q:
        if any(a.has(c) for a in trig):
            known[c] = {}  # an angle
    # ½ M_qq q̇² is an energy: [q]² = kg m² / [M_qq]; each pass may resolve what another coordinate needs
    for _ in range(len(q)):
        for c, v in zip(q, qd, strict=True):
            if c in known:
                continue
            # at rest when ∂²L/∂q̇² depends on the velocities (mγ³ of a relativistic L is m there), whose
            # dimensions are not known yet
            entry = sp.diff(lagrangian, v, 2).xreplace(dict.fromkeys(qd, sp.Integer(0)))
            rates = {**known, **{x: {} for x in qd}}
            d = dimension(entry, rates) if entry != 0 else None
            # every term of M_qq has its dimension, so its part free of q tells it (m (1 + 4α²ρ²) at ρ = 0 is m)
            if d is None and (free := entry.xreplace({c: 0})) != 0:
                d = dimension(free, rates)
            if d is None:
                continue
            square = add_dims({"kg": Fraction(1), "m": Fraction(2)}, d, Fraction(-1))
            known[c] = {k: v2 / 2 for k, v2 in square.items()}
    for c, v, a in zip(q, qd, qdd, strict=True):
        if c in known:
            known[v] = add_dims(known[c], {"s": Fraction(-1)})
            known[a] = add_dims(known[c], {"s": Fraction(-2)})
    return known


def system_dimensions(d: Derivation) -> dict[sp.Symbol, Dims]:
    """Every name's dimension that the system's declared units tell (parameters, coordinates, rates)."""
    t = d.table
    by_name = {p.name: p.unit for p in d.system.parameters}
    units = {s: by_name.get(s.name, "") for s in t.params}
    return known_dimensions(units, t.q, t.qd, t.qdd, d.mechanics.L, t.t)
