"""Check a student's own step against the engine's derivation.

A *problem* is one step of one system (``kinetic``, ``potential``, ``lagrangian``,
``momentum``, ``equation``, ``acceleration``, ``hamiltonian``, ``omega_squared``;
the middle three per coordinate): the engine's expression for it (the truth),
how answers may legitimately differ from it, the names an answer may use, and
the mistaken expressions of ``app.engine.tutor.mistakes``. A problem holds SymPy
objects only, so it can be built where the derivation lives and sent to a
worker process with the student's text. (``app.engine.tutor.exercises`` lists a
system's steps for a practice page.)

``judge`` parses the text with the project's parser (app/engine/parser/parse.py), then
compares (app/engine/tutor/compare.py):

* ``correct``: equal to the truth at every random point (or, where too few points
  are defined, symbolically within a time budget);
* ``equivalent``: U, L or h plus a constant (another zero of the potential), or
  an equation of motion times a nonzero factor free of the velocities and
  accelerations (the same equation wherever the factor is not zero);
* ``incorrect``: with ``difference`` = answer − truth, after removing an accepted
  constant (U, L, h) or rescaling the truth to the answer's coefficient of q̈
  (equations), and a hint: the first mistake of ``mistakes.RULES`` the answer
  matches, else the step's general pointer.

``check_answer`` runs the parser's pure-Python gates plus the step's name rules,
so a web process can refuse bad text without SymPy.

The names an answer may use and its reading are ``app.engine.tutor.check_answers``; the
problem of a step is ``app.engine.tutor.check_problem``; this module judges, and is the
door to all three.
"""

from __future__ import annotations

from collections import OrderedDict
from fractions import Fraction
from typing import Any

import sympy as sp

from app.engine.algebra.budget import display_budget, unbudgeted, work_limit
from app.engine.algebra.simplify import tidy
from app.engine.algebra.work import WorkExceeded
from app.engine.derivation.dimensions import (
    Own,
    add_dims,
    dimension,
    equation_words,
    mismatch,
    number_beside_units,
    unit_name,
)
from app.engine.display import textbook
from app.engine.display.names import unicode
from app.engine.display.spoken import spoken
from app.engine.display.textbook import unicode_text
from app.engine.document.report import Printer, display
from app.engine.parser.parse import Parsed
from app.engine.tutor.check_answers import (
    KEYED,
    PER_COMPONENT,
    PER_COORDINATE,
    STEPS,
    CheckError,
    allowed_names,
    answer_error,
    cancelling_terms,
    check_answer,
    name_kinds,
    offered_names,
    parse_answer,
)
from app.engine.tutor.check_problem import (
    RELATIONS,
    Problem,
    checkable_equilibria,
    conserved_momenta,
    exercises,
    problem,
    short_label,
)
from app.engine.tutor.compare import (
    Groups,
    Values,
    close,
    differ_by_constant,
    differ_by_factor,
    equal,
    factor_is_constant,
    mistake_only,
    ratio_groups,
    symbolically_zero,
    usable,
    values,
    without_constant,
)
from app.engine.tutor.diagnose import agreement, follow_up_json, match, mistake_json, partial_json, rate_parts, sentence
from app.engine.tutor.mistake_answer import (
    AnswerSlip,
    extra_cross_term,
    level_body_term,
    linearised,
    missing_square,
    part_off_by_a_factor,
    small_angle,
    solved_slip,
)
from app.engine.tutor.mistake_box import piece_box
from app.engine.tutor.mistake_families import Correct, FollowUp, Mistake
from app.engine.tutor.mistakes import (
    CONSTANT_FACTOR_HINT,
    HALF_MOMENTUM_HINT,
    MISSING_FACTOR_HINT,
    pointer,
    without_gravity,
    without_springs,
)
from app.engine.tutor.quoted_term import as_typed
from app.engine.tutor.spoken_tex import formulas
from app.limits import ANSWER_SLIP_WORK, DIFFERENCE_WORK, FACTOR_WORK, PARTS_WORK, PIECE_WORK
from app.limits import CHECK_DISPLAY_WORK as DISPLAY_WORK

__all__ = [
    "MIN_POINTS",
    "PARTED",
    "KEYED",
    "PER_COMPONENT",
    "PER_COORDINATE",
    "RELATIONS",
    "STEPS",
    "CheckError",
    "Problem",
    "allowed_names",
    "answer_error",
    "cancelling_terms",
    "check_answer",
    "checkable_equilibria",
    "conserved_momenta",
    "exercises",
    "follow_up_answer",
    "follow_up_mistake",
    "follow_up_of",
    "judge",
    "judge_follow_up",
    "judge_of",
    "name_kinds",
    "offered_names",
    "parse_answer",
    "problem",
    "verdict",
    "verdict_of",
]

MIN_POINTS = 6  # sample points where both sides are defined, for a numeric verdict
# the steps whose answers are polynomials in the rates, compared part by part when no mistake matches
PARTED = frozenset({"kinetic", "lagrangian", "momentum", "equation", "hamiltonian"})


def _budgeted(work, fallback, units: float):
    try:
        with work_limit(units):
            return work()
    except (WorkExceeded, RecursionError, TypeError, ValueError, NotImplementedError, ZeroDivisionError):
        return fallback


def _verdict(
    verdict: str, message: str, reveal: dict[str, Any] | None = None, hint: str | None = None, **more: Any
) -> dict[str, Any]:
    """A verdict: what the student reads (message, hint, mistake, partial, follow_up) names the slip and never
    prints the correct answer; ``correct_part`` (the correct part the mistake's name points at: a denominator, a
    stretch) is for the student to open on request, ``reveal`` (the difference and the correct piece) for the
    step's reveal."""
    mistake, partial, follow_up = more.get("mistake"), more.get("partial"), more.get("follow_up")
    # the formulas those words quote, each with its LaTeX, for a page to typeset where the words print them
    words = (message, hint, (mistake or {}).get("name"), (mistake or {}).get("where"),
             (partial or {}).get("message"), (follow_up or {}).get("question"))  # fmt: skip
    return {
        "verdict": verdict,
        "message": message,
        "hint": hint,
        "mistake": mistake,
        "partial": partial,
        "follow_up": follow_up,
        "correct_part": more.get("correct_part"),
        "reveal": reveal,
        "formulas": formulas(words),
    }


def _correct_part(correct: Correct | None, printer: Printer) -> dict[str, Any] | None:
    """The correct part a named mistake points at, typeset, for the student to open ("Show the correct
    denominator"); None where the name points at none."""
    if correct is None:
        return None
    return {"what": correct.what, "latex": printer.tex(correct.expr), "text": printer.text(correct.expr),
            "note": correct.note}  # fmt: skip


def _reveal(shown: dict[str, str], piece: str = "") -> dict[str, Any]:
    return {"difference": shown, "piece": piece}


def _several_terms(answer: sp.Expr) -> bool:
    """Whether "everything else is right" says anything: an answer of more than one term."""
    return answer != 0 and len(sp.Add.make_args(sp.expand(answer))) > 1


def _noun(pb: Problem) -> str:
    return f"the correct {pb.label}" + (f" (at {pb.where[0]})" if pb.where else "")


_VALUES: OrderedDict[tuple, Values] = OrderedDict()


def _known(expr: sp.Expr, groups: Groups) -> Values:
    """The values of an engine expression (a truth or a mistake), remembered: a worker judges many answers."""
    key = (expr, groups)
    if key in _VALUES:
        _VALUES.move_to_end(key)
        return _VALUES[key]
    found = _VALUES[key] = values(expr, groups)
    while len(_VALUES) > 512:
        _VALUES.popitem(last=False)
    return found


def verdict(pb: Problem, text: Parsed | str) -> dict[str, Any] | None:
    """The verdict on a right answer (correct, or equivalent), decided from the sample values without the
    catalogue of mistakes (a problem built with ``mistakes=False`` will do); None for a wrong one."""
    return verdict_of(pb, parse_answer(pb, text))


def verdict_of(pb: Problem, answer: sp.Expr) -> dict[str, Any] | None:
    """``verdict`` on an answer already built (``parse_answer``): a function of the expression alone, so
    answers typed differently that build to one expression (``m*g*l``, ``g*m*l``) may share it."""
    a = values(answer, pb.groups)
    return _right(pb, answer, a, [(truth, _known(truth, pb.groups)) for truth in pb.truths])


def _right(pb: Problem, answer: sp.Expr, a: Values, results: list[tuple[sp.Expr, Values]]) -> dict[str, Any] | None:
    """The verdict when the answer equals a truth (or differs from it as the step allows), else None."""
    numeric = [(truth, b) for truth, b in results if usable(a, b) >= MIN_POINTS]
    for i, (truth, b) in enumerate(results):
        if (truth, b) in numeric:
            same = equal(a, b)
        else:
            # too few points where both are defined: decide symbolically within the budget
            same = symbolically_zero(answer - truth) is True
        if same:
            at = f" at {pb.where[i]}" if pb.where else ""
            return _verdict("correct", f"Correct: this is the {pb.label}{at}.")

    for truth, b in numeric:
        if pb.relation == "constant" and differ_by_constant(a, b):
            # another zero of U, unless the constant is a bare number beside an energy (7 has no unit)
            offence = _units(pb, answer, None)
            if offence is not None:
                return _units_verdict(pb, Printer(pb.latex_names), *offence)
            return _verdict("equivalent", _constant_message(pb, answer - truth))
        if pb.relation == "factor" and differ_by_factor(a, b):
            constant = factor_is_constant(a, b)
            # the same equation divided through by a constant (θ̈ + (g/R) sin θ, as the page prints it) is right;
            # a factor that depends on the coordinates makes it the same only where that factor is not zero
            return _verdict("correct" if constant else "equivalent", _factor_message(pb, answer, truth, constant))
    return None


def judge(pb: Problem, text: Parsed | str) -> dict[str, Any]:
    """The verdict on one answer (as ``check_answer`` read it, or its text): ``{"verdict", "message",
    "difference", "hint"}``; a system without a spring is not told about springs."""
    return judge_of(pb, parse_answer(pb, text), cancelling_terms(pb, text))


def judge_of(pb: Problem, answer: sp.Expr, cancelling: tuple[sp.Expr, sp.Expr] | None = None) -> dict[str, Any]:
    """``judge`` on an answer already built (``parse_answer``): a function of the expression alone, so answers
    typed differently that build to one expression may share it; and of ``cancelling``, two typed terms that
    cancel (``app.engine.tutor.check_answers.cancelling_terms``), which the built answer no longer shows."""
    verdict = _judge(pb, answer)
    if cancelling is not None and verdict["verdict"] == "incorrect":
        verdict = _cancelled(pb, answer, cancelling, verdict)
    if not pb.gravity and verdict.get("hint"):
        verdict["hint"] = without_gravity(verdict["hint"])
    if not pb.springs:
        if verdict.get("hint"):
            verdict["hint"] = without_springs(verdict["hint"])
        # the named mistake is shown by its name and its reason: neither speaks of a spring
        if verdict.get("mistake"):
            mistake = verdict["mistake"]
            verdict["mistake"] = {**mistake, "name": without_springs(mistake["name"]),
                                  "where": without_springs(mistake["where"])}  # fmt: skip
    return verdict


def _not_at_equilibrium(pb: Problem, printer: Printer, answer: sp.Expr) -> dict[str, Any]:
    """An ω² that still depends on a coordinate (g cos(θ)/R): graded wrong, and named as U_eff″/m_eff not
    evaluated at the equilibrium where putting the equilibrium in makes it right."""
    w = pb.frequency
    # I_eff for an angle, m_eff for a length (app/engine/notation.inertia)
    i = pb.inertia.unicode
    moving = sorted(answer.free_symbols & set(pb.groups.positions), key=sp.default_sort_key)
    said = " and ".join(spoken(s) for s in moving)
    at = pb.where[0] if pb.where else "the equilibrium"
    message = f"Incorrect: this is not {_noun(pb)}."
    if pb.equilibrium is not None:
        q, q0 = pb.equilibrium
        # ω² = U_eff″(q₀)/m_eff(q₀): the second derivative and the effective mass taken at the equilibrium q₀
        there = answer.subs(q, q0)
        found = None if there.free_symbols & set(pb.groups.positions) else verdict_of(pb, there)
        if found is not None and found["verdict"] == "correct":
            name = f"{w}² = U_eff″/{i} not evaluated at the equilibrium"
            where = f"put {at}: {w}² at an equilibrium is a constant, U_eff″ and {i} taken there"
            mistake = Mistake(f"{pb.step}.not_at_equilibrium", "not_at_equilibrium", name, None, where, answer)
            return _verdict(
                "incorrect",
                message,
                _reveal(printer.pair(answer - pb.truths[0])),
                f"Your {w}² still depends on {said}: {name}: put {at}.",
                mistake=mistake_json(mistake, str),
            )
    return _verdict(
        "incorrect",
        message,
        _reveal(printer.pair(answer - pb.truths[0])),
        f"Your {w}² still depends on {said}, but {w}² at an equilibrium is a constant: take U_eff″ and {i} at "
        f"{at}, with the parameters (and conserved momenta) only.",
    )


def _cancelled(
    pb: Problem, answer: sp.Expr, pair: tuple[sp.Expr, sp.Expr], verdict: dict[str, Any]
) -> dict[str, Any]:
    """A wrong answer that two of its typed terms cancelling made wrong: right with either one of them kept
    (gravity written twice with opposite signs was named as gravity left out). Said so,
    as the student's own two terms; another wrong answer keeps its verdict."""
    if not any(verdict_of(pb, answer + term) is not None for term in pair):
        return verdict
    moving = pb.groups.positions
    shown = " and ".join(
        f"−{spoken(-t, moving)}" if t.could_extract_minus_sign() else f"+{spoken(t, moving)}" for t in pair
    )
    gravity = any(s.name == "g" for s in pair[0].free_symbols)
    if pb.step == "equation" and pb.coordinate:
        q = unicode(pb.coordinate)
        # the force of a potential along q is −∂U/∂q: it enters d/dt ∂L/∂q̇ − ∂L/∂q = 0 once, through −∂L/∂q
        force = "gravity's force" if gravity else "this force"
        where = f"{force} enters once, as −∂U/∂{q}"
    else:
        where = "each term enters once: two with opposite signs leave it out"
    name = f"your terms {shown} cancel"
    mistake = Mistake(f"{pb.step}.cancelling_terms", "cancelling_terms", name, None, where, answer)
    label = short_label(pb.step, pb.label)
    return {
        **verdict,
        "hint": f"In your {label}, the {name.removeprefix('your ')}: {where}.",
        "mistake": mistake_json(mistake, str),
        "partial": partial_json(mistake, label),
        "follow_up": None,
    }


def _judge(pb: Problem, answer: sp.Expr) -> dict[str, Any]:
    printer = Printer(pb.latex_names)
    a = values(answer, pb.groups)
    results = [(truth, _known(truth, pb.groups)) for truth in pb.truths]
    right = _right(pb, answer, a, results)
    if right is not None:
        return right
    if pb.step == "omega_squared" and answer.free_symbols & set(pb.groups.positions):
        return _not_at_equilibrium(pb, printer, answer)

    truth, b = results[0]
    with display_budget(DISPLAY_WORK):
        difference, how, scale = _difference(pb, answer, truth)
        # the mistake only: what cancels identically gone, trigonometry recombined; where that did not apply
        # (a long difference, an acceleration's), the display's own simplification
        only = mistake_only(difference, DIFFERENCE_WORK)
        shown = _shown(pb, printer, display(difference) if only is difference else only)
    message = f"Incorrect: this is not {_noun(pb)}{how}."
    # terms whose units disagree are named first, at any step: no algebra explains them; then the catalogue,
    # then a whole of the wrong units
    found = _units(pb, answer, None)
    if found is None:
        keep = _keeps_a_right_acceleration(pb, answer, truth)
        if pb.step == "momentum" and differ_by_factor(b, a):
            # a momentum short of a whole factor (m ż for m ż (1 + α²R²)) is named by that factor below, never as
            # one of the terms its factor expands into
            keep = lambda m: m.family != "left_out"  # noqa: E731
        found = match(pb.mistakes, a, b, pb.relation, _at_engines_scale(pb, answer, a, truth), keep)
    more = None
    if found is None and pb.relation != "factor" and pb.step != "momentum":
        # (a momentum short of a factor is named by that factor, below)
        found = _units(pb, answer, truth)
        # a whole of the wrong units may hide a second slip: said, and named where it is a named one
        more = _budgeted(lambda: _more_after_units(pb, answer, truth, b), None, ANSWER_SLIP_WORK) if found else None
    if found is not None:
        mistake, hint = found
        if mistake.family == "units":
            return _units_verdict(pb, printer, mistake, hint, more)
        mistake, hint = as_typed(mistake, hint, answer, scale, pb.step, pb.groups.positions)
        if pb.relation == "exact" or equal(a, _known(mistake.expr, pb.groups)):
            # the answer is this mistake as written: show the difference as the change to the engine's own
            # pieces (m₂ l₁ l₂ θ̇₁ θ̇₂ (sin(θ₁ − θ₂) − cos(θ₁ − θ₂)), not its sines and cosines expanded)
            own = mistake.expr - truth
            if pb.relation == "constant":  # less the constant the shown difference leaves out
                own = without_constant(own, pb.groups.dynamic())[0]
            own = sp.factor_terms(own)
            if own != 0 and own.free_symbols and sp.count_ops(own) <= sp.count_ops(sp.sympify(shown["sympy"])):
                shown = printer.pair(own)
        whole = _whole_mistake(pb, a, mistake)
        # the piece under the name: labelled, at the answer's scale, or nothing where the difference says it
        box = _budgeted(
            lambda: piece_box(mistake, difference, truth, scale, pb.groups, pb.relation,
                              short_label(pb.step, pb.label), whole, printer.tex),
            "",
            PIECE_WORK,
        )  # fmt: skip
        return _verdict(
            "incorrect",
            message,
            # the correct piece (what the answer leaves out, the correct term) is the answer's: kept for the reveal
            _reveal(shown, box),
            hint,
            mistake={**mistake_json(mistake, printer.tex), "latex": ""},
            # "everything else is right" only where the answer is this mistake and nothing more (never for a
            # whole of the wrong units: a second slip may hide behind it), and has more than the one slip's term
            # (never beside the sign of the whole answer: nothing else is left to be right)
            partial=partial_json(mistake, short_label(pb.step, pb.label))
            if whole and _several_terms(answer) and not mistake.key.endswith("whole_sign")
            else None,
            follow_up=follow_up_json(mistake, allowed_names(mistake.follow_up.kind, pb.kinds))
            if mistake.follow_up
            else None,
            correct_part=_correct_part(mistake.correct, printer),
        )
    # no known mistake: say which parts agree (against the truth at the answer's scale)
    partial = (
        _budgeted(lambda: _agreement(pb, answer, truth, difference), None, PARTS_WORK) if pb.step in PARTED else None
    )
    advice = _hint(pb, answer, a, b, truth)
    if isinstance(advice, AnswerSlip):
        # a slip read from the answer is named as a catalogue's mistake is (or as an approximation)
        return _verdict("incorrect", message, _reveal(shown), advice.hint, mistake=advice.json(),
                        correct_part=_correct_part(advice.correct, printer))  # fmt: skip
    if pb.step == "momentum" and differ_by_factor(b, a):
        partial = None  # the answer agrees up to one factor: "no part agrees" would contradict the hint
    return _verdict("incorrect", message, _reveal(shown), advice, partial=partial)


def _agreement(pb: Problem, answer: sp.Expr, truth: sp.Expr, difference: sp.Expr) -> dict[str, Any] | None:
    """Part by part: an equation against the truth at the scale where most parts agree (the acceleration term may
    be the wrong part); any other step against the truth as its difference was taken."""
    if pb.relation == "factor":
        return agreement(answer, truth, pb.groups, pb.step, rescale=True)
    return agreement(answer, answer - difference, pb.groups, pb.step)


def _shown(pb: Problem, printer: Printer, shown: sp.Expr) -> dict[str, Any]:
    """A difference with no factor a reader could not write: (1 − R) m R θ̇ subtracts a length from a number,
    so it is shown expanded (m R θ̇ − m R² θ̇), as it is, not refactored by the textbook form."""
    if pb.dimensions and number_beside_units(shown, pb.dimensions):
        expanded = sp.expand(shown)
        if not number_beside_units(expanded, pb.dimensions):
            with unbudgeted():
                tex = textbook.latex(expanded, printer.names, None)
            return printer.shown(expanded, tex, expanded)
    return printer.pair(shown)


def _units_verdict(
    pb: Problem, printer: Printer, mistake: Mistake, hint: str, more: str | None = None
) -> dict[str, Any]:
    """Terms whose units disagree: a difference would read as nonsense ((1 − R/2) m R θ̇²); the units are the
    mistake, shown on the student's own sum, and nothing else is shown but ``more``, a second slip behind them."""
    return _verdict(
        "incorrect",
        f"Incorrect: this is not {_noun(pb)}: its units do not agree, as said below.",
        None,
        hint,
        partial={"message": more, "agree": [], "differ": []} if more else None,
        mistake={
            **mistake_json(mistake, printer.tex),
            # the offending part of a longer answer; the whole answer is in the student's own preview already
            "latex": "" if mistake.piece == mistake.expr else r"\text{in your answer: }" + printer.tex(mistake.piece),
        },
    )


def _whole_mistake(pb: Problem, a: Values, mistake: Mistake) -> bool:
    """Whether the answer is the mistake's own wrong answer (up to the step's accepted constant or factor)."""
    if mistake.family in ("units", "other_coordinate", "limit", "bodies_lumped") or mistake.expr is None:
        return False  # (another question's answer, or the whole answer recast: nothing "else" in it is right or wrong)
    v = _known(mistake.expr, pb.groups)
    return (
        equal(a, v)
        or (pb.relation == "constant" and differ_by_constant(a, v))
        or (pb.relation == "factor" and differ_by_factor(a, v))
    )


def _at_engines_scale(pb: Problem, answer: sp.Expr, a: Values, truth: sp.Expr) -> Values | None:
    """An equation's values rescaled to the engine's coefficient of the acceleration (the student's own terms,
    at the engine's scale), or None."""
    if pb.relation != "factor" or pb.acceleration is None:
        return None
    mine = values(sp.diff(answer, pb.acceleration), pb.groups)
    theirs = _known(sp.diff(truth, pb.acceleration), pb.groups)
    out = []
    for xa, xm, xt in zip(a, mine, theirs, strict=True):
        out.append([
            [x * t / m if x is not None and m and t is not None else None for x, m, t in zip(pa, pm, pt, strict=True)]
            for pa, pm, pt in zip(xa, xm, xt, strict=True)
        ])  # fmt: skip
    return out


def _by_a_number(a: Values, b: Values) -> bool:
    """a / b is one number at every sample point (the parameters' values included)."""
    ratios = [x for group in ratio_groups(a, b) for x in group]
    return len(ratios) >= MIN_POINTS and all(close(x, ratios[0]) for x in ratios)


def _keeps_a_right_acceleration(pb: Problem, answer: sp.Expr, truth: sp.Expr):
    """For an equation whose acceleration term is the truth's (up to a number): a test refusing every mistake that
    changes that term (a slip of T, say), since the answer's slip lies elsewhere; else None."""
    if pb.relation != "factor" or pb.acceleration is None:
        return None
    theirs = _known(sp.diff(truth, pb.acceleration), pb.groups)
    if not _by_a_number(values(sp.diff(answer, pb.acceleration), pb.groups), theirs):
        return None
    return lambda m: m.expr is None or _by_a_number(values(sp.diff(m.expr, pb.acceleration), pb.groups), theirs)


def _units(pb: Problem, answer: sp.Expr, truth: sp.Expr | None) -> tuple[Mistake, str] | None:
    """An answer whose terms have different units, or (given the truth) whose whole has other units than the
    step's, named so."""
    if not pb.dimensions:
        return None
    want = None if truth is None else dimension(truth, pb.dimensions)
    what = short_label(pb.step, pb.label)
    offence = mismatch(answer, pb.dimensions, want, what, _own_words(pb), _parameters(pb))
    if offence is None:
        return None
    where = "every term of an expression has the same units; checking them finds a slip before any algebra"
    words = offence.words if offence.words.endswith((".", "?")) else f"{offence.words}."
    mistake = Mistake("units.mismatch", "units", f"units that do not agree. {words}", offence.piece, where,
                      answer)  # fmt: skip
    return mistake, f"Check the units. {words}"


def _more_after_units(pb: Problem, answer: sp.Expr, truth: sp.Expr, b: Values) -> str | None:
    """A whole of the wrong units put right by a parameter of the units it lacks (or has too many): where every
    answer so corrected still differs from the truth, at least one more slip remains (m R θ̇²
    for ½ m R² θ̇², the R named and the ½ not); named where it is a slip of the step's catalogue, else said so."""
    got, want = dimension(answer, pb.dimensions), dimension(truth, pb.dimensions)
    if got is None or want is None or got == want:
        return None
    missing = add_dims(want, got, Fraction(-1))
    extra = add_dims(got, want, Fraction(-1))
    parameters = _parameters(pb)
    # the answer times each parameter of the missing units, or over each of the extra units
    corrected = [answer * p for p in parameters if pb.dimensions.get(p) == missing]
    corrected += [answer / p for p in parameters if pb.dimensions.get(p) == extra]
    if not corrected:
        return None
    tried = [values(c, pb.groups) for c in corrected]
    if any(usable(v, b) < MIN_POINTS or _same_answer(pb, v, b) for v in tried):
        return None  # the units' slip is the only one (or cannot be told)
    for v in tried:
        found = match(pb.mistakes, v, b, pb.relation)
        if found is not None and found[0].family != "units":
            name = found[0].said.replace("your ", "the ")
            return f"And there is at least one more difference: {name}."
    return (
        "And there is at least one more difference, not one of the slips named here: with the units put right, "
        "compare your answer with the correct one term by term."
    )


def _same_answer(pb: Problem, a: Values, b: Values) -> bool:
    """a equals b as the step allows (up to its accepted constant or factor)."""
    return (
        equal(a, b)
        or (pb.relation == "constant" and differ_by_constant(a, b))
        or (pb.relation == "factor" and differ_by_factor(a, b))
    )


def _own_words(pb: Problem) -> Own:
    """What this step calls a dimension its own way: a term of an angle's equation of motion is a torque."""
    if pb.step != "equation" or pb.coordinate is None or pb.coordinate not in pb.namespace:
        return ()
    return equation_words(pb.coordinate, pb.dimensions.get(pb.namespace[pb.coordinate]))


def _parameters(pb: Problem) -> tuple[sp.Symbol, ...]:
    """The problem's parameters (m, g, R): one of them names a factor the units say is missing."""
    return tuple(pb.namespace[n] for n, kind in pb.kinds.items() if kind == "parameter" and n in pb.namespace)


def follow_up_mistake(pb: Problem, key: str) -> Mistake:
    """The named mistake of this step that asks a follow-up question (a CheckError naming the ones that do)."""
    mistake = pb.mistake(key)
    if mistake is None or mistake.follow_up is None:
        keys = [m.key for m, _, _ in pb.mistakes if m.follow_up is not None]
        raise CheckError(
            f"follow_up: {key[:80]!r} is not a mistake of this step with a question; "
            + (f"the ones with a question are: {', '.join(keys)}" if keys else "this step has none"),
            "follow_up",
            key[:80],
        )
    return mistake


def judge_follow_up(pb: Problem, key: str, text: Parsed | str) -> dict[str, Any]:
    """The verdict on the answer to a named mistake's follow-up question (a CheckError when it has none)."""
    mistake = follow_up_mistake(pb, key)
    return follow_up_of(pb, mistake, follow_up_answer(pb, mistake, text))


def follow_up_answer(pb: Problem, mistake: Mistake, text: Parsed | str) -> sp.Expr:
    """The answer to ``mistake``'s follow-up question, built with the names that question may use."""
    assert mistake.follow_up is not None  # follow_up_mistake refuses a mistake without a question
    return parse_answer(pb, text, mistake.follow_up.kind)


def follow_up_of(pb: Problem, mistake: Mistake, answer: sp.Expr) -> dict[str, Any]:
    """``judge_follow_up`` on an answer already built (``follow_up_answer``): a function of the expression
    alone."""
    fu = mistake.follow_up
    assert fu is not None  # follow_up_mistake refuses a mistake without a question
    if fu.relation == "magnitude":
        # a speed or a stretch: either sign is the same size
        mine, theirs = values(answer**2, pb.groups), _known(fu.truth**2, pb.groups)
    else:
        mine, theirs = values(answer, pb.groups), _known(fu.truth, pb.groups)
    right = usable(mine, theirs) >= MIN_POINTS and equal(mine, theirs)
    printer = Printer(pb.latex_names)
    if right:
        return _verdict(
            "correct",
            # echoed as the student wrote it (M (ẏ₁ + ẏ₂)²/8 stays factored), not as the engine's answer reads
            f"Correct: {spoken(answer, factored=False)}. Now put it back into your {pb.label}.",
            hint=None,
            mistake=mistake_json(mistake, printer.tex),
        )
    # a new hint, not the first one again and not the question again: the slip in the reply where it is one a
    # student makes; else its units where they are wrong, as the step's own check tells an answer (R α for a
    # speed); else the concrete one where the question has it
    slip = _follow_up_slip(pb, fu, answer) or _same_slip(pb, fu, mistake, mine)
    units = None if slip else _reply_units(pb, fu, answer)
    return _verdict(
        "incorrect",
        "Not yet: its units do not agree, as said below."
        if units
        else "Not yet: that is not the answer to the question.",
        hint=slip
        or units
        or fu.hint
        or "Work it out on its own, from its definition, then compare your reply with it term by term.",
        mistake={**mistake_json(mistake, printer.tex), "latex": ""},  # (the piece is the question's answer)
        follow_up=follow_up_json(mistake, allowed_names(fu.kind, pb.kinds)),
    )


def _reply_units(pb: Problem, fu: FollowUp, answer: sp.Expr) -> str | None:
    """A reply to a follow-up whose terms disagree in units, or whose whole has other units than the question's
    answer, in the words of the step's own units check; None where the units agree or cannot be told."""
    if not pb.dimensions:
        return None
    offence = mismatch(answer, pb.dimensions, dimension(fu.truth, pb.dimensions), "reply", (), _parameters(pb))
    if offence is None:
        return None
    return f"Check the units. {offence.words if offence.words.endswith('.') else offence.words + '.'}"


def _same_slip(pb: Problem, fu: FollowUp, asked: Mistake, mine) -> str | None:
    """The step's own catalogue run on the question's answer: a mistake of the step changes the truth by
    expr − truth, and where the question's answer changed by the same amount is the reply, the reply has that
    slip (the lower bob's T alone as ½ m₂ l₂² θ̇₂²: its θ̇₁ part left out, as in the whole T)."""
    if fu.relation != "exact" or fu.kind != pb.step:
        return None
    truth = pb.truths[0]
    for m, _, _ in pb.mistakes:
        if m.key == asked.key or m.count != 1 or m.family == "units":
            continue
        # the reply with m's slip: the question's answer plus the change m makes to the whole
        slipped = _known(fu.truth + m.expr - truth, pb.groups)
        if usable(mine, slipped) >= MIN_POINTS and equal(mine, slipped):
            # and the body that carries this one along, where the mistake's own question knows it
            carrier = [c for c in (m.follow_up.hint if m.follow_up else "").split(". ") if " carries the " in c]
            return " ".join([sentence(m, "reply"), *(f"{c}." for c in carrier[:1])])
    return None


def _follow_up_slip(pb: Problem, fu: FollowUp, answer: sp.Expr) -> str | None:
    """A slip in the reply to a follow-up question: its sign reversed; or, in a time derivative, the chain
    rule's rate left out: the reply times one coordinate's rate is the answer (2 r for d/dt r², whose answer is
    2 r ṙ), or times the rate of an argument of several coordinates (θ̇₁ − θ̇₂)."""
    theirs = _known(fu.truth, pb.groups)
    if fu.relation == "exact" and answer != 0 and equal(values(-answer, pb.groups), theirs):
        return "Your reply has the right size but the opposite sign: check the sign each derivative brings."
    if fu.kind != "momentum" or not fu.question.startswith("What is the time derivative"):
        return None
    rates = [v for v in pb.groups.rates if v.name.endswith("_dot") and not v.name.endswith("_ddot")]
    # the chain rule's whole factor left out, where the argument holds several coordinates
    # (−sin(θ₁ − θ₂) for d/dt cos(θ₁ − θ₂), whose answer is −sin(θ₁ − θ₂)(θ̇₁ − θ̇₂))
    factor = _budgeted(lambda: sp.cancel(fu.truth / answer), None, FACTOR_WORK) if answer != 0 else None
    if (
        factor is not None
        and factor.free_symbols
        and factor.free_symbols <= set(rates)
        and factor.is_polynomial(*rates)
        and sp.Poly(factor, *rates).total_degree() == 1
        and len(factor.free_symbols) > 1
    ):
        return (
            f"You differentiated the function, and left out the chain rule's factor {unicode_text(factor)}: its "
            "argument changes along the motion, so d/dt f(u) = f′(u) u̇, with u̇ the rate of the argument."
        )
    for v in rates:
        if not fu.truth.has(v):
            continue
        if equal(values(answer * v, pb.groups), theirs):
            # d/dt f(q) = f′(q) q̇: the reply is f′(q), the derivative by q alone
            name, rate = unicode(v.name[: -len("_dot")]), unicode(v.name)
            return (
                f"You differentiated with respect to {name}, and left out the chain rule's {rate}: {name} changes "
                f"along the motion, so d/dt f({name}) = (df/d{name}) {rate}."
            )
    return None


def _constant_message(pb: Problem, difference: sp.Expr) -> str:
    varying, constant = without_constant(difference, pb.groups.dynamic())
    shown = constant if symbolically_zero(varying) else None
    amount = f"the constant {_with_unit(pb, shown)}" if shown is not None else "a constant"
    why = {
        "position": "another origin, which changes no velocity and no equation of motion",
        "potential": "a different zero of height; a constant added to U changes no force and nothing in the motion",
        "lagrangian": "a constant added to L drops out of every Euler–Lagrange equation and changes nothing in the "
        "motion",
        "hamiltonian": "the zero of U moved, which changes no equation of motion",
    }[pb.step]
    return f"Equivalent: your {pb.label} is the correct one plus {amount}: {why}."


def _with_unit(pb: Problem, constant: sp.Expr) -> str:
    """A constant as a sentence says it: a number with the step's unit (1 J, 0.5 m), or, where no unit was
    declared, in the step's units (1, in the units of U); a product of parameters carries its own (m g R)."""
    said = unicode_text(constant)
    if constant.free_symbols:
        return said
    said = said.replace("-", "\u2212")  # a number's sign as printed: −2, never a hyphen
    unit = dimension(pb.truths[0], pb.dimensions) if pb.dimensions else None
    if unit is None:
        return f"{said} (in the units of {short_label(pb.step, pb.label)})"
    return f"{said} {unit_name(unit)}".strip()


def _factor_message(pb: Problem, answer: sp.Expr, truth: sp.Expr, constant: bool) -> str:
    factor = _budgeted(lambda: tidy(sp.cancel(answer / truth), FACTOR_WORK), None, FACTOR_WORK * 2)
    rates = set(pb.groups.rates)
    named = f"{unicode_text(factor)}" if factor is not None and not (factor.free_symbols & rates) else "a factor"
    if constant:
        # a nonzero constant factor changes no solution: the same equation, however it was divided through
        return f"Correct: this is the equation of motion for {pb.label.rsplit(' for ', 1)[-1]}."
    return (
        f"Equivalent: your equation is the correct one multiplied by {named}, which depends on the "
        "coordinates: the same equation wherever that factor is not zero."
    )


def _difference(pb: Problem, answer: sp.Expr, truth: sp.Expr) -> tuple[sp.Expr, str, sp.Expr]:
    """answer − truth, less an accepted constant, or against the truth rescaled to the answer's q̈ coefficient;
    with the words saying so and the scale (1 unless rescaled)."""
    one = sp.Integer(1)
    if pb.relation == "constant":
        varying, constant = without_constant(answer - truth, pb.groups.dynamic())
        if varying != 0:
            # the clause only where a constant was in fact taken out of the difference
            # (said of U where U is what was asked; a position, L or h has "a constant" of its own)
            of = "constants in U are" if pb.step == "potential" else "a constant added to it is"
            said = f" ({of} ignored in this comparison)" if constant != 0 else ""
            return varying, said, one
        return answer - truth, "", one
    if pb.relation == "factor" and pb.acceleration is not None:
        mine, theirs = sp.diff(answer, pb.acceleration), sp.diff(truth, pb.acceleration)
        if mine != 0 and theirs != 0:
            scale = _budgeted(lambda: sp.cancel(mine / theirs), None, FACTOR_WORK)
            if scale is not None and scale != 1 and not (scale.free_symbols & set(pb.groups.rates)):
                # compared at the student's scale, which is not said: the scale is the coefficient of q̈
                return answer - scale * truth, "", scale
    return answer - truth, "", one


def _hint(pb: Problem, answer: sp.Expr, a, b, truth: sp.Expr) -> str | AnswerSlip:
    """The hint when no known mistake matches: a missing factor of a momentum, else the step's rule."""
    if pb.step == "momentum" and differ_by_factor(b, a):
        # the engine's momentum is the answer times a factor free of the velocities: a factor is missing
        factor = _budgeted(lambda: tidy(sp.cancel(truth / answer), FACTOR_WORK), None, FACTOR_WORK * 2)
        if factor is not None:
            if factor == 2:
                return HALF_MOMENTUM_HINT
            template = CONSTANT_FACTOR_HINT if factor_is_constant(b, a) else MISSING_FACTOR_HINT
            return template.format(factor=unicode_text(factor))
    # slips read from the answer itself (app/engine/tutor/mistake_answer.py)
    if pb.step in ("kinetic", "lagrangian", "hamiltonian"):
        found = _budgeted(lambda: missing_square(answer, b, pb.groups), None, ANSWER_SLIP_WORK)
        if found is None:
            # the same rule on the answer grouped by its products of velocities, each coefficient factored: a part
            # left unsquared inside one term (½ m (… + 2αρ ρ̇²) read as ½ m (1 + 2αρ) ρ̇² + …)
            grouped = _budgeted(lambda: _grouped(answer, pb.groups), None, ANSWER_SLIP_WORK)
            if grouped is not None and grouped != answer:
                found = _budgeted(lambda: missing_square(grouped, b, pb.groups), None, ANSWER_SLIP_WORK)
        if found is not None:
            return found
    if pb.step == "kinetic":
        found = _budgeted(lambda: extra_cross_term(answer, truth, pb.groups), None, ANSWER_SLIP_WORK)
        if found is not None:
            return found
    if pb.step == "potential" and pb.level:
        found = _budgeted(lambda: level_body_term(answer, truth, pb.groups, pb.level), None, ANSWER_SLIP_WORK)
        if found is not None:
            return found
    if pb.step == "equation":
        found = _budgeted(lambda: linearised(a, truth, pb.groups), None, ANSWER_SLIP_WORK)
        if found is not None:
            return found
        # one part wrong by a factor, every other part right (the helix's gravity times 1 + α²R²)
        found = _budgeted(lambda: part_off_by_a_factor(answer, truth, pb.groups), None, ANSWER_SLIP_WORK)
        if found is not None:
            return found
    if pb.step in _SMALL_FORMS or pb.step == "position":
        # the small-angle form where the exact one is asked (the equation's own is named by linearised, above); a
        # position too (R θ²/2 for the bob's z)
        what, constant = _SMALL_FORMS.get(pb.step, pb.label), pb.relation == "constant"
        found = _budgeted(lambda: small_angle(a, truth, pb.groups, what, constant), None, ANSWER_SLIP_WORK)
        if found is not None:
            return found
    if pb.step in ("acceleration", "omega_squared"):
        frequency = pb.frequency if pb.step == "omega_squared" else None
        found = _budgeted(lambda: solved_slip(answer, truth, pb.groups, frequency, pb.inertia), None, ANSWER_SLIP_WORK)
        if found is not None:
            return found
    # the step's rule in the document's letter for the frequency (Ω² on the rotating wire)
    return pointer(pb.step, pb.frequency, pb.inertia)


def _grouped(answer: sp.Expr, groups: Groups) -> sp.Expr | None:
    """The answer as a sum over its products of velocities, each times its coefficient factored
    (m (1 + 2 α ρ) ρ̇²/2 + m ω² ρ²/2); None where it is no polynomial in the velocities."""
    try:
        parts = rate_parts(answer, groups.rates)
    except sp.PolynomialError:
        return None
    if parts is None:
        return None
    return sp.Add(*(monomial * sp.factor(coefficient) for monomial, coefficient in parts.items()))


# the steps whose small-displacement form is named, and what each is called in the hint
_SMALL_FORMS = {"kinetic": "T", "potential": "U", "lagrangian": "L", "hamiltonian": "h"}
