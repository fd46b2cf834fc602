"""Slips read from the answer itself, when no mistake of the step's catalogue matches.

The catalogue (app/engine/tutor/mistakes.py, mistake_pieces.py) builds each wrong answer from the derivation
and compares; some common slips cannot be built that way, because what goes wrong depends on what the
student wrote:

* **a square left out**: a velocity component a·q̇ enters v² as a²q̇², and students write a instead of
  a² (the helix's m(1 + Rα)ż²/2 for m(1 + R²α²)ż²/2, the parabola's 1 + 2αρ for 1 + 4α²ρ²).  Each
  product or symbol of the answer that holds no velocity is squared in turn; the one whose square
  turns the answer into the engine's is named;
* **an equation linearised**: the small-angle equation (sin θ ≈ θ, cos ≈ 1, products of small
  quantities dropped) where the full one is asked for.  The engine's equation is expanded to first
  order about the state where every coordinate, velocity and acceleration is zero (when that state
  is an equilibrium); an answer equal to it, or to a constant multiple of it, is named;
* **T, U, L or h for small displacements**: the same expanded to second order (cos θ ≈ 1 − θ²/2);
* **one part of an equation off by a factor**, every other part right at some scale;
* **a solved acceleration or ω²** read against the truth: the sign of the whole, a factor (or the number)
  upside down or squared, one term's factor 2, another coordinate's term left out, a number off, then
  numerator and denominator each on its own.

All compare values at the checker's sample points (app/engine/tutor/compare.py), within a count of work.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from app.engine.display.spoken import spoken
from app.engine.display.textbook import unicode_text
from app.engine.document.notation import MASS_INERTIA, Inertia
from app.engine.parser.symbols import TIME
from app.engine.tutor.compare import (
    Groups,
    Values,
    differ_by_constant,
    differ_by_factor,
    equal,
    factor_is_constant,
    usable,
    values,
)
from app.engine.tutor.diagnose import MIN_POINTS, part_scales, rate_parts  # (MIN_POINTS: one home with the catalogue)
from app.engine.tutor.mistake_families import Correct, monomial_words, said

MAX_CANDIDATES = 24  # products and symbols of an answer tried as the one left unsquared

SQUARE_HINT = (
    "You wrote {part} where T needs its square {square}: a velocity component such as {part}·{rate} enters "
    "v² squared, as {square}·{rate}², so square each component before adding them."
)
LINEAR_HINT = (
    "This is the equation linearised for small displacements (sin θ ≈ θ, cos θ ≈ 1, products of small "
    "quantities such as θ̇² dropped): an approximation. The step asks for the full equation of motion: keep "
    "the sines, cosines and velocity-squared terms as d/dt(∂L/∂q̇) − ∂L/∂q gives them."
)


@dataclass(frozen=True)
class AnswerSlip:
    """A slip read from the answer: a named mistake (``approximation`` for the small-angle form) and its hint."""

    key: str
    name: str
    where: str
    hint: str
    approximation: bool = False
    correct: Correct | None = None  # the correct part the name points at, shown only on request

    def json(self) -> dict[str, Any]:
        """The API's ``mistake`` (as ``app.engine.tutor.diagnose.mistake_json`` gives a catalogue's)."""
        family = "small_angle" if self.approximation else self.key.split(".")[-1]
        # the piece left out or added said so, as a catalogue's name is (mistake_families.said)
        return {"key": self.key, "family": family, "name": said(family, self.name), "latex": "",
                "where": self.where, "approximation": self.approximation, "count": 1}  # fmt: skip


def _same(a: Values, b: Values) -> bool:
    return usable(a, b) >= MIN_POINTS and equal(a, b)


def missing_square(answer: sp.Expr, truth: Values, groups: Groups) -> AnswerSlip | None:
    """The slip naming a part of the answer written where its square belongs, or None."""
    rates = set(groups.rates)
    seen: set[sp.Expr] = set()
    for part in sp.preorder_traversal(answer):
        if len(seen) >= MAX_CANDIDATES:
            break
        # a name, a product, or a function of the coordinates (sin θ where T needs sin²θ)
        if not (part.is_Symbol or part.is_Mul or isinstance(part, sp.Function)) or part in seen or part.free_symbols & rates:
            continue
        if not part.free_symbols or part.could_extract_minus_sign():
            continue
        seen.add(part)
        squared = answer.xreplace({part: part**2})
        if squared != answer and _same(values(squared, groups), truth):
            # the rate the part multiplies (φ̇ beside sin θ in the spherical pendulum's T), else any of the answer's
            beside = [t for t in sp.Add.make_args(sp.expand(answer)) if t.has(part)]
            rate = next((r for t in beside for r in groups.rates if t.has(r)), None) or next(
                (r for r in groups.rates if r in answer.free_symbols), None
            )
            shown, square = unicode_text(part), unicode_text(part**2)
            hint = SQUARE_HINT.format(part=shown, square=square, rate=unicode_text(rate) if rate is not None else "q̇")
            return AnswerSlip(
                "kinetic.square_left_out",
                f"{shown} where T needs its square {square}",
                hint.split(": ", 1)[1].removesuffix("."),
                hint,
            )
    return None


def extra_cross_term(answer: sp.Expr, truth: sp.Expr, groups: Groups) -> AnswerSlip | None:
    """The slip naming a cross term of two rates the correct T has none of (½ m (ẋ₁ + ẋ₂)² for two
    masses that move apart, each with its own ½ m v²), or None."""
    extra = sp.expand(answer - truth)
    if extra == 0 or len(sp.Add.make_args(extra)) != 1:
        return None
    held = [r for r in groups.rates if extra.has(r)]
    if len(held) != 2 or any(sp.degree(extra, r) != 1 for r in held):
        return None
    a, b = held
    if any(t.has(a) and t.has(b) for t in sp.Add.make_args(sp.expand(truth))):
        return None  # the correct T mixes these rates itself: the slip is in that term, not an extra one
    shown = spoken(extra)
    return AnswerSlip(
        "kinetic.cross_term_added",
        f"a cross term {shown} added, which the correct T does not have",
        f"each body's ½ m v² is added on its own; squaring the sum of two bodies' velocities ({unicode_text(a)} and "
        f"{unicode_text(b)}) mixes them",
        f"Your T has a cross term {shown} added, which the correct T does not have: each body's ½ m v² is added on its "
        f"own, and squaring the sum of the velocities of two bodies ({unicode_text(a)} + {unicode_text(b)})² "
        "mixes them.",
    )


def level_body_term(
    answer: sp.Expr, truth: sp.Expr, groups: Groups, level: tuple[tuple[str, sp.Expr], ...]
) -> AnswerSlip | None:
    """The slip naming a term of U for a body whose height never changes (−M g X sin α for the wedge,
    which slides on the floor), or None."""
    moving = set(groups.positions)
    # what the answer adds to U, less a constant (U is defined up to one)
    extra = sp.Add(*(t for t in sp.Add.make_args(sp.expand(answer - truth)) if t.free_symbols & moving))
    if extra == 0:
        return None
    for label, mass in level:
        mass_symbols = mass.free_symbols
        if not mass_symbols or not all(t.free_symbols & mass_symbols for t in sp.Add.make_args(extra)):
            continue
        shown, m = spoken(extra), spoken(mass)
        # U holds m g × height for each body: a body whose height is the same wherever it is adds only a constant
        why = (
            f"the {label} moves only horizontally, so its height does not change and gravity does no work on it: "
            f"{m} has no term in U"
        )
        return AnswerSlip(
            "potential.level_body",
            f"a term {shown} added for the {label}, whose height never changes",
            why,
            f"Your U has a term {shown} added for the {label}, whose height never changes: {why}.",
        )
    return None


def linearised(answer: Values, truth: sp.Expr, groups: Groups) -> AnswerSlip | None:
    """The slip naming an equation linearised about rest at zero, or None (no such rest state, or not it)."""
    moving = (*groups.positions, *groups.rates)
    rest = dict.fromkeys(moving, sp.S.Zero)
    if sp.simplify(truth.xreplace(rest)) != 0:
        return None  # zero is not an equilibrium of this equation: no small-angle form about it
    first = sum((sp.diff(truth, v).xreplace(rest) * v for v in moving), sp.S.Zero)
    if first == 0 or sp.expand(first - truth) == 0:
        return None  # the equation is linear already (or has no first-order part)
    mine = values(first, groups)
    if usable(answer, mine) >= MIN_POINTS and differ_by_factor(answer, mine) and factor_is_constant(answer, mine):
        return AnswerSlip(
            "equation.linearised",
            "the equation linearised for small displacements (sin θ ≈ θ, cos θ ≈ 1, products of small quantities "
            "such as θ̇² dropped)",
            "the step asks for the full equation of motion: keep the sines, cosines and velocity-squared terms as "
            "d/dt(∂L/∂q̇) − ∂L/∂q gives them",
            LINEAR_HINT,
            approximation=True,
        )
    return None


# ---- a solved acceleration or ω² -----------------------------------------------------------------


def _slip(key: str, name: str, where: str, correct: Correct | None = None) -> AnswerSlip:
    return AnswerSlip(f"solved.{key}", name, where, f"Your answer has {name}: {where}.", correct=correct)


def _constant(expr: sp.Expr) -> bool:
    return not expr.free_symbols and expr != 0


def solved_slip(
    answer: sp.Expr, truth: sp.Expr, groups: Groups, frequency: str | None = None, inertia: Inertia = MASS_INERTIA
) -> AnswerSlip | None:
    """The slip in a solved acceleration (``frequency`` None) or ω² (its letter, ω or Ω, and ``inertia`` the
    reduced coordinate's, an effective moment of inertia for an angle), read by comparing the
    answer with the truth: the sign of the whole, a factor upside down or squared, a term of the truth halved or
    doubled, another coordinate's term left out, then the numerator and the denominator compared each on its own;
    or None."""
    mine = values(answer, groups)

    def same(expr: sp.Expr) -> bool:
        return _same(mine, values(expr, groups))

    # answer = −truth: every term's sign reversed together
    if same(-truth):
        return _slip(
            "sign",
            "the sign of the whole answer",
            "every term of yours has the opposite sign: a sign lost on one side of the equation turns every term over",
        )
    numerator, denominator = sp.fraction(sp.cancel(sp.together(truth)))
    number = sp.cancel(numerator.as_coeff_Mul()[0] / denominator.as_coeff_Mul()[0])
    # the truth's factors with their powers (a denominator's negative), its number among them (3/2 of 3 g/(2 l))
    factors = [*((f, -p) for f, p in sp.factor_list(denominator)[1]), *sp.factor_list(numerator)[1]]
    factors += [(number, 1)] if number.is_Rational and abs(number) != 1 else []
    for f, power in factors:
        said = spoken(f) if f.free_symbols else f"number {spoken(f)}"
        where = "divides" if power < 0 else "multiplies"
        # f upside down: the answer is truth · f^(−2 power) (it multiplies where it divides, or the other way); a
        # number is named as the student wrote it (2/3 for 3/2), which does not give the answer away
        if same(truth * f ** (-2 * power)):
            return _slip(
                "upside_down",
                f"the factor {said} upside down" if f.free_symbols else f"the number {spoken(1 / f)} upside down",
                f"in the correct answer it {where}, where yours {'multiplies' if power < 0 else 'divides'}"
                if f.free_symbols
                else "the correct answer has it the other way up; check which of its two numbers goes on top",
            )
        # f squared: the answer is truth · f^power (its power doubled)
        if same(truth * f**power):
            return _slip(
                "squared",
                f"the {'factor ' if f.free_symbols else ''}{said} squared",
                f"in the correct answer it {where} once, to the first power",
            )
    # one term of the truth written at half or twice its size: a factor 2 lost or gained
    terms = sp.Add.make_args(sp.expand(numerator))
    for term in terms if len(terms) > 1 and _constant(denominator) else ():
        term = term / denominator
        for scale, words in ((sp.Rational(1, 2), "lost"), (2, "too many")):
            if same(truth + (scale - 1) * term):
                return _slip(
                    "factor_two",
                    f"a factor 2 {words} in the term {spoken(term)}",
                    f"you wrote {spoken(scale * term)}; the rest of your answer agrees with the correct one",
                )
    # a coordinate the truth depends on, missing from the answer: its term left out
    for q in groups.positions:
        if q in truth.free_symbols and q not in answer.free_symbols:
            return _slip(
                "other_coordinate_left_out",
                f"the term of {spoken(q)} left out",
                f"the correct answer depends on {spoken(q)} too: the coordinates are coupled, so each acceleration "
                "feels the other coordinate",
            )
    # the numerator and the denominator compared each on its own (the answer's scale may be any constant)
    if not denominator.free_symbols:
        return None
    top, bottom = sp.fraction(sp.cancel(sp.together(answer)))
    scale = sp.cancel(top / numerator)
    ratio = sp.cancel(answer / truth)
    if _constant(ratio) and scale != 1:
        # every letter where it belongs and only a number off: said as that number, never as a denominator
        # rescaled to the answer's numerator (4 l/3 for 2 g/(3 l))
        return _slip(
            "number",
            f"a number off: your answer is {spoken(ratio)} times the correct one",
            "every letter is where it belongs; check each number as you carry it from the equation to the answer",
        )
    right = scale * denominator if _constant(scale) else None
    if right is None and _constant(sp.cancel(bottom / denominator)) and answer.is_Add:
        # no one fraction typed (−g sin(θ)/R + θ̇²): said in the student's terms, never as a numerator they did not
        # write. answer = truth + extra; where no extra term is a multiple of one of the truth's, the truth's terms
        # are all there and the extra ones are the slip
        extra = sp.expand(answer - truth)
        theirs = sp.Add.make_args(sp.expand(truth))
        if not any(_constant(sp.cancel(e / t)) for e in sp.Add.make_args(extra) for t in theirs):
            several = len(sp.Add.make_args(extra)) > 1
            return _slip(
                "extra_term",
                f"{'the extra terms' if several else 'an extra term'} {spoken(extra, factored=False)} added, which "
                "the correct answer does not have",
                "every term of the correct answer is in yours",
            )
        # the student's terms named; the correct ones kept for the student to ask for
        return _slip(
            "terms",
            f"the terms {spoken(answer, factored=False)}",
            "compare them with the correct ones term by term",
            Correct("terms", sp.expand(truth)),
        )
    if right is None and _constant(sp.cancel(bottom / denominator)):
        # the correct numerator over the student's own denominator
        wrong = sp.cancel(bottom / denominator) * numerator
        return _slip(
            "numerator",
            f"the numerator {spoken(top)}",
            "the denominator is right",
            Correct("numerator", sp.expand(wrong)),
        )
    if right is not None:
        squares = _square_of_a_sum(bottom, right)
        if squares is not None:
            return _slip("square_of_a_sum", *squares, Correct("denominator", sp.expand(right)))
    numerators = "" if right is not None else f", and the numerator {spoken(top)} differs too"
    return _slip(
        "denominator",
        f"the denominator {spoken(bottom)}{numerators}",
        _denominator_why(denominator, groups, frequency, answer, truth, inertia),
        Correct("denominator", sp.expand(right)) if right is not None
        else Correct("denominator", denominator, "up to a constant factor"),
    )


def _square_of_a_sum(bottom: sp.Expr, right: sp.Expr) -> tuple[str, str] | None:
    """A denominator (a + b)² where a² + b² belongs, or the other way round: (1 + αR)² for the helix's 1 + α²R²,
    named with the cross term 2ab that tells them apart; None otherwise."""
    for yours, correct, words in ((bottom, right, "the square of a sum for a sum of squares"),
                                  (right, bottom, "a sum of squares for the square of a sum")):  # fmt: skip
        square = sp.factor(yours)
        if not (isinstance(square, sp.Pow) and square.exp == 2 and len(sp.Add.make_args(square.base)) == 2):
            continue
        a, b = sp.Add.make_args(square.base)
        # (a + b)² = a² + 2ab + b²: a sum of squares lacks the cross term 2ab
        if sp.expand(correct - a**2 - b**2) != 0:
            continue
        cross = spoken(sp.expand(2 * a * b))
        shown = (spoken(square), spoken(sp.expand(correct))) if yours is bottom else (spoken(bottom), spoken(square))
        # the place and the kind of slip; the correct denominator is kept for the student to ask for
        return (
            f"the denominator {shown[0]}: {words}",
            f"({spoken(square.base)})² = {spoken(sp.expand(square))}, whose cross term {cross} "
            f"{'is not in' if yours is bottom else 'is missing from'} the correct denominator: squaring the sum "
            "adds that cross term, adding the squares has none",
        )
    return None


def _denominator_why(
    denominator: sp.Expr,
    groups: Groups,
    frequency: str | None,
    answer: sp.Expr,
    truth: sp.Expr,
    inertia: Inertia = MASS_INERTIA,
) -> str:
    """What a solved answer's denominator is, in the step's own terms: an ω²'s the effective mass; a single
    equation's acceleration its coefficient of q̈; coupled accelerations' (a sum) what solving them together gives,
    and the body whose mass the answer leaves out, where one does (the pulley's m₂)."""
    if frequency is not None:
        # ω² = U_eff″/m_eff at the equilibrium: one coordinate, no equations to solve together
        return (
            f"{frequency}² is the effective potential's second derivative over the {inertia.words} (the coefficient "
            f"of ½ q̇² in T), both at the equilibrium: check each on its own"
        )
    coordinates = [q for q in groups.positions if q != TIME]
    if len(coordinates) > 1 and isinstance(sp.expand(denominator), sp.Add):
        # a parameter of the correct answer the student's never holds: the equations solved as if without it
        left = sorted(truth.free_symbols - answer.free_symbols - set(groups.positions), key=sp.default_sort_key)
        if left:
            names = " and ".join(spoken(s) for s in left)
            others = ", ".join(spoken(q) for q in coordinates[:-1]) + f" and {spoken(coordinates[-1])}"
            others += " both" if len(coordinates) == 2 else " all"
            return (
                f"your answer has no {names}, as if {'that body' if len(left) == 1 else 'those bodies'} did not move "
                f"(another system's result, such as an Atwood machine's): here {others} move, and solving their "
                f"equations together brings {names} into the denominator"
            )
        return (
            "once the equations are solved together, the denominator collects every body the motion carries and "
            "every coupling of the accelerations"
        )
    # q̈ = (force terms)/(coefficient of q̈): the equation's own coefficient
    return "the acceleration is the force terms of its equation of motion over the coefficient of the acceleration there"


# ---- a small-angle T, U, L or h --------------------------------------------------------------------

SMALL_HINT = (
    "This is {what} for small displacements about q = 0 (cos θ ≈ 1 − θ²/2, sin θ ≈ θ, kept to second order): "
    "an approximation. The step asks for the exact {what}: keep the sines and cosines as the positions give them."
)


def small_angle(answer: Values, truth: sp.Expr, groups: Groups, what: str, constant: bool) -> AnswerSlip | None:
    """The slip naming T, U, L or h written to second order in the small displacements (every coordinate and
    velocity small), where the exact form is asked; or None (the truth has no other form, or not it)."""
    moving = (*groups.positions, *groups.rates)
    if not any(truth.has(q) for q in moving):
        return None
    # each coordinate and velocity scaled by ε: the form to second order is the Taylor polynomial in ε at ε = 1
    eps = sp.Dummy("epsilon")
    scaled = truth.xreplace({v: eps * v for v in moving})
    second = sum((sp.diff(scaled, eps, n).xreplace({eps: 0}) / sp.factorial(n) for n in range(3)), sp.S.Zero)
    if sp.expand(second - truth) == 0:
        return None  # already quadratic: the small-displacement form is the exact one
    mine = values(second, groups)
    if usable(answer, mine) < MIN_POINTS:
        return None
    if not (equal(answer, mine) or (constant and differ_by_constant(answer, mine))):
        return None
    hint = SMALL_HINT.format(what=what)
    return AnswerSlip(
        "small_displacements",
        f"{what} for small displacements (cos θ ≈ 1 − θ²/2, sin θ ≈ θ)",
        f"the step asks for the exact {what}: keep the sines and cosines as the positions give them",
        hint,
        approximation=True,
    )


# ---- one part of an equation off by a factor -------------------------------------------------------


def part_off_by_a_factor(answer: sp.Expr, truth: sp.Expr, groups: Groups) -> AnswerSlip | None:
    """The slip naming the one part of an equation (the terms of one product of rates) that differs from the
    truth's by a factor, every other part agreeing at some scale; or None."""
    try:
        mine, theirs = rate_parts(answer, groups.rates), rate_parts(truth, groups.rates)
    except (sp.PolynomialError, ValueError, TypeError):
        return None
    if mine is None or theirs is None or set(mine) != set(theirs) or len(mine) < 2:
        return None
    for scale in part_scales(mine, theirs, groups):
        wrong = [m for m in mine if not _same(values(mine[m], groups), values(scale * theirs[m], groups))]
        if len(wrong) != 1:
            continue
        part = wrong[0]
        # the part's own factor: its coefficient over the truth's at this scale, free of the rates
        factor = sp.factor(sp.cancel(mine[part] / (scale * theirs[part])))
        if factor.free_symbols & set(groups.rates) or not factor.free_symbols:
            return None
        words = monomial_words(part)
        return AnswerSlip(
            "equation.part_factor",
            f"{words} multiplied by an extra factor {spoken(factor)}",
            f"every other part of your equation agrees with the correct one; only {words} differ",
            f"Your equation has {words} multiplied by an extra factor {spoken(factor)}: every other part agrees with "
            f"the correct one, and only {words} differ.",
        )
    return None
