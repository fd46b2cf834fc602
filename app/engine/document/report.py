"""The derivation as data: ordered steps and the API's JSON contract.

Every step is ``{"key", "title", "latex", "sympy", "explanation"}``; templates only
loop over them.  ``key`` identifies the step (``euler-lagrange``; ``derivatives:theta`` for one of a kind,
the part after the colon naming which), stable whatever its ``title`` says: the title is display text,
and a scene's reasons (app/scenes/reasons.py) and the document's placement of steps go by key.  ``sympy`` strings use the symbol convention (``q``, ``q_dot``,
``q_ddot``, ``t``, parameters by name) and parse with ``sympy.sympify``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp

from app.engine.algebra.budget import memoized, unbudgeted
from app.engine.algebra.simplify import is_zero, pythagoras
from app.engine.derivation import comparisons
from app.engine.derivation.derive import Derivation
from app.engine.display import meaning, textbook
from app.engine.display.breaking import broken, broken_row, single
from app.engine.display.forms import one_denominator, settle, textbook_form, use_names
from app.engine.display.names import unicode
from app.engine.display.root_forms import power_form, trig_cancelled
from app.engine.document import notation
from app.engine.document.action_step import KEY as ACTION_KEY
from app.engine.document.action_step import action_step
from app.engine.document.trees import maybe_of_sympy
from app.engine.equations.bodies import BodyMotion

# The steps (by key) a reader needs to follow the argument: T and U (where students go wrong most), the
# Lagrangian, its equations of motion, the accelerations and what is conserved.  The others are bookkeeping a
# page may fold away.
CORE_STEPS = frozenset(
    {"kinetic", "potential", "lagrangian", "generalized-forces", "euler-lagrange", "accelerations", "comparison", "cyclic",
     "h-vs-e", "energy-integral", ACTION_KEY}
)  # fmt: skip


@dataclass
class Printer:
    names: dict[sp.Symbol, str]

    def __post_init__(self) -> None:
        # expressions formed without a printer at hand (a step's sympy text) read coordinates from these names
        use_names(self.names)

    def form(self, expr: Any) -> Any:
        """The expression's textbook form (app.engine.display.forms): what both its text and its LaTeX show."""
        return textbook_form(expr, self.names)

    def tex(self, expr: Any, first: sp.Symbol | None = None) -> str:
        """LaTeX of the textbook form, in a textbook's order (``first``: the term holding it leads a sum)."""
        shown = self.form(expr)
        with unbudgeted():  # printing must not eat the simplifications' share of the display budget
            return textbook.latex(shown, self.names, first)

    def root(self, expr: Any) -> str:
        """LaTeX of a quantity holding a cube or fourth root, as a textbook writes it: one root of a single
        fraction, r₀ = (p_θ²/(m k))^{1/4}, never √|p_θ|/(∜m ∜k); else ``tex``."""
        found = self._root(expr)
        if found is not None:
            return rf"\left({self.tex(found[0])}\right)^{{1/{found[1]}}}"
        return self.tex(expr)

    def root_text(self, expr: Any) -> str:
        """``root`` as running text writes it: (p_θ²/(mk))^(1/4); else ``text``."""
        found = self._root(expr)
        if found is not None:
            return f"({self.text(found[0])})^(1/{found[1]})"
        return self.text(expr)

    def _root(self, expr: Any) -> tuple[sp.Expr, int] | None:
        """(C, n) where ``expr`` is the n-th root of a single fraction C free of roots and |·| (n = 3 or 4)."""
        if isinstance(expr, sp.Expr) and expr.free_symbols:
            # n: the root's degree, the least common multiple of the exponents' denominators
            exponents = [e.exp for e in expr.atoms(sp.Pow) if e.exp.is_Rational and not e.exp.is_Integer]
            n = math.lcm(*(int(e.q) for e in exponents))
            if n in (3, 4):
                power = sp.powsimp(sp.expand_power_base(expr**n, force=True), force=True)
                # |p|² is p² for a real p
                power = power.replace(
                    lambda e: e.is_Pow and isinstance(e.base, sp.Abs) and e.exp.is_even,
                    lambda e: e.base.args[0] ** e.exp,
                )
                power = sp.cancel(power)
                if not any(not e.exp.is_Integer for e in power.atoms(sp.Pow)) and not power.atoms(sp.Abs):
                    return power, n
        return None

    def text(self, expr: sp.Expr) -> str:
        """The textbook form of ``expr`` as running text writes it (a label, a sentence): its factors and terms in
        the order of the LaTeX ``pair`` prints for it (2gα − ω² beside 2 g α − ω², never SymPy's 2αg)."""
        return textbook.unicode_text(self.form(expr), self.names)

    def pair(self, expr: sp.Expr, first: sp.Symbol | None = None) -> dict[str, Any]:
        """An expression in the document: the text of its textbook form, the LaTeX of the same form, and the
        tree the browser evaluates (of the engine's own expression; None when it has none: a function
        outside the allowlist, or too large for a figure)."""
        shown = self.form(expr)
        with unbudgeted():
            tex = textbook.latex(shown, self.names, first)
        # a long result broken across lines, as in the steps (the results box is narrower than a step)
        return {"sympy": sp.sstr(shown), "latex": broken(tex), "tree": maybe_of_sympy(expr)}

    def shown(self, form: sp.Expr, tex: str, expr: sp.Expr) -> dict[str, Any]:
        """A pair for an expression already put in a display form of its own (an equation's scaled residual)."""
        return {"sympy": sp.sstr(form), "latex": single(tex), "tree": maybe_of_sympy(expr)}


def _aligned(rows: list[str]) -> str:
    """One row as it is; several rows stacked and aligned at their first '='.  A row wider than a page's box
    is broken across lines first (app.engine.display.breaking): its continuations (``\\quad + …``) and blocks of
    lines start at the alignment column."""
    rows = [line for row in rows for line in broken_row(row)]
    if len(rows) == 1:
        return rows[0]
    # rows holding a block of lines (an equation broken across lines) are set flush left, not at their '=';
    # so are equations that each read "… = 0" (Euler–Lagrange equations): aligned at "= 0" their left sides
    # start at ragged places, flush left they read as a textbook stacks them
    flush = any(row.startswith("\\begin{aligned}") for row in rows) or all(
        row.endswith(" = 0") and row.count(" = ") == 1 for row in rows
    )
    marked = [
        row.replace(" = ", " &= ", 1) if " = " in row and not flush and not row.startswith("\\quad") else "&" + row
        for row in rows
    ]
    return r"\begin{aligned}" + r" \\ ".join(marked) + r"\end{aligned}"


def plain_name(name: str) -> str:
    """A coordinate's name as a reader writes it in running text: theta -> θ, x1 -> x₁."""
    return unicode(name)


def _formed(sympy: Any) -> Any:
    """Every expression in a step's data in its textbook form (the form its LaTeX rows typeset)."""
    if isinstance(sympy, (list, tuple)):
        return type(sympy)(_formed(x) for x in sympy)
    return textbook_form(sympy)


def _step(key: str, title: str, rows: list[str], sympy: Any, explanation: str, formed: bool = False) -> dict[str, str]:
    """``key`` names the step whatever its title reads (see the module's docstring).  ``formed``: the data is already in the form the rows show (else each expression is put in its textbook
    form, as ``Printer.tex`` does for the rows)."""
    text = sympy if isinstance(sympy, str) else sp.sstr(sympy if formed else _formed(sympy))
    return {"key": key, "title": title, "latex": _aligned(rows), "sympy": text, "explanation": explanation}


def _mapping_step(
    key: str, title: str, mapping: dict[Any, Any], explanation: str, names: Printer, values: Printer | None = None
) -> dict[str, str]:
    """A step of rows ``name = value``, one for each pair of ``mapping``: the names printed by ``names``, the
    values by ``values`` (the same printer unless given)."""
    values = values or names
    rows = [f"{names.tex(name)} = {values.tex(value)}" for name, value in mapping.items()]
    return _step(key, title, rows, list(mapping.values()), explanation)


def display(expr: sp.Expr) -> sp.Expr:
    """The textbook form of an expression (app.engine.display.forms), with the current printer's names."""
    return textbook_form(expr) if isinstance(expr, sp.Expr) and expr.free_symbols else expr


def shown_accelerations(d: Derivation) -> list[sp.Expr]:
    """Each explicit acceleration as the document prints it (the accelerations step and the results box alike):
    grouped by coordinate where linear in them (app.engine.display.meaning), in its textbook form, all over one
    denominator when they have one (app.engine.display.forms.one_denominator)."""
    grouped = [meaning.by_coordinate(a, d.table.q) for a in d.equations.accelerations]
    return memoized("accelerations", tuple(grouped), lambda: one_denominator(grouped))


def equations(d: Derivation, pr: Printer) -> list[tuple[sp.Expr, str]]:
    """Each Euler–Lagrange equation as a textbook prints it, θ̈ + (g/R) sin θ = 0: the residual in its
    textbook form scaled for display (the equation residual = 0 is unchanged), and its LaTeX row."""
    return [(shown, row) for shown, row, _ in _scaled_equations(d, pr)]


def _scaled_equations(d: Derivation, pr: Printer) -> list[tuple[sp.Expr, str, sp.Expr]]:
    """``equations``' rows, each with the factor its residual was divided by (residual = factor × shown)."""
    # the results box and the steps show the same rows: worked out once per document
    key = (tuple(d.equations.residuals), tuple(d.table.qdd), tuple(pr.names.items()))
    return memoized("equations", key, lambda: _equations(d, pr))


def _equations(d: Derivation, pr: Printer) -> list[tuple[sp.Expr, str, sp.Expr]]:
    eqs = d.equations
    M, diagonal = eqs.mass_matrix, eqs.mass_matrix.is_diagonal()
    out = []
    for k, r in enumerate(eqs.residuals):
        own, residual = d.table.qdd[k], pr.form(r)
        with unbudgeted():
            shown, factor = textbook.scaled(residual, M[k, k], diagonal, pr.names, own)
            if diagonal and textbook.masses_summed(M[k, k]):
                # an inertia that adds masses is kept in sight, 𝓜 q̈ = f: (m₁ + m₂ + M/2) z̈ = (m₁ − m₂) g
                left, force = textbook.inertia_sides(shown, pr.names)
                shown = sp.Add(left, -force, evaluate=False)
                row = f"{textbook.latex(left, pr.names, first=own)} = {textbook.latex(force, pr.names)}"
                out.append((shown, row, factor))
                continue
            out.append((shown, f"{textbook.latex(shown, pr.names, first=own)} = 0", factor))
    return out


def equation_rows(d: Derivation, pr: Printer) -> list[str]:
    return [row for _, row in equations(d, pr)]


def equation_pairs(d: Derivation, pr: Printer) -> list[dict[str, Any]]:
    """The equations for the document: each one's text is the scaled residual its row typesets, and
    ``divided_by`` the factor it was divided by to be shown so (None when it is shown as derived), so that
    a reader can go from the rows shown to ℳq̈ = f: row k of ℳ and f is equation k times its factor."""
    scales = equation_scales(d, pr)
    out = []
    for k, ((shown, row), r) in enumerate(zip(equations(d, pr), d.equations.residuals, strict=True)):
        s = scales[k] if scales is not None else None
        factor = None if s is None or s == 1 else {"sympy": sp.sstr(s), "latex": pr.tex(s)}
        out.append({**pr.shown(shown, row, r), "divided_by": factor})
    return out


def equation_scales(d: Derivation, pr: Printer) -> list[sp.Expr] | None:
    """The one home of how each printed equation is scaled: residual k = (its printed form) × s_k, each s_k the
    factor common to its terms (the double pendulum's θ₁ equation: l₁); None when a factor would hold a
    coordinate or a rate (then the rows are not a constant rescaling of ℳq̈ = f and no factor is claimed)."""
    shown = _scaled_equations(d, pr)
    key = (tuple(d.equations.residuals), tuple(s for s, _, _ in shown))

    def scale(r: sp.Expr, s: sp.Expr, factor: sp.Expr) -> sp.Expr:
        # r/s in lowest terms: the factor the display divided by when r − factor·s multiplies out to zero (then
        # r/s and that factor are one rational function, and their lowest terms are the same), else r/s itself
        # (a form that used sin² + cos² = 1 is no rational multiple of r), cancelled as a whole (the slow way)
        return sp.factor(sp.cancel(factor if sp.expand(r - factor * s) == 0 else r / s))

    def scales() -> list[sp.Expr] | None:
        with unbudgeted():
            out = [scale(r, s, f) for r, (s, _, f) in zip(d.equations.residuals, shown, strict=True)]
        return None if any(s.free_symbols & {*d.table.q, *d.table.qd, *d.table.qdd} for s in out) else out

    return memoized("equation-scales", key, scales)


def lagrangian(d: Derivation, pr: Printer) -> sp.Expr:
    """L printed from the same pieces as T and U (T's form minus U's), or its own form when declared alone."""
    m = d.mechanics
    if m.T is None or m.U is None:
        return pr.form(m.L)
    return settle(pr.form(m.T) - pr.form(m.U), pr.names)


def energies(d: Derivation, pr: Printer) -> tuple[sp.Expr, sp.Expr]:
    """h and E printed from the same pieces as T and U: E = (T's form) + (U's form), and h the same sum
    when h = E (else h's own textbook form)."""
    m, en = d.mechanics, d.energetics
    if m.T is None or m.U is None:
        return pr.form(en.hamiltonian), pr.form(en.energy)
    energy = settle(pr.form(m.T) + pr.form(m.U), pr.names)
    same = en.h_equals_e and sp.expand(en.hamiltonian - en.energy) == 0
    return (energy if same else pr.form(en.hamiltonian)), energy


def momentum(d: Derivation, k: int) -> sp.Expr:
    """The k-th generalized momentum, ∂L/∂q̇ₖ, grouped by velocity: (M + m)Ẋ + mḊ cos α (``by_inertia``)."""
    return by_inertia(d, d.equations.momenta[k], d.table.qd)


def by_inertia(d: Derivation, expr: sp.Expr, rates: Sequence[sp.Symbol]) -> sp.Expr:
    """A momentum pₖ = Σⱼ 𝓜ₖⱼ q̇ⱼ + …, or its rate of change Σⱼ 𝓜ₖⱼ q̈ⱼ + …, grouped by ``rates`` with each
    coefficient, an entry of the mass matrix, in the form the mass matrix step prints it: one factor in one form
    throughout a derivation, m(1 + 4α²ρ²) ρ̇ and m(1 + 4α²ρ²) ρ̈ + 8mα²ρρ̇² beside 𝓜 = m(1 + 4α²ρ²). An
    expression not linear in them, or too large, in its own textbook form."""
    # each momentum is printed in the results, the Euler–Lagrange step and the momenta's step: grouped once
    return memoized("by-inertia", (expr, tuple(rates)), lambda: _by_inertia(d, expr, rates), charged=True)


def _by_inertia(d: Derivation, expr: sp.Expr, rates: Sequence[sp.Symbol]) -> sp.Expr:
    # pₖ = Σⱼ (∂pₖ/∂q̇ⱼ) q̇ⱼ + pₖ(q̇ = 0), each ∂pₖ/∂q̇ⱼ = 𝓜ₖⱼ formed as the mass matrix's entry is (not
    # factored on its own first: ``meaning.by_velocity``'s factoring was thrown away here, 0.9 s of a 5-link chain)
    split = meaning.linear_split(expr, rates)
    if split is None:
        return display(expr)
    held, coefficients, rest = split
    terms = [display(c) * s for c, s in zip(coefficients, held, strict=True)]
    # the form is kept as built: formed again, it would be multiplied out (mρ̇ + 4mα²ρ²ρ̇)
    return settle(sp.Add(*terms, display(rest)), d.table.latex_names())


def effective_potential(d: Derivation) -> sp.Expr:
    """U_eff as its centrifugal piece plus the potential's: p_θ²/(2mr²) + ½kr²; U itself, as the potential's
    step prints it, where U_eff is U (no momentum held, no constraint moving): the simple pendulum's
    mgR(1 − cos θ) in every step and in the results alike."""
    red = d.reduction
    assert red is not None
    if _is_potential(d, red.effective_potential):
        return d.mechanics.U
    return meaning.pieces(red.effective_potential, red.momenta, d.table.q)


def _is_potential(d: Derivation, expr: sp.Expr) -> bool:
    """Whether ``expr`` is the potential energy U (identically)."""
    U = d.mechanics.U
    return U is not None and sp.expand(expr - U) == 0


def conserved_form(d: Derivation, pr: Printer, expr: sp.Expr) -> sp.Expr:
    """A conserved quantity as a textbook writes it: the energy as the document's E (its bodies' and springs'
    pieces, T's form plus U's), h as the document's h, a momentum grouped by velocity."""
    en = d.energetics
    h, energy = energies(d, pr)
    if sp.expand(expr - en.energy) == 0:
        return energy
    if sp.expand(expr - en.hamiltonian) == 0:
        return h
    return display(meaning.by_velocity(expr, d.table.qd))


def _at_root(pr: Printer, expr: sp.Expr, r: sp.Symbol) -> str:
    """LaTeX of ``expr`` at the root r₀: printed in r (the form a coordinate gets) with r renamed r₀ where its
    name is a command (θ → θ₀); else the expression at the symbol r₀ is printed."""
    name = pr.tex(r)
    if re.fullmatch(r"\\[A-Za-z]+", name):
        return re.sub(re.escape(name) + r"(?![A-Za-z_])", lambda _: name + "_{0}", pr.tex(expr))
    return pr.tex(expr.xreplace({r: sp.Symbol(r.name + "0")}))


# the clause that says how coupled equations are shown: a scene's own reason for the step keeps it (contract.py)
SCALED_CLAUSE = "each is shown divided by the factor common to all its terms"


def _divided_by(d: Derivation, pr: Printer) -> str:
    """How equations coupled through their accelerations are shown: each divided by the factor common to its
    terms (the double pendulum's first by l₁, its second by m₂ l₂), said so that no reader wonders why they
    are scaled differently."""
    scales = equation_scales(d, pr)
    if scales is None:
        return "."
    said = [
        f"the {plain_name(n)} equation by {textbook.unicode_text(s)}"
        for n, s in zip(d.table.names, scales, strict=True)
        if s != 1
    ]
    if not said:
        return "."
    return f"; {SCALED_CLAUSE} (" + ", ".join(said) + ")."


def _undivided(d: Derivation, pr: Printer) -> str:
    """The end of the mass matrix's sentence: where the equations above are shown divided by factors, that
    its rows are theirs undivided (row k: equation k times the factor it was divided by)."""
    scales = equation_scales(d, pr)
    if scales is None or all(s == 1 for s in scales):
        return "."
    return (
        "; they are the equations above undivided: each row of the mass matrix and of f is that equation as shown "
        "times the factor it was divided by."
    )


def _common_factor(c: sp.Expr) -> sp.Expr:
    """A sum with a symbol common to all its terms, written with it taken out: R(1 − cos θ) for R − R cos θ
    (a sign alone is not taken out: −l₁ cos θ₁ − l₂ cos θ₂ stays)."""
    f = sp.factor_terms(c)
    rest = f.as_coeff_Mul()[1]
    return f if isinstance(rest, sp.Mul) and any(a.is_Symbol for a in rest.args) else c


def _power_tex(n: int) -> str:
    """The exponent of r₀ⁿ in LaTeX (nothing for n = 1)."""
    return "" if n == 1 else f"^{{{n}}}"


def _body_mark(bodies: tuple[BodyMotion, ...], i: int) -> str:
    """The subscript of body i's v_cm and I_cm: cm alone for one body, numbered for several."""
    return r"\mathrm{cm}" if len(bodies) == 1 else rf"\mathrm{{cm}},{i + 1}"


def _turning_squared(b: BodyMotion, pr: Printer, tex: bool = True) -> str:
    """The square of the body's turning rate written as the rate itself, θ̇² or (ẋ/R)², never ω² (the pages keep
    ω for frequencies), in LaTeX or (``tex`` false) in running text: a sign inside is dropped, as (−a)² = a²."""
    rate = -b.turning_rate if b.turning_rate.could_extract_minus_sign() else b.turning_rate
    if not tex:
        return f"{pr.text(rate)}²" if rate.is_Symbol else f"({pr.text(rate)})²"
    return f"{pr.tex(rate)}^{{2}}" if rate.is_Symbol else rf"\left({pr.tex(rate)}\right)^{{2}}"


def _bodies_step(bodies: tuple[BodyMotion, ...], pr: Printer, vector: str = r"\vec r") -> dict[str, str]:
    """Each rigid body's centre (``vector`` the page's position letter, app/engine/notation.position), the squared
    speed of its centre, its angular velocity and I_cm from the table."""
    rows: list[str] = []
    data: list[sp.Expr] = []
    for i, b in enumerate(bodies):
        cm = _body_mark(bodies, i)
        rows += [
            rf"{vector}_{{{cm}}} = \left({', '.join(pr.tex(_common_factor(c)) for c in b.centre)}\right)",
            rf"v_{{{cm}}}^2 = {pr.tex(b.speed_squared)}",
            rf"I_{{{cm}}} = {pr.tex(b.inertia)}",
        ]
        data += [*b.centre, b.speed_squared, b.inertia]
    named = "; ".join(
        f"the {b.body.label or b.body.kind} turns at the rate {pr.text(b.turning_rate)}, and its "
        f"I_cm = {pr.text(b.inertia)} is {_INERTIA_WORDS[b.body.kind]}"
        for b in bodies
    )
    return _step(
        "bodies",
        "Centre of mass and moment of inertia",
        rows,
        data,
        "A rigid body moves with its centre of mass and turns about it: the centre is placed and differentiated "
        f"like a mass; {named}.",
    )


# each kind's moment of inertia about its centre in words (the values: INERTIA in app/engine/equations/bodies.py)
_INERTIA_WORDS = {
    "rod": "that of a uniform rod turning end over end about its middle, a twelfth of its mass times its length squared",
    "disc": "that of a uniform disc turning about its axis, half its mass times its radius squared",
    "ring": "that of a thin ring, its whole mass at the radius from the axis",
    "sphere": "that of a uniform solid sphere about any axis through its centre, two fifths of its mass times its radius squared",
}


def _body_pieces(bodies: tuple[BodyMotion, ...], pr: Printer) -> list[str]:
    """One row per body: T_body = ½ M v_cm² + ½ I_cm θ̇² = its translation + its rotation."""
    rows = []
    for i, b in enumerate(bodies):
        cm = _body_mark(bodies, i)
        name = b.body.label or b.body.kind
        rotation = pr.tex(b.rotation)
        # a centre moving in two ways at once (a cylinder rolling on a sliding wedge) keeps its v_cm² whole, as a
        # textbook writes it: ½ m (Ẋ² + ṡ² + 2 Ẋ ṡ cos α), not m (½ Ẋ² + ½ ṡ² + Ẋ ṡ cos α)
        whole = isinstance(b.speed_squared, sp.Add) and sp.expand(b.mass * b.speed_squared / 2 - b.translation) == 0
        translation = (
            rf"\tfrac{{1}}{{2}} {pr.tex(b.mass)} \left({pr.tex(b.speed_squared)}\right)"
            if whole
            else pr.tex(b.translation)
        )
        # a centre on a fixed axle (a pulley's) does not move: its piece is 0, and the body only turns
        pieces = (
            rotation
            if b.translation == 0
            else translation + (rf" - {rotation[1:]}" if rotation.startswith("-") else rf" + {rotation}")
        )
        rows.append(
            rf"T_{{\mathrm{{{name}}}}} = \tfrac{{1}}{{2}} {pr.tex(b.mass)} v_{{{cm}}}^2 + \tfrac{{1}}{{2}} I_{{{cm}}}"
            rf" {_turning_squared(b, pr)} = {pieces}"
        )
    return rows


def _kinetic_explanation(m: Any, pr: Printer) -> str:
    """What T adds up: the particles' ½ m v², each body's translation and rotation, or T as declared."""
    if not m.positions and not m.bodies:
        return "The kinetic energy as declared."
    if not m.bodies:
        return "T adds up one half of mass times squared speed."
    pieces = "; ".join(
        f"the {b.body.label or b.body.kind}'s is ½ M v_cm² = {pr.text(b.translation)} for the motion of its "
        f"centre plus ½ I_cm {_turning_squared(b, pr, tex=False)} = {pr.text(b.rotation)} for its turning about the "
        "centre"
        for b in m.bodies
    )
    masses = " plus one half of mass times squared speed for each point mass" if m.positions else ""
    return f"T adds up each rigid body's two pieces{masses}: {pieces}."


def _comparison_step(d: Derivation, pr: Printer, acc: list[sp.Expr]) -> dict[str, str] | None:
    """Each acceleration beside a carried body's that slides without turning and beside the carrier held fixed
    (app/engine/derivation/comparisons.py), where a carried body rolls: the comparison its statement asks for."""
    slid = comparisons.sliding(d) if acc else None
    if slid is None:
        return None
    table = d.table
    rows, data = [], []
    body = next(b.body.label or b.body.kind for b in d.mechanics.bodies if b.rotation != 0)
    for k, q in enumerate(table.qdd):
        rows.append(rf"{pr.tex(q)} = {pr.tex(acc[k])}")
        rows.append(rf"{pr.tex(q)}_{{\text{{sliding}}}} = {pr.tex(display(slid[k]))}")
        data += [acc[k], slid[k]]
    fixed = []
    for M, limits in comparisons.held(d):
        for k, q in enumerate(table.qdd):
            if limits[k] is not None and limits[k] != 0:
                rows.append(rf"{pr.tex(q)}_{{{pr.tex(M)} \to \infty}} = {pr.tex(display(limits[k]))}")
                data.append(limits[k])
        fixed.append(f"with {pr.text(M)} → ∞")
    held = f", and the limit {' and '.join(fixed)}, where the body that carries it stays still" if fixed else ""
    return _step(
        "comparison",
        "The accelerations compared",
        rows,
        data,
        f"Each acceleration beside the same with the {body}'s turning left out, a body that slides without turning"
        f"{held}.",
    )


def build_steps(d: Derivation) -> list[dict[str, str]]:
    m, eqs, en, red, table = d.mechanics, d.equations, d.energetics, d.reduction, d.table
    pr = Printer(table.latex_names())
    qn = [pr.tex(s) for s in table.q]
    qdn = [pr.tex(s) for s in table.qd]
    qddn = [pr.tex(s) for s in table.qdd]
    steps: list[dict[str, str]] = []
    steps.append(action_step(d))  # Hamilton's principle first (app/engine/document/action_step.py)

    if m.positions:
        n = len(m.positions)
        label = (lambda i: rf"_{{{i + 1}}}") if n > 1 else (lambda i: "")

        def vectors(letter: str, of_masses: Any) -> tuple[list[str], list[tuple[sp.Expr, ...]]]:
            """Each mass's vector (its position or its velocity, ``letter`` in LaTeX) as a LaTeX row and as data."""
            rows = [
                # a common factor taken out, as a textbook writes a position: R(1 − cos θ), not −R cos θ + R
                rf"{letter}{label(i)} = \left({', '.join(pr.tex(_common_factor(c)) for c in vector)}\right)"
                for i, vector in enumerate(of_masses)
            ]
            return rows, [tuple(vector) for vector in of_masses]

        steps.append(
            _step(
                "positions",
                "Positions",
                # r⃗, or R⃗ where r is a parameter (the rolling cylinder's radius): app/engine/notation.position
                *vectors(notation.position(d)[0], m.positions),
                "Each mass is placed in Cartesian coordinates as a function of the generalized coordinates"
                + (
                    " and of time, because a constraint moves."
                    if any(c.has(table.t) for r in m.positions for c in r)
                    else "."
                ),
            )
        )
        steps.append(
            _step(
                "velocities",
                "Velocities",
                *vectors(r"\vec v", m.velocities),
                "Differentiating each position along the motion (chain rule through every coordinate) gives its velocity.",
            )
        )
        steps.append(
            _step(
                "squared-speeds",
                "Squared speeds",
                [rf"v{label(i)}^2 = {pr.tex(v2)}" for i, v2 in enumerate(m.speeds_squared)],
                list(m.speeds_squared),
                "The dot product of each velocity with itself"
                # the identity is named only where a sine or cosine was there to use it on
                + (
                    ", after using sin² + cos² = 1."
                    if any(c.has(sp.sin, sp.cos) for r in m.positions for c in r)
                    else "."
                ),
            )
        )
    if m.bodies:
        steps.append(_bodies_step(m.bodies, pr, notation.position(d)[0]))
    if m.T is not None:
        steps.append(
            _step(
                "kinetic",
                "Kinetic energy",
                [*_body_pieces(m.bodies, pr), f"T = {pr.tex(m.T)}"],
                m.T,
                _kinetic_explanation(m, pr),
            )
        )
        steps.append(
            _step(
                "potential",
                "Potential energy",
                [f"U = {pr.tex(m.U)}"],
                m.U,
                # said only where it is true: a driven support puts t in U
                "The potential energy depends on positions only."
                if m.U is None or not m.U.has(d.table.t)
                else "The potential energy depends on the positions and, explicitly, on the time t.",
            )
        )
    steps.append(
        _step(
            "lagrangian",
            "Lagrangian",
            [f"L = {pr.tex(lagrangian(d, pr))}"],
            lagrangian(d, pr),
            "The Lagrangian is kinetic minus potential energy." if m.T is not None else "The Lagrangian as declared.",
        )
    )

    for k, name in enumerate(table.names):
        g = eqs.dL_dq[k]
        # d/dt ∂L/∂q̇ = Σⱼ 𝓜ₖⱼ q̈ⱼ + …, its inertia printed as the momentum's
        rate_of_momentum = by_inertia(d, eqs.ddt_momenta[k], table.qdd)
        steps.append(
            _step(
                f"derivatives:{name}",
                f"Derivatives for {plain_name(name)}",
                [
                    rf"\frac{{\partial L}}{{\partial {qn[k]}}} = {pr.tex(display(g))}",
                    # ∂L/∂q̇ is the momentum: printed in its form, m(1 + 4α²ρ²) ρ̇, not mρ̇ + 4mα²ρ²ρ̇
                    rf"\frac{{\partial L}}{{\partial {qdn[k]}}} = {pr.tex(momentum(d, k))}",
                    rf"\frac{{d}}{{dt}}\left(\frac{{\partial L}}{{\partial {qdn[k]}}}\right) = {pr.tex(rate_of_momentum)}",
                ],
                [display(g), momentum(d, k), rate_of_momentum],
                "The two partial derivatives the Euler–Lagrange equation needs, and the total time derivative of the second.",
            )
        )
    if any(f != 0 for f in m.Q):
        steps.append(
            _step(
                "generalized-forces",
                "Generalized forces",
                [f"Q_{{{qn[k]}}} = {pr.tex(f)}" for k, f in enumerate(m.Q)],
                list(m.Q),
                "Forces that no potential describes enter on the right: d/dt ∂L/∂q̇ − ∂L/∂q = Q.",
            )
        )
    shown_equations = equations(d, pr)
    Mt, Mu = notation.letter("mass_matrix", d), notation.text("mass_matrix", d)
    steps.append(
        _step(
            "euler-lagrange",
            "Euler–Lagrange equations",
            [row for _, row in shown_equations],
            [shown for shown, _ in shown_equations],
            "For each coordinate, d/dt ∂L/∂q̇ − ∂L/∂q"
            + (" − Q (the generalized force above)" if any(f != 0 for f in m.Q) else "")
            + " vanishes along the true motion"
            + (
                "; each equation is shown divided by its acceleration's coefficient."
                if eqs.mass_matrix.is_diagonal()
                else _divided_by(d, pr)
            ),
            formed=True,
        )
    )
    steps.append(
        _step(
            "mass-matrix",
            notation.MATRIX_FORM,
            # one coordinate: a number and a function, never a 1×1 matrix in brackets; a force linear in the
            # coordinates grouped by coordinate: κx₂ − (k + κ)x₁
            [
                rf"{Mt} = {pr.tex(pr.form(eqs.mass_matrix[0, 0]))}",
                rf"f = {pr.tex(pr.form(meaning.by_coordinate(eqs.forcing[0], table.q)))}",
            ]
            if len(table.q) == 1
            else [
                rf"{Mt} = {pr.tex(eqs.mass_matrix.applyfunc(pr.form))}",
                rf"f = {pr.tex(eqs.forcing.applyfunc(lambda x: pr.form(meaning.by_coordinate(x, table.q))))}",
            ],
            [eqs.mass_matrix.tolist(), [display(meaning.by_coordinate(x, table.q)) for x in eqs.forcing]],
            f"The equations are linear in the accelerations: {Mu} q̈ = f, with {Mu} the mass matrix (the Hessian of L in "
            f"the velocities) and f {notation.RIGHT_SIDE} (the forces and the velocity terms)"
            + _undivided(d, pr),
        )
    )
    # an acceleration linear in the coordinates grouped by coordinate over its shared denominator (app.engine.display.meaning)
    acc = shown_accelerations(d) if eqs.closed_form else []
    steps.append(
        _step(
            "accelerations",
            "Accelerations",
            [f"{qddn[k]} = {pr.tex(a)}" for k, a in enumerate(acc)],
            acc,
            f"Solving {Mu} q̈ = f gives each acceleration explicitly, as a function of the coordinates and velocities.",
        )
        if eqs.closed_form  # else M⁻¹f stays factored (app.engine.equations.lagrange.CLOSED_FORM_MAX_NODES)
        else _step(
            "accelerations",
            "Accelerations",
            [rf"\ddot{{q}} = {Mt}^{{-1}} f"],
            "M**(-1)*f",
            f"Solved symbolically, {Mu} q̈ = f gives expressions too long to read "
            f"({eqs.closed_form_reason}): the accelerations stay {Mu}⁻¹f, and the "
            f"numerics solve {Mu} q̈ = f by LU at every step.",
        )
    )
    compared = _comparison_step(d, pr, acc)
    if compared is not None:
        steps.append(compared)
    steps.append(
        _step(
            "momenta",
            "Generalized momenta",
            [f"p_{{{qn[k]}}} = {pr.tex(momentum(d, k))}" for k in range(len(eqs.momenta))],
            [momentum(d, k) for k in range(len(eqs.momenta))],
            "Each generalized momentum is the derivative of L with respect to that coordinate's velocity.",
        )
    )
    if en.cyclic:
        steps.append(
            _step(
                "cyclic",
                "Cyclic coordinates",
                [
                    rf"\frac{{\partial L}}{{\partial {qn[table.names.index(c)]}}} = 0 \;\Rightarrow\; "
                    rf"p_{{{qn[table.names.index(c)]}}} = {pr.tex(momentum(d, table.names.index(c)))} = \text{{const}}"
                    for c in en.cyclic
                ],
                [momentum(d, table.names.index(c)) for c in en.cyclic],
                "A coordinate missing from L (with no force on it) has a momentum that never changes.",
            )
        )
    steps.append(
        _step(
            "time-dependence",
            "Explicit time dependence",
            [rf"\frac{{\partial L}}{{\partial t}} = {pr.tex(display(en.dL_dt))}"],
            display(en.dL_dt),
            "If L does not contain t explicitly and no non-conservative force acts, the energy function h is conserved.",
        )
    )
    h_form, e_form = energies(d, pr)
    steps.append(
        _step(
            "hamiltonian",
            "Energy function h",
            [rf"h = \sum_k p_k \dot{{q}}_k - L = {pr.tex(h_form)}"],
            h_form,
            "The energy function h is the sum of momenta times velocities minus the Lagrangian, written in the "
            "velocities (the Hamiltonian H is the same quantity written in the momenta).",
        )
    )
    if m.T is not None:
        steps.append(
            _step(
                "energy",
                "Energy",
                [f"E = T + U = {pr.tex(e_form)}"],
                e_form,
                "The mechanical energy, for comparison with h.",
            )
        )
        steps.append(
            _step(
                "h-vs-e",
                "Is h equal to E?",
                [f"E - h = {pr.tex(en.energy_minus_h)}"],
                en.energy_minus_h,
                en.reason,
            )
        )
    if any(f != 0 for f in m.Q):
        steps.append(
            _step(
                "power",
                "Power of the non-conservative forces",
                [
                    rf"\frac{{dh}}{{dt}} = -\frac{{\partial L}}{{\partial t}} + \sum_k Q_k \dot{{q}}_k = {pr.tex(display(en.power - en.dL_dt))}"
                ],
                display(en.power - en.dL_dt),
                "Along the motion h changes at the rate at which the generalized forces do work.",
            )
        )
    if red is not None:
        steps.extend(_reduction_steps(d, pr))
    return steps


def _effective_potential_why(d: Derivation) -> str:
    """Where U_eff comes from, in words, by case: cyclic coordinates held at their momenta, a moving constraint
    (a part T₀ of T without velocities), both, or neither (the bead on a spun hoop has no cyclic coordinate:
    its U_eff is U − T₀)."""
    red = d.reduction
    assert red is not None
    mech, table = d.mechanics, d.table
    name = unicode(red.coordinate)
    inertia = notation.inertia(d)
    # a length moves like a particle of mass m_eff; an angle like a body of moment of inertia I_eff turning
    body = "a particle of mass" if inertia is notation.MASS_INERTIA else "a body turning with moment of inertia"
    moves = f"{name} moves like {body} {inertia.unicode} in the potential U_eff."
    held = "each conserved momentum held at its value, the cyclic velocities eliminated"
    if mech.T is None:
        # only L was given: T₀ and U cannot be told apart, U_eff is −L at q̇ = 0 (with the momenta held)
        if red.momenta:
            return f"With {held}, {moves}"
        return f"U_eff is −L with {name}\u0307 = 0, and {moves}"
    # T₀ = T at every velocity zero: the part of T a moving constraint (or a rotating frame) leaves without
    # velocities; it enters L = T − U with U's opposite sign, so U_eff = U − T₀ (plus the momenta's part)
    t0 = mech.T.xreplace(dict.fromkeys(table.qd, sp.Integer(0)))
    moving = not is_zero(t0)
    t = table.t
    if any(c.has(t) for r in mech.positions for c in r):
        source = "the moving constraint (the positions contain t)"
    else:
        source = "the part of T without velocities as written (a moving constraint's or a rotating frame's)"
    if red.momenta and moving:
        return (
            f"With {held}, and the part T₀ of T without velocities from {source} counted with U "
            f"(it enters L = T − U with the opposite sign), {moves}"
        )
    if red.momenta:
        return f"With {held}, {moves}"
    if moving:
        return (
            f"No coordinate is cyclic here: U_eff comes from {source}, which leaves a part T₀ of T without "
            f"velocities. T₀ enters L = T − U with the sign opposite to U's, so U_eff = −L at {name}\u0307 = 0 "
            f"is U − T₀, and {moves}"
        )
    return (
        f"One coordinate on fixed constraints: U_eff is the potential energy U itself and {inertia.unicode} the coefficient "
        f"of ½{name}\u0307² in T, so {moves}"
    )


def _reduction_steps(d: Derivation, pr: Printer) -> list[dict[str, str]]:
    red = d.reduction
    assert red is not None
    table = d.table
    r = table.q[table.names.index(red.coordinate)]
    rn = pr.tex(r)
    # the inertia's letter: I_eff where r is an angle, m_eff where a length (app/engine/notation.inertia)
    held = notation.inertia(d)
    # The constant of this first integral is the conserved energy E where h = E, else h itself (a rotating
    # frame's bead): the page's own letter for it, never a new E_r.
    level = "E" if d.energetics.h_equals_e else "h"
    # ½ m_eff ṙ² followed by U_eff exactly as the step before prints it (centrifugal piece first)
    rd = table.qd[table.names.index(red.coordinate)]
    u_eff = pr.tex(effective_potential(d), red.momenta[0] if red.momenta else None)
    # ½ m_eff ṙ² factored, or in its textbook form where that is shorter (½(m₁ + m₂ + M/2) ẏ², as T prints it,
    # not ¼(M + 2m₁ + 2m₂) ẏ²); a tie keeps the factored one
    piece = red.radial_energy - red.effective_potential
    forms = [sp.factor_terms(piece), display(piece)]
    kinetic = pr.tex(min(forms, key=lambda e: (sp.count_ops(e), forms.index(e))), rd)
    radial = f"{kinetic} {u_eff}" if u_eff.startswith("-") else f"{kinetic} + {u_eff}"
    out: list[dict[str, str]] = []
    if red.cyclic_velocities:
        out.append(
            _mapping_step(
                "cyclic-velocities",
                "Eliminating the cyclic velocities",
                red.cyclic_velocities,
                "Each conserved momentum is solved for its velocity, leaving one coordinate to follow.",
                pr,
            )
        )
    out.append(
        _step(
            "effective-potential",
            "Effective potential",
            [
                # the centrifugal piece first, as a textbook writes U_eff; U_eff = U in U's own form; with no
                # momentum held and a moving constraint (U_eff = U − T₀), each piece as its own term, as the
                # equilibria's step prints the same U_eff (−mgR cos θ − ½mR²w² sin²θ, never −mR(g cos θ + ½Rw² sin²θ))
                rf"U_\text{{eff}}({rn}) = "
                + (
                    pr.tex(effective_potential(d), red.momenta[0] if red.momenta else None)
                    if red.momenta or _is_potential(d, red.effective_potential)
                    else pr.tex(display(sp.expand(red.effective_potential)))
                ),
                f"{held.latex} = {pr.tex(red.effective_mass)}",
            ],
            [effective_potential(d), red.effective_mass],
            _effective_potential_why(d),
        )
    )
    out.append(
        _step(
            "energy-integral",
            "Energy first integral",
            [rf"{level} = {radial}"],
            red.radial_energy,
            f"The conserved {level}, written in {unicode(red.coordinate)} alone: a first-order equation for "
            f"{unicode(red.coordinate)}.",
        )
    )
    level_symbol = sp.Symbol(level, real=True)
    # E − U_eff with E first and U_eff's pieces in the order the effective-potential step prints them
    energy_left = pr.tex(level_symbol - effective_potential(d), level_symbol)
    # 2/m_eff printed as one quotient, its numerator and denominator each collected: m_eff may itself be a
    # fraction (the wedge's m(M + m sin²α)/(M + m)), and a textbook never prints a fraction over a fraction
    # (2(M + m)/(m(M + m sin²α)), not 2 over m(M + m sin²α)/(M + m))
    integrand = rf"\frac{{d{rn}}}{{\sqrt{{{pr.tex(2 / red.effective_mass)}\left({energy_left}\right)}}}}"
    rows = [
        rf"t = \int \sqrt{{\frac{{{held.latex}}}{{2\,\left({level} - U_\text{{eff}}({rn})\right)}}}}\, d{rn}",
        # the same integral with this system's m_eff and U_eff written in (what a problem asks for)
        rf" = \int {integrand}",
    ]
    integrals: list[sp.Expr] = [red.time_integral]
    why = (
        f"Separating variables in the energy integral gives the time to reach each {unicode(red.coordinate)}; "
        f"the second form writes in this system's {held.unicode} and U_eff."
    )
    steady = red.omega_squared_steady
    bounded = steady is not None and steady.is_nonpositive is not True
    if bounded or any(e.stable is not False for e in red.equilibria):
        # U_eff has a minimum (a stable equilibrium, or a steady motion about which ω² can be positive), so a
        # motion can be bounded: between its turning points r_min and r_max (where
        # U_eff = E) the integral is the time from one to the other, half the period (there and back is one)
        low, high = (sp.Symbol(f"{red.coordinate}_{end}", real=True) for end in ("min", "max"))
        rows.append(
            rf"\tfrac{{1}}{{2}}\,\text{{period}} = \int_{{{rn}_\text{{min}}}}^{{{rn}_\text{{max}}}} {integrand}"
        )
        integrals.append(sp.Integral(red.time_integral.function, (r, low, high)))
        name = unicode(red.coordinate)
        why += (
            f" Taken between the turning points {name}_min and {name}_max, where U_eff = {level}, it is half the "
            "period of a bounded motion: there and back is a whole one."
        )
    out.append(_step("time-integral", "Time as an integral", rows, integrals, why))
    omega = notation.letter("frequency", d)
    if red.equilibria and steady is not None and all(e.omega_squared.has(*red.momenta) for e in red.equilibria):
        # ω² about a steady motion in terms of its r₀, the momentum eliminated by U_eff'(r₀) = 0, as a textbook
        # writes it (not the root put back into U_eff'')
        r0 = sp.Symbol(r.name + "0", real=True)
        at = trig_cancelled(steady.xreplace({r: r0}))
        # r₀³ = p_φ² tan α/(m² g) where the root is a cube root (app/engine/display/root_forms.py)
        powers = [power_form(e.position) for e in red.equilibria]
        rows = [rf"{rn}_0{_power_tex(n)} = {pr.tex(c)}" for n, c in powers] + [rf"{omega}^2 = {pr.tex(at)}"]
        sym: Any = [c for _, c in powers] + [at]
        momentum = unicode(red.momenta[0].name)
        why = (
            f"A steady motion sits where U_eff′ vanishes; about it, ω² = U_eff″/{held.unicode}. The condition "
            f"U_eff′({unicode(r0.name)}) = 0 gives {momentum}² in terms of {unicode(r0.name)}, and ω² is written "
            f"with it, so it depends on {unicode(r0.name)} and the parameters alone."
            + (" It is positive: the steady motion is stable." if all(e.stable for e in red.equilibria) else "")
            + (
                " It is negative: the steady motion is unstable."
                if all(e.stable is False for e in red.equilibria)
                else ""
            )
        )
    elif red.equilibria:
        rows = [rf"{rn}_0 = {pr.root(e.position)},\quad {omega}^2 = {pr.tex(e.omega_squared)}" for e in red.equilibria]
        sym = [(e.position, e.omega_squared) for e in red.equilibria]
        why = f"Equilibria make U_eff′ vanish; about each, ω² = U_eff″/{held.unicode} (oscillation when positive, instability when negative)."
    else:
        if not red.equilibrium_condition.has(r):
            # a force that never vanishes: no equilibrium, so no frequency about one either
            rows = [rf"U_\text{{eff}}' = {pr.tex(red.equilibrium_condition)} \neq 0", r"\text{no equilibrium}"]
            sym = [red.equilibrium_condition]
            why = f"U_eff′ does not depend on {unicode(red.coordinate)} and is not zero, so there is no equilibrium."
        elif steady is not None:
            # a steady motion whose root θ₀ has no closed form (the spherical pendulum's cone): the condition
            # U_eff′(θ₀) = 0 still fixes the momentum, p² = −B(θ₀)/A(θ₀), and ω² = U_eff″/m_eff is written with it,
            # in θ₀ and the parameters alone, as a textbook prints it (reduction._steady_omega_squared)
            r0 = sp.Symbol(r.name + "0", real=True)
            # over one denominator: −g(1 + 3 cos² θ₀)/(R cos θ₀), not −(1/cos θ₀ + 3 cos θ₀) g/R
            at = sp.factor_terms(sp.together(trig_cancelled(steady.xreplace({r: r0}))))
            condition = red.equilibrium_condition.xreplace({r: r0})
            rows = [
                rf"U_\text{{eff}}'({rn}_0) = {pr.tex(condition)} = 0",
                rf"{omega}^2 = \frac{{U_\text{{eff}}''({rn}_0)}}{{{held.latex}}} = {pr.tex(at)}",
            ]
            sym = [condition, at]
            momentum, root = unicode(red.momenta[0].name), unicode(r0.name)
            why = (
                f"A steady motion sits at a root {root} of U_eff′, here found numerically; about it, ω² = "
                f"U_eff″/{held.unicode}. The condition U_eff′({root}) = 0 fixes {momentum}² by {root}, and ω² is written "
                f"with it, so it depends on {root} and the parameters alone."
            )
        else:
            # both rows at the root θ₀ (the frequency is U_eff″ there, not at every θ)
            at_root = {r: sp.Symbol(r.name + "0")}
            rows = [
                rf"U_\text{{eff}}'({rn}_0) = {pr.tex(red.equilibrium_condition.xreplace(at_root))} = 0",
                rf"{omega}^2 = \frac{{U_\text{{eff}}''({rn}_0)}}{{{held.latex}}} = {_at_root(pr, pythagoras(red.omega_squared_at), r)}",
            ]
            sym = [red.equilibrium_condition, pythagoras(red.omega_squared_at)]
            why = (
                f"No closed-form root was found; the condition and the frequency hold at any {unicode(red.coordinate + '0')} "
                "that satisfies it."
            )
    out.append(_step("reduced-equilibria", "Equilibria and small oscillations", rows, sym, why))
    return out
