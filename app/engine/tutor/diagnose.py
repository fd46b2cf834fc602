"""Name the mistake in a wrong answer: the catalogue of one step's mistakes, the match, and the words.

The catalogue of a step is the generated mistakes of ``app.engine.tutor.mistake_families``
(most specific first), then the rules every system invites (``app.engine.tutor.mistakes``),
then pairs of mistakes where the combinations are few (a generated mistake of T
together with the lost ½; a spring's natural length together with the sign of U).
Each comes with its values at the checker's sample points, computed once when
the problem is built (the service caches problems per system), and a mistake
whose values repeat an earlier one's (up to the step's accepted constant or
factor) or the truth's is dropped: the first name is the one given.

An answer matches a mistake when it equals it at every sample point, up to the
same constant or factor an answer may differ from the truth by.  When no
mistake matches, ``agreement`` compares the answer with the truth part by part
(the terms of each product of velocities and accelerations, and the rest) and
says which parts agree.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.derivation.dimensions import mismatch, system_dimensions
from app.engine.display.names import said_all
from app.engine.document.notation import inertia
from app.engine.document.notation import text as frequency_letter
from app.engine.tutor.compare import Groups, Values, differ_by_constant, differ_by_factor, equal, usable, values
from app.engine.tutor.mistake_carried import carried_equations, lagrangian_pairs
from app.engine.tutor.mistake_equations import generated
from app.engine.tutor.mistake_families import (
    Mistake,
    bodies_lumped,
    height_mistakes,
    monomial_words,
    says_how,
    spoken,
    states_answer,
)
from app.engine.tutor.mistake_masses import wrong_masses
from app.engine.tutor.mistake_other import held_still, other_coordinates
from app.engine.tutor.mistake_pieces import effective_terms, inertia_in_potential, masses_of, piece_mistakes, travelled
from app.engine.tutor.mistake_positions import position_mistakes
from app.engine.tutor.mistakes import OMEGA_HINT, RULES

MIN_POINTS = 6
MAX_PAIRS = 12
GENERIC = frozenset({"term_sign"})

# How a hint opens, by family: {what} is the step's label, {name} the mistake's name.
_OPENINGS = {
    "term_sign": "In your {what}, {name} is wrong",
    "force_sign": "In your {what}, {name} is wrong",
    "left_out": "Your {what} has {name}",
    "half_momentum": "Your {what} has {name}",
    "force_doubled": "Your {what} has {name}",
    "small_angle": "Your {what} uses {name}. That is an approximation, not a slip of algebra",
    "other_equilibrium": "This is {name}",
    "pair": "Your {what} has two mistakes: {name}",
    "counted_twice": "Your {what} has {name}",
    "doubled": "Your {what} has {name}",
    "halved": "Your {what} has {name}",
    "velocity_doubled": "Your {what} has {name}",
    "inner_sign": "Your {what} has {name}",
    "stretch_part": "Your {what} has {name}",
    "sin_cos": "Your {what} has {name}",
    "travelled": "Your {what} follows from {name}",
    "terms_left_out": "Your {what} has {name}",
    "rigid": "Your {what} has {name}",
    "factor_left_out": "Your {what} has {name}",
    "units": "Your {what} has {name}",
    "other_coordinate": "Your {what} is {name}",
    "limit": "Your {what} is {name}",
    "position_for_velocity": "Your {what} has {name}",
    "wrong_mass": "Your {what} has {name}",
    "momentum_part": "Your {what} has {name}",
    "position_carried": "Your {what} has {name}",
    "position_sign": "Your {what} has {name}",
    "position_other": "Your {what} is {name}",
    "position_coordinate": "Your {what} has {name}",
    "inertia_in_u": "Your {what} has {name}",
    "height_axis": "Your {what} has {name}",
    "height_squared": "Your {what} has {name}",
    "bodies_lumped": "Your {what} has {name}",
}


def sentence(m: Mistake, what: str) -> str:
    """The hint for a generated mistake: what went wrong, then where in the set-up it comes from."""
    # "your" said once: the opening has it, so the name's own "your term" is "the term" here
    name = re.sub(r"\byour\b", "the", m.name)
    # a family without its own opening names the piece left out, unless its name says how the piece is wrong
    default = "Your {what} has {name}" if says_how(name) else "Your {what} leaves out {name}"
    opening = _OPENINGS.get(m.family, default).format(what=what, name=name)
    return f"{opening}: {m.where}."


def _same(a: Values, b: Values, relation: str) -> bool:
    return (
        equal(a, b)
        or (relation == "constant" and differ_by_constant(a, b))
        or (relation == "factor" and differ_by_factor(a, b))
    )


def _legacy(d: Derivation, step: str, k: int | None, truth: sp.Expr) -> list[tuple[Mistake, str]]:
    out = []
    for rule in RULES:
        if step not in rule.steps:
            continue
        built = rule.build(d, step, k)
        if built is None or sp.expand(built - truth) == 0:
            continue
        hint = rule.hint
        if rule.mistake == "h_is_e":
            hint += _why_h_is_not_e(d)
        # the piece of an acceleration's mistake is too long to name: the difference shows it
        piece = None if step == "acceleration" else sp.expand(built - truth)
        out.append((Mistake(rule.mistake, rule.mistake, rule.name, piece, rule.hint, built), hint))
    return out


def _why_h_is_not_e(d: Derivation) -> str:
    """Which body's position depends on t itself (what makes h ≠ E here)."""
    for i, r in enumerate(d.mechanics.positions):
        if any(c.has(d.table.t) for c in r):
            label = d.system.particles[i].label if i < len(d.system.particles) else ""
            body = label or f"particle {i + 1}"
            shown = ", ".join(spoken(c) for c in r)
            return f" Here the {body}'s position ({shown}) depends on t itself."
    return ""


def catalogue(
    d: Derivation, step: str, k: int | None, truths: tuple[sp.Expr, ...], groups: Groups, relation: str, label: str
) -> tuple[tuple[Mistake, str, Values], ...]:
    """(mistake, hint, values) for every distinct mistake of the step, in the order they are tried."""
    truth = truths[0]
    if step == "position" and k is not None:
        # one component of one body (k = 3 × body + axis): its own mistakes only (app.engine.tutor.mistake_positions)
        own = [(m, sentence(m, label)) for m in position_mistakes(d, k // 3, k % 3)]
        return _kept(d, own, truths, groups, relation, label)
    asked = _asked(d, truths)
    made = [(m, sentence(m, label)) for m in generated(d, step, k, asked)]
    known = system_dimensions(d)
    # the mistakes of T and U carried into this step, and a rigid body's (backward: from the system's pieces)
    carried = [(m, sentence(m, label)) for m in travelled(d, step, k, truth, known, asked)]
    carried += [(m, sentence(m, label)) for m in effective_terms(d, asked)] if step == "omega_squared" else []
    pieces = [(m, sentence(m, label)) for m in piece_mistakes(d, step, k, truth)]
    if step == "potential":
        pieces += [(m, sentence(m, label)) for m in inertia_in_potential(d, truth, known)]
    # slips of T and U carried on into L, and an equation derived correctly from such an L (after the pieces: a
    # slip the step itself explains is named by that step's words)
    if step == "lagrangian":
        pieces += [(m, sentence(m, label)) for m in lagrangian_pairs(d, truth)]
    elif step == "equation" and k is not None:
        pieces += [(m, sentence(m, label)) for m in carried_equations(d, k, truth)]
    # the specific ones first, then the rules every system invites, then the truth's own pieces changed one at a
    # time, then a term's sign (which for a short expression is also the sign of everything else, and would hide
    # a rule's better name)
    # another question's right answer (another coordinate's, a body held still) is named as that, before all
    found = [(m, sentence(m, label)) for m in (*other_coordinates(d, step, k), *held_still(d, step, truth, k))]
    # a solved acceleration turned over whole is named one way on every system, before a rule's cause (the sign of
    # ∂L/∂q) that an answer typed as q̈ = … never shows; ω² after its other equilibria
    whole = [(m, sentence(m, label)) for m in whole_sign(d, step, truth)]
    found += whole if step == "acceleration" else []
    found += [x for x in made if x[0].family not in GENERIC]
    found += whole if step == "omega_squared" else []
    found += [x for x in carried if x[0].key.startswith(f"{step}.rigid")]
    found += _legacy(d, step, k, truth)
    found += [x for x in carried if not x[0].key.startswith(f"{step}.rigid")]
    # one body's mass swapped for another's (or for the total): before the pieces' factors, which would name it as
    # a term of the wrong size
    found += [(m, sentence(m, label)) for m in wrong_masses(d, step, truth, masses_of(d, known))]
    found += pieces
    # slips the step's own pieces do not explain, read from the positions (a height written wrong) and the
    # velocities (the bodies taken as one)
    if step == "potential":
        found += [(m, sentence(m, label)) for m in height_mistakes(d)]
    elif step == "kinetic":
        found += [(m, sentence(m, label)) for m in bodies_lumped(d)]
    found += [x for x in made if x[0].family in GENERIC]
    if step == "omega_squared":
        # in the document's letter for the frequency (Ω where ω is a parameter)
        w = frequency_letter("frequency", d)
        hint = OMEGA_HINT.format(w=w, i=inertia(d).unicode)
        found += [
            (Mistake("omega_not_squared", "omega_not_squared", f"{w} in place of {w}²", sp.sqrt(w2), hint,
                     sp.sqrt(w2)), hint)
            for w2 in truths
        ]  # fmt: skip
    found += _pairs(d, step, found, label)
    return _kept(d, found, truths, groups, relation, label)


def whole_sign(d: Derivation, step: str, truth: sp.Expr) -> list[Mistake]:
    """The whole of a solved acceleration or ω² with its sign reversed, and its likely cause: a U turned over."""
    if step not in ("acceleration", "omega_squared") or truth == 0:
        return []
    has_u = d.mechanics.U is not None and d.mechanics.U != 0
    if step == "acceleration":
        # every force is −∂U/∂q: U with its sign reversed turns each of them over, and the acceleration with them
        cause = (
            "The likely cause is U with its sign reversed: each force is −∂U/∂q, so a reversed U turns every force "
            "over. Else "
            if has_u
            else "Check "
        )
        where = (
            f"every term of yours has the opposite sign. {cause}check which way the coordinate counts as positive "
            "and that each term changed sign once as it crossed the equals sign"
        )
    else:
        # ω² = U_eff″/m_eff at the equilibrium: U turned over makes a minimum a maximum and turns ω² over, but only
        # where U_eff is U; where U_eff holds more (the rotating wire's −½ m ω² ρ²), a U turned over alone does not
        # give the whole answer turned over (it was said so on the rotating parabola)
        w = frequency_letter("frequency", d)
        red = d.reduction
        alone = red is None or not has_u or sp.simplify(red.effective_potential - d.mechanics.U) == 0
        where = (
            f"{w}² is the effective potential's second derivative over the {inertia(d).words}, at the equilibrium; "
            + ("the likely cause is U with its sign reversed, which turns a minimum into a maximum and "
               f"{w}² over" if has_u and alone else "check the sign of each term of the effective potential")
        )  # fmt: skip
    return [Mistake(f"{step}.whole_sign", "term_sign", "the sign of the whole answer", truth, where, -truth)]


def _kept(
    d: Derivation,
    found: list[tuple[Mistake, str]],
    truths: tuple[sp.Expr, ...],
    groups: Groups,
    relation: str,
    label: str,
) -> tuple[tuple[Mistake, str, Values], ...]:
    """Each mistake with its values, less one whose units disagree, one equal to a truth and a repeat."""
    known = system_dimensions(d)
    kept: list[tuple[Mistake, str, Values]] = []
    truth_values = [values(t, groups) for t in truths]
    for mistake, hint in found:
        if mismatch(mistake.expr, known, None, label) is not None:
            continue  # terms whose units disagree: the units name it first (app.engine.tutor.check)
        fu = mistake.follow_up
        if fu is not None and states_answer(" ".join((hint, mistake.name, mistake.where)), fu):
            # a question whose answer the line above it already prints is not asked ("of speed R α ż",
            # then "What is the bead's speed along x and y?")
            mistake = replace(mistake, follow_up=None)
        v = values(mistake.expr, groups)
        if any(usable(v, b) < MIN_POINTS or _same(v, b, relation) for b in truth_values):
            continue
        # a repeat of an earlier mistake's values is dropped; one equal to it only up to a factor is kept, since
        # the answer's own scale tells them apart (2 m g R sin θ beside m R² θ̈ is gravity counted twice, not
        # the ½ of m R² θ̈ lost)
        if any(
            equal(v, w)
            or (relation == "constant" and differ_by_constant(v, w))
            or (relation == "factor" and equal(_negated(v), w))  # the same equation moved to the other side
            for _, _, w in kept
        ):
            continue
        kept.append((mistake, hint, v))
    return tuple(kept)


def _asked(d: Derivation, truths: tuple[sp.Expr, ...]) -> list:
    red = d.reduction
    return [e for e in red.equilibria if e.omega_squared in truths] if red is not None else []


def _pairs(d: Derivation, step: str, found: list[tuple[Mistake, str]], label: str) -> list[tuple[Mistake, str]]:
    """Two mistakes at once, where the combinations are few."""
    out = []
    if step == "kinetic":
        for m, _ in found:
            if m.count == 1 and m.family in ("velocity_part", "moving_constraint", "cross_term", "body_forgotten"):
                pair = replace(
                    m,
                    key=f"{m.key}+missing_half",
                    family="pair",
                    name=f"{m.name} is left out, and the ½ of ½ m v² is missing",
                    expr=2 * m.expr,
                    count=2,
                )
                out.append((pair, sentence(pair, label)))
    elif step == "potential":
        for m, _ in found:
            if m.family == "natural_length":
                pair = replace(
                    m,
                    key=f"{m.key}+sign_of_u",
                    family="pair",
                    name=f"{m.name} is left out, and the sign of U is reversed",
                    expr=-m.expr,
                    count=2,
                )
                out.append((pair, sentence(pair, label)))
    return out[:MAX_PAIRS]


def match(
    catalogue_: tuple[tuple[Mistake, str, Values], ...],
    a: Values,
    b: Values,
    relation: str,
    scaled: Values | None = None,
    keep: Callable[[Mistake], bool] | None = None,
) -> tuple[Mistake, str] | None:
    """The mistake the answer's values match: first one it equals as written, then (an equation) one it equals
    at the engine's coefficient of the acceleration (``scaled``), then the first up to the step's accepted
    constant or factor; a mistake ``keep`` refuses is never given."""
    tried = [(m, h, v) for m, h, v in catalogue_ if usable(a, v) >= MIN_POINTS and not equal(v, b)]
    negated = _negated(a) if relation == "factor" else None
    for test in (lambda v: equal(a, v), lambda v: negated is not None and equal(negated, v),
                 lambda v: scaled is not None and equal(scaled, v), lambda v: _same(a, v, relation)):  # fmt: skip
        for mistake, hint, v in tried:
            if test(v) and (keep is None or keep(mistake)):
                return mistake, hint
    return None


def _negated(a: Values) -> Values:
    """An equation moved to the other side: every value's sign reversed."""
    return [[[None if x is None else -x for x in block] for block in draw] for draw in a]


def mistake_json(m: Mistake, tex, difference: str = "") -> dict[str, Any]:
    """The API's ``mistake``: a stable key for records, display text, the piece typeset (the difference's
    LaTeX where the piece is not named) and where it comes from."""
    return {
        "key": m.key,
        "family": m.family,
        # the piece left out said "left out", one added "added" (mistake_families.said)
        "name": m.said,
        "latex": tex(m.piece) if m.piece is not None else difference,
        "where": m.where,
        "approximation": m.approximation,
        "count": m.count,
    }


def partial_json(m: Mistake, label: str) -> dict[str, Any]:
    message = (
        f"Everything else in your {label} is right."
        if m.count == 1
        else f"Apart from these {m.count} mistakes, everything else in your {label} is right."
    )
    return {"message": message, "agree": [], "differ": []}


def follow_up_json(m: Mistake, names: list[str]) -> dict[str, Any] | None:
    if m.follow_up is None:
        return None
    # kind: the step whose names the reply may use, and how it is typeset
    # names_said: each name as the page prints it, with how it is typed once (θ̇ (type theta_dot))
    return {"key": m.key, "question": m.follow_up.question, "names": names, "names_said": said_all(names),
            "kind": m.follow_up.kind}  # fmt: skip


# ---- part by part ------------------------------------------------------------------------------


def agreement(
    answer: sp.Expr, truth: sp.Expr, groups: Groups, step: str, rescale: bool = False
) -> dict[str, Any] | None:
    """Which parts of the answer agree with the truth: the terms of each product of rates, and the rest.

    Both are split by their products of velocities and accelerations (θ̇², θ̇ φ̇, θ̈, none); each
    part's coefficient is compared at the sample points.  None when the answer is not a polynomial in
    the rates or has a single part.  With ``rescale`` (an equation, right up to a factor) the truth is
    taken at the scale where the most parts agree: unscaled first, then each part's own ratio (a number
    before an expression), so that a wrong part is never the yardstick the right ones are measured by.
    """
    rates = groups.rates
    try:
        mine, theirs = rate_parts(answer, rates), rate_parts(truth, rates)
    except (sp.PolynomialError, ValueError, TypeError):
        return None
    if mine is None or theirs is None:
        return None
    monomials = sorted(set(mine) | set(theirs), key=sp.default_sort_key)
    if len(monomials) < 2:
        return None
    zero = sp.Integer(0)
    pairs = [(m, values(mine.get(m, zero), groups), theirs.get(m, zero)) for m in monomials]
    best: tuple[list[str], list[str]] | None = None
    for scale in part_scales(mine, theirs, groups) if rescale else (sp.Integer(1),):
        agree: list[str] = []
        differ: list[str] = []
        for monomial, a, coefficient in pairs:
            (agree if equal(a, values(scale * coefficient, groups)) else differ).append(monomial_words(monomial))
        if best is None or len(agree) > len(best[0]):
            best = agree, differ
    agree, differ = best  # type: ignore[misc]
    if not agree:
        return {"message": "No part of your answer agrees with the correct one yet.", "agree": [], "differ": differ}
    return {
        "message": f"Part by part: {listed(agree)} agree with the correct ones; {listed(differ)} do not.",
        "agree": agree,
        "differ": differ,
    }


def part_scales(mine: dict[sp.Expr, sp.Expr], theirs: dict[sp.Expr, sp.Expr], groups: Groups) -> list[sp.Expr]:
    """The scales an equation's truth is tried at: 1, then each shared part's ratio answer / truth (numbers first),
    each free of the rates."""
    ratios = [sp.cancel(mine[m] / theirs[m]) for m in mine if m in theirs and theirs[m] != 0 and mine[m] != 0]
    kept = [r for r in ratios if r != 0 and not (r.free_symbols & set(groups.rates))]
    out = [sp.Integer(1)]
    for r in sorted(kept, key=lambda r: bool(r.free_symbols)):  # (a stable sort: numbers first, else in order)
        if r not in out:
            out.append(r)
    return out


def listed(groups: list[str]) -> str:
    """Groups of terms as a reader lists them: "a", "a and b", "a, b and c"."""
    return ", ".join(groups) if len(groups) < 2 else f"{', '.join(groups[:-1])} and {groups[-1]}"


def rate_parts(expr: sp.Expr, rates: tuple[sp.Symbol, ...]) -> dict[sp.Expr, sp.Expr] | None:
    present = [r for r in rates if expr.has(r)]
    expanded = sp.expand(expr)
    out: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(expanded):
        coefficient, monomial = term.as_independent(*present, as_Add=False) if present else (term, sp.Integer(1))
        if monomial != 1 and not all(b in rates and e.is_Integer for b, e in monomial.as_powers_dict().items()):
            return None
        out[monomial] = out.get(monomial, sp.Integer(0)) + coefficient
    return out
