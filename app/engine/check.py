"""Check a student's own step against the engine's derivation.

A *problem* is one step of one system (``kinetic``, ``potential``, ``lagrangian``,
``momentum``, ``equation``, ``acceleration``, ``hamiltonian``, ``omega_squared``;
the middle three per coordinate): the engine's expression for it (the truth),
how answers may legitimately differ from it, the names an answer may use, and
the mistaken expressions of ``app.engine.mistakes``. A problem holds SymPy
objects only, so it can be built where the derivation lives and sent to a
worker process with the student's text. (``app.engine.exercises`` lists a
system's steps for a practice page.)

``judge`` parses the text with the project's parser (app/engine/parse.py), then
compares (app/engine/compare.py):

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
"""

from __future__ import annotations

import re
from collections import OrderedDict
from dataclasses import dataclass
from typing import Any

import sympy as sp

from app.engine.budget import BudgetExceeded, display_budget, tidy, time_limit
from app.engine.compare import (
    Groups,
    Values,
    differ_by_constant,
    differ_by_factor,
    equal,
    factor_is_constant,
    mistake_only,
    symbolically_zero,
    usable,
    values,
    without_constant,
)
from app.engine.derive import Derivation
from app.engine.diagnose import (
    agreement,
    catalogue,
    follow_up_json,
    match,
    mistake_json,
    partial_json,
)
from app.engine.mistake_families import Mistake
from app.engine.mistakes import CONSTANT_FACTOR_HINT, MISSING_FACTOR_HINT, POINTERS
from app.engine.parse import ExpressionError, check_expression, parse_expression
from app.engine.reality import real_somewhere
from app.engine.report import Printer, display, plain_name
from app.engine.textbook import unicode_text
from app.limits import CHECK_DISPLAY_SECONDS as DISPLAY_SECONDS
from app.limits import DIFFERENCE_SECONDS, FACTOR_SECONDS, PARTS_SECONDS

STEPS = ("kinetic", "potential", "lagrangian", "momentum", "equation", "acceleration", "hamiltonian", "omega_squared")
PER_COORDINATE = frozenset({"momentum", "equation", "acceleration"})
# how an answer may differ from the truth and still be physically the same
RELATIONS = {"potential": "constant", "lagrangian": "constant", "hamiltonian": "constant", "equation": "factor"}
MIN_POINTS = 6  # sample points where both sides are defined, for a numeric verdict
# the steps whose answers are polynomials in the rates, compared part by part when no mistake matches
PARTED = frozenset({"kinetic", "lagrangian", "momentum", "equation", "hamiltonian"})

# which kinds of name each step's answer may use
_KINDS = {
    "kinetic": {"parameter", "position", "velocity"},
    "potential": {"parameter", "position"},
    "lagrangian": {"parameter", "position", "velocity"},
    "momentum": {"parameter", "position", "velocity"},
    "equation": {"parameter", "position", "velocity", "acceleration"},
    "acceleration": {"parameter", "position", "velocity"},
    "hamiltonian": {"parameter", "position", "velocity"},
    "omega_squared": {"parameter", "momentum"},
}
_WHY_NOT = {
    ("potential", "velocity"): "U depends on positions only, so a velocity cannot appear in it",
    ("acceleration", "acceleration"): "the acceleration is what you solve for: write it with the coordinates, "
    "velocities, parameters and t, without any q_ddot",
    ("omega_squared", "position"): "ω² at an equilibrium is a constant: write it with the parameters "
    "(and conserved momenta p_q) only",
    ("omega_squared", "velocity"): "ω² at an equilibrium is a constant: write it with the parameters "
    "(and conserved momenta p_q) only",
    ("omega_squared", "acceleration"): "ω² at an equilibrium is a constant: write it with the parameters "
    "(and conserved momenta p_q) only",
}
_IDENTIFIER = re.compile(r"\b[A-Za-z_][A-Za-z0-9_]*")


class CheckError(ExpressionError):
    """A check request refused; ``field`` is ``step``, ``coordinate`` or ``answer``."""

    def __init__(self, message: str, field: str, part: str = "", start: int | None = None, end: int | None = None):
        super().__init__(message, part, start, end)
        self.field = field

    def __reduce__(self):
        return (type(self), (str(self), self.field, self.part, self.start, self.end))


def name_kinds(coordinates: tuple[str, ...], parameters: tuple[str, ...], momenta: tuple[str, ...]) -> dict[str, str]:
    """Every name a check may mention, with its kind."""
    kinds = {p: "parameter" for p in parameters}
    kinds.update({p: "momentum" for p in momenta})
    kinds["t"] = "position"
    for q in coordinates:
        kinds.update({q: "position", f"{q}_dot": "velocity", f"{q}_ddot": "acceleration"})
    return kinds


def allowed_names(step: str, kinds: dict[str, str]) -> list[str]:
    return sorted(name for name, kind in kinds.items() if kind in _KINDS[step])


def check_answer(text: str, step: str, kinds: dict[str, str]) -> None:
    """Refuse an answer the step cannot take, in pure Python (the parser's gates 1 and 2 plus name rules)."""
    if isinstance(text, str):
        for match in _IDENTIFIER.finditer(text[:4000]):
            kind = kinds.get(match.group())
            if kind is not None and kind not in _KINDS[step]:
                why = _WHY_NOT.get((step, kind)) or (
                    "an acceleration appears only in the equation step"
                    if kind == "acceleration"
                    else f"a {kind} cannot appear in this step"
                )
                raise CheckError(
                    f"answer: {why}: {match.group()!r} at column {match.start() + 1}",
                    "answer",
                    match.group(),
                    match.start(),
                    match.end(),
                )
    try:
        check_expression(text, allowed_names(step, kinds))
    except ExpressionError as exc:
        raise CheckError(f"answer: {exc}", "answer", exc.part, exc.start, exc.end) from None


@dataclass(frozen=True)
class Problem:
    """One step of one system, ready to judge answers against."""

    step: str
    coordinate: str | None
    label: str
    truths: tuple[sp.Expr, ...]
    where: tuple[str, ...]  # for ω²: the equilibrium each truth belongs to
    relation: str
    kinds: dict[str, str]
    namespace: dict[str, sp.Symbol]
    groups: Groups
    mistakes: tuple[tuple[Mistake, str, Values], ...]  # (mistake, hint, its values at the sample points)
    latex_names: dict[sp.Symbol, str]
    acceleration: sp.Symbol | None = None

    def mistake(self, key: str) -> Mistake | None:
        return next((m for m, _, _ in self.mistakes if m.key == key), None)


def conserved_momenta(d: Derivation) -> tuple[sp.Symbol, ...]:
    return d.reduction.momenta if d.reduction is not None else ()


def checkable_equilibria(d: Derivation) -> list:
    """Equilibria whose ω² a student can be asked for: not known to be unstable."""
    red = d.reduction
    return [e for e in red.equilibria if e.stable is not False] if red is not None else []


def exercises(d: Derivation) -> list[tuple[str, str | None]]:
    """The steps a student can check for this system, in the chapter's order."""
    out: list[tuple[str, str | None]] = []
    for step in STEPS:
        if step in ("kinetic", "potential") and d.mechanics.T is None:
            continue
        if step == "omega_squared" and not checkable_equilibria(d):
            continue
        if step in PER_COORDINATE:
            out += [(step, name) for name in d.table.names]
        else:
            out.append((step, None))
    return out


def _unavailable(d: Derivation, step: str) -> str:
    if step in ("kinetic", "potential"):
        return "this system is given by its Lagrangian alone, so T and U are not known separately"
    return "this system has no equilibrium with a closed-form ω² that is not unstable"


def _label(step: str, name: str | None, d: Derivation) -> str:
    shown = plain_name(name) if name else ""
    return {
        "kinetic": "kinetic energy T",
        "potential": "potential energy U",
        "lagrangian": "Lagrangian L",
        "momentum": f"momentum p_{shown}",
        "equation": f"Euler–Lagrange equation for {shown}",
        "acceleration": f"acceleration of {shown}",
        "hamiltonian": "Hamiltonian h",
        "omega_squared": "ω² of small oscillations",
    }[step]


def problem(d: Derivation, step: str, coordinate: str | None = None, mistakes: bool = True) -> Problem:
    """The problem for one step (a CheckError naming the field when the step or coordinate does not apply).

    With ``mistakes`` the step's catalogue of mistakes is generated and evaluated at the sample points
    (``app.engine.diagnose``): the costly part, done once per system and step by the service.
    """
    table, eqs = d.table, d.equations
    available = exercises(d)
    steps = list(dict.fromkeys(s for s, _ in available))
    if step not in STEPS:
        raise CheckError(
            f"step: unknown step {str(step)[:40]!r}; the steps are: {', '.join(steps)}", "step", str(step)[:40]
        )
    if step not in steps:
        raise CheckError(
            f"step: {step!r} does not apply: {_unavailable(d, step)}; the steps are: {', '.join(steps)}", "step", step
        )
    k = None
    if step in PER_COORDINATE:
        names = ", ".join(table.names)
        if not coordinate:
            raise CheckError(f"coordinate: the {step} step is per coordinate; give one of: {names}", "coordinate")
        if coordinate not in table.names:
            raise CheckError(
                f"coordinate: {str(coordinate)[:40]!r} is not a coordinate of this system; the coordinates are: {names}",
                "coordinate",
                str(coordinate)[:40],
            )
        k = table.names.index(coordinate)
    else:
        coordinate = None

    where: tuple[str, ...] = ()
    if step == "kinetic":
        truths = (d.mechanics.T,)
    elif step == "potential":
        truths = (d.mechanics.U,)
    elif step == "lagrangian":
        truths = (d.mechanics.L,)
    elif step == "momentum":
        truths = (eqs.momenta[k],)  # type: ignore[index]
    elif step == "equation":
        truths = (eqs.residuals[k],)  # type: ignore[index]
    elif step == "acceleration":
        truths = (eqs.accelerations[k],)  # type: ignore[index]
    elif step == "hamiltonian":
        truths = (d.energetics.hamiltonian,)
    else:
        found = checkable_equilibria(d)
        truths = tuple(e.omega_squared for e in found)
        r = d.reduction.coordinate  # type: ignore[union-attr]
        where = tuple(f"{plain_name(r)} = {unicode_text(e.position)}" for e in found)

    momenta = conserved_momenta(d)
    kinds = name_kinds(table.names, table.parameter_names, tuple(p.name for p in momenta))
    namespace = {**table.namespace(), **{s.name: s for s in table.qdd}, **{p.name: p for p in momenta}}
    groups = Groups((*table.params, *momenta), (*table.q, table.t), (*table.qd, *table.qdd))
    latex_names = {**table.latex_names(), **{p: sp.latex(p) for p in momenta}}
    label = _label(step, coordinate, d)
    relation = RELATIONS.get(step, "exact")
    return Problem(
        step,
        coordinate,
        label,
        truths,
        where,
        relation,
        kinds,
        namespace,
        groups,
        catalogue(d, step, k, truths, groups, relation, _short_label(step, label)) if mistakes else (),
        latex_names,
        table.qdd[k] if step == "equation" and k is not None else None,
    )


def _short_label(step: str, label: str) -> str:
    """The label as a hint names it: 'T', 'U', 'equation for θ'."""
    return {"kinetic": "T", "potential": "U", "lagrangian": "L", "hamiltonian": "h"}.get(
        step, label.replace("Euler–Lagrange ", "")
    )


def parse_answer(pb: Problem, text: str, kind: str | None = None) -> sp.Expr:
    """The answer in SymPy (CheckError on the ``answer`` field when it is not allowed); ``kind`` is the step
    whose names it may use (a follow-up question's), by default the problem's own."""
    kind = kind or pb.step
    check_answer(text, kind, pb.kinds)
    allowed = set(allowed_names(kind, pb.kinds))
    try:
        return real_somewhere(text, parse_expression(text, {n: s for n, s in pb.namespace.items() if n in allowed}))
    except ExpressionError as exc:
        raise CheckError(f"answer: {exc}", "answer", exc.part, exc.start, exc.end) from None


def _budgeted(work, fallback, seconds: float):
    try:
        with time_limit(seconds):
            return work()
    except (BudgetExceeded, RecursionError, TypeError, ValueError, NotImplementedError, ZeroDivisionError):
        return fallback


def _verdict(
    verdict: str, message: str, difference: dict[str, str] | None = None, hint: str | None = None, **more: Any
) -> dict[str, Any]:
    return {
        "verdict": verdict,
        "message": message,
        "difference": difference,
        "hint": hint,
        "mistake": more.get("mistake"),
        "partial": more.get("partial"),
        "follow_up": more.get("follow_up"),
    }


def _noun(pb: Problem) -> str:
    return f"the engine's {pb.label}" + (f" (at {pb.where[0]})" if pb.where else "")


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


def judge(pb: Problem, text: str) -> dict[str, Any]:
    """The verdict on one answer: ``{"verdict", "message", "difference", "hint"}``."""
    answer = parse_answer(pb, text)
    printer = Printer(pb.latex_names)
    a = values(answer, pb.groups)
    results = [(truth, _known(truth, pb.groups)) for truth in pb.truths]
    numeric = [(truth, b) for truth, b in results if usable(a, b) >= MIN_POINTS]

    for i, (truth, b) in enumerate(results):
        if (truth, b) in numeric:
            same = equal(a, b)
        else:
            # too few points where both are defined: decide symbolically within the budget
            same = symbolically_zero(answer - truth) is True
        if same:
            at = f" at {pb.where[i]}" if pb.where else ""
            return _verdict("correct", f"Correct: this is the engine's {pb.label}{at}.")

    for truth, b in numeric:
        if pb.relation == "constant" and differ_by_constant(a, b):
            return _verdict("equivalent", _constant_message(pb, answer - truth))
        if pb.relation == "factor" and differ_by_factor(a, b):
            return _verdict("equivalent", _factor_message(pb, answer, truth, factor_is_constant(a, b)))

    truth, b = results[0]
    with display_budget(DISPLAY_SECONDS):
        difference, how = _difference(pb, answer, truth)
        # the mistake only: what cancels identically gone, trigonometry recombined; where that did not apply
        # (a long difference, an acceleration's), the display's own simplification
        only = mistake_only(difference, DIFFERENCE_SECONDS)
        shown = printer.pair(display(difference) if only is difference else only)
    message = f"Incorrect: this is not {_noun(pb)}{how}. The difference (yours − the engine's) is shown."
    found = match(pb.mistakes, a, b, pb.relation)
    if found is not None:
        mistake, hint = found
        return _verdict(
            "incorrect",
            message,
            shown,
            hint,
            mistake=mistake_json(mistake, printer.tex, shown["latex"]),
            partial=partial_json(mistake, _short_label(pb.step, pb.label)),
            follow_up=follow_up_json(mistake, allowed_names(mistake.follow_up.kind, pb.kinds))
            if mistake.follow_up
            else None,
        )
    # no known mistake: say which parts agree (against the truth at the answer's scale)
    partial = (
        _budgeted(lambda: agreement(answer, answer - difference, pb.groups, pb.step), None, PARTS_SECONDS)
        if pb.step in PARTED
        else None
    )
    return _verdict("incorrect", message, shown, _hint(pb, answer, a, b, truth), partial=partial)


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


def judge_follow_up(pb: Problem, key: str, text: str) -> dict[str, Any]:
    """The verdict on the answer to a named mistake's follow-up question (a CheckError when it has none)."""
    mistake = follow_up_mistake(pb, key)
    fu = mistake.follow_up
    assert fu is not None  # follow_up_mistake refuses a mistake without a question
    answer = parse_answer(pb, text, fu.kind)
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
            f"Correct: {fu.answer_text or sp.sstr(fu.truth)}. Now put it back into your {pb.label}.",
            hint=None,
            mistake=mistake_json(mistake, printer.tex),
        )
    return _verdict(
        "incorrect",
        f"Not yet: that is not the answer to “{fu.question}”",
        hint=f"Think of where it comes from: {mistake.where}.",
        mistake=mistake_json(mistake, printer.tex),
        follow_up=follow_up_json(mistake, allowed_names(fu.kind, pb.kinds)),
    )


def _constant_message(pb: Problem, difference: sp.Expr) -> str:
    varying, constant = without_constant(difference, pb.groups.dynamic())
    shown = constant if symbolically_zero(varying) else None
    amount = f"the constant {unicode_text(shown)}" if shown is not None else "a constant"
    why = {
        "potential": "a different zero of height, which changes no force and no equation of motion",
        "lagrangian": "a constant drops out of every Euler–Lagrange equation",
        "hamiltonian": "the zero of U moved, which changes no equation of motion",
    }[pb.step]
    return f"Equivalent: your {pb.label} is the engine's plus {amount}: {why}."


def _factor_message(pb: Problem, answer: sp.Expr, truth: sp.Expr, constant: bool) -> str:
    factor = _budgeted(lambda: tidy(sp.cancel(answer / truth), FACTOR_SECONDS), None, FACTOR_SECONDS * 2)
    rates = set(pb.groups.rates)
    named = f"{unicode_text(factor)}" if factor is not None and not (factor.free_symbols & rates) else "a factor"
    if constant:
        return (
            f"Equivalent: your equation is the engine's {pb.label} multiplied by {named}, "
            "which is not zero, so it has the same solutions."
        )
    return (
        f"Equivalent: your equation is the engine's {pb.label} multiplied by {named}, which depends on the "
        "coordinates: the same equation wherever that factor is not zero."
    )


def _difference(pb: Problem, answer: sp.Expr, truth: sp.Expr) -> tuple[sp.Expr, str]:
    """answer − truth, less an accepted constant, or against the truth rescaled to the answer's q̈ coefficient."""
    if pb.relation == "constant":
        varying, _ = without_constant(answer - truth, pb.groups.dynamic())
        if varying != 0:
            return varying, " (a constant, which would only move the zero of U, is left out)"
        return answer - truth, ""
    if pb.relation == "factor" and pb.acceleration is not None:
        mine, theirs = sp.diff(answer, pb.acceleration), sp.diff(truth, pb.acceleration)
        if mine != 0 and theirs != 0:
            scale = _budgeted(lambda: sp.cancel(mine / theirs), None, FACTOR_SECONDS)
            if scale is not None and scale != 1 and not (scale.free_symbols & set(pb.groups.rates)):
                how = f", even after scaling it by {unicode_text(scale)} to match your coefficient of the acceleration"
                return answer - scale * truth, how
    return answer - truth, ""


def _hint(pb: Problem, answer: sp.Expr, a, b, truth: sp.Expr) -> str:
    """The hint when no known mistake matches: a missing factor of a momentum, else the step's rule."""
    if pb.step == "momentum" and differ_by_factor(b, a):
        # the engine's momentum is the answer times a factor free of the velocities: a factor is missing
        factor = _budgeted(lambda: tidy(sp.cancel(truth / answer), FACTOR_SECONDS), None, FACTOR_SECONDS * 2)
        if factor is not None:
            template = CONSTANT_FACTOR_HINT if factor_is_constant(b, a) else MISSING_FACTOR_HINT
            return template.format(factor=unicode_text(factor))
    return POINTERS[pb.step]
