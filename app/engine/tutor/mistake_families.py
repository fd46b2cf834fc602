"""Mistakes generated from a system's own derivation, each named in the system's words.

``app.engine.tutor.mistakes`` lists the mistakes any system invites (the ½, the square,
the sign of U); this module builds the ones that only this system's structure
can name, from the same objects the engine derives:

* T: each body's velocity v_i = Σ_k (∂r_i/∂q_k) q̇_k + ∂r_i/∂t with one
  coordinate's contribution (or the moving constraint's ∂r_i/∂t) left out; a body
  forgotten; the products of two velocities of a pair of coordinates dropped
  (T given directly: each part of T by its velocities);
* U: each spring (a square (a + c)² whose c is constant) without its natural
  length c, each term of U left out, each term's sign;
* p_k = ∂L/∂q̇_k: each velocity's part left out;
* the equation E_k = d/dt p_k − ∂L/∂q_k − Q_k with each chain-rule term of
  d/dt p_k = Σ_j (∂p_k/∂q̇_j) q̈_j + Σ_j (∂p_k/∂q_j) q̇_j + ∂p_k/∂t left out, each part
  of ∂L/∂q_k left out (the parts of ∂T/∂q_k by their velocities, the force of
  each term of U), ∂(½ a q̇²)/∂q̇ taken as ½ a q̇, Q_k doubled or of the wrong
  sign, sin x ≈ x and cos x ≈ 1 for every angle (an approximation, named so),
  and each part's sign; the accelerations those equations give, M q̈ = f';
* ω² at another equilibrium than the one asked for.

Each is a ``Mistake``: a stable machine key (``kinetic.velocity_part.ball.phi``)
with display text, the piece typeset, where in the set-up it comes from, the
whole wrong answer, and where it helps a follow-up question a student can answer.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

import sympy as sp
from sympy.simplify.fu import TR10i

from app.engine.algebra.budget import within_budget
from app.engine.algebra.simplify import pythagoras
from app.engine.derivation.derive import Derivation
from app.engine.display.names import unicode
from app.engine.display.spoken import spoken
from app.limits import NAME_WORK

MAX_PER_STEP = 60


@dataclass(frozen=True)
class FollowUp:
    """A short question after a named mistake; ``kind`` is the step whose names the answer may use."""

    question: str
    kind: str
    truth: sp.Expr
    relation: str  # "exact", or "magnitude" (a speed or a stretch: its sign is the student's choice)
    answer_text: str  # the answer in words, for the verdict
    hint: str = ""  # a second, more concrete hint, for a wrong answer to the question


def states_answer(words: str, fu: FollowUp) -> bool:
    """Whether the words said before a follow-up question give its answer away: the answer written out in them
    (either sign, for a speed or a stretch).  A lone name (Ẋ, in "the part that comes from Ẋ") says where a part
    comes from, not what it is, and gives nothing away."""
    if fu.truth.is_Symbol or fu.truth.is_Number:
        return False
    said = {fu.answer_text, spoken(fu.truth)} | ({spoken(-fu.truth)} if fu.relation == "magnitude" else set())
    # the answer as a whole, never a part of a longer name or formula (ż in żz)
    return any(re.search(rf"(?<![\w\u0300-\u036f]){re.escape(s)}(?![\w\u0300-\u036f²³₀-₉])", words) for s in said if s)


@dataclass(frozen=True)
class Correct:
    """The correct part a mistake's name points at (the denominator, the stretch, a rod's I about its end), kept
    out of the name: the verdict names the place and the kind of slip, and the student opens this one part only
    by asking for it ("the denominator M + 4 m₁, where the correct one is …" gave the answer away)."""

    what: str  # the part in words, after "the correct": "denominator", "stretch", "moment of inertia about the end"
    expr: sp.Expr
    note: str = ""  # what holds it, in words: "up to a constant factor"


@dataclass(frozen=True)
class Mistake:
    key: str  # stable, for records: "<step>.<family>[.<detail>…]"
    family: str
    name: str  # what went wrong, in the system's words (plain text with Unicode mathematics)
    piece: sp.Expr | None  # the piece the name speaks of (left out, extra, or of the wrong sign); None: the difference
    where: str  # where in the set-up the piece comes from
    expr: sp.Expr  # the whole wrong answer
    approximation: bool = False
    follow_up: FollowUp | None = None
    count: int = 1  # mistakes at once
    correct: Correct | None = None  # the correct part the name points at, shown only on request

    @property
    def said(self) -> str:
        """The name as the student reads it: what happened to the piece said beside it (``said``)."""
        return said(self.family, self.name)


# How a family's slip changes the answer: it leaves a piece out, or it adds one (a piece counted again). A family's
# name says which piece; the words the student reads say what happened to it ("the cross term in Ẋ Ḋ left out"),
# since a bare piece reads as one the student wrote ("The mistake: the cross term in Ẋ Ḋ", where the
# answer had no cross term). The one home of that rule, for every family of every step.
LEAVES_OUT = frozenset({
    "velocity_part", "moving_constraint", "body_forgotten", "velocity_axis", "cross_term", "part_left_out",
    "natural_length", "term_left_out", "momentum_part", "chain_rule", "dl_dq_part", "force_left_out",
    "half_momentum", "left_out", "position_carried",
})  # fmt: skip
ADDS = frozenset({"counted_twice", "force_doubled", "cross_term_added", "extra_term", "level_body"})


# ---- words -------------------------------------------------------------------------------------

# a mistake's name that already says how its piece is wrong ("the ½ of ½ k × stretch² left out of the term k x₂²"):
# a sentence composed around it says "with …" or "has …", never "leaves out … left out"
_SAYS_HOW = re.compile(r"\b(left out|leaves out|missing|without|swapped|twice|reversed|added)\b")


def says_how(name: str) -> bool:
    """Whether a mistake's name says how its piece is wrong, not only which piece it is."""
    return bool(_SAYS_HOW.search(name))


def said(family: str, name: str) -> str:
    """A mistake's name as the student reads it: a piece left out said "… left out", a piece added "… added",
    unless the name says so already (or says otherwise how the piece is wrong)."""
    if says_how(name):
        return name
    if family in LEAVES_OUT:
        return f"{name} left out"
    if family in ADDS:
        return f"{name} added"
    return name


def slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_") or "body"


def term_key(term: sp.Expr) -> str:
    """A term of U named for a record by its symbols: k_l0_x1_x2 (stable, whatever the order of the sum)."""
    return "_".join(sorted(s.name for s in term.free_symbols))


_SHORT: dict[sp.Expr, sp.Expr] = {}


def sum_words(a: sp.Expr, coordinates: Iterable[sp.Symbol]) -> str:
    """A sum as a textbook orders it: the coordinates' terms, those added before those taken away, then the
    constants (x₂ − x₁ − l₀, never x₂ − l₀ − x₁); a sum that is no stretch as the printer has it."""
    q = set(coordinates)
    if not isinstance(a, sp.Add) or not q:
        return spoken(a)
    terms = sorted(
        a.args, key=lambda t: (not (t.free_symbols & q), t.could_extract_minus_sign(), sp.default_sort_key(t))
    )
    text = spoken(terms[0])
    for t in terms[1:]:
        text += f" − {spoken(-t)}" if t.could_extract_minus_sign() else f" + {spoken(t)}"
    return text


def spring_words(energy: sp.Expr, coordinates: Iterable[sp.Symbol]) -> str:
    """A spring's energy as a textbook writes it, k (x₂ − x₁ − l₀)²: the stretch in a textbook's order, the
    natural length taken away (of a stretch and its negative, whose squares are the same)."""
    f = sp.factor(energy)
    squares = [a for a in sp.Mul.make_args(f) if isinstance(a, sp.Pow) and a.exp == 2 and a.base.is_Add]
    if len(squares) != 1:
        return spoken(f)
    q = set(coordinates)
    stretch = squares[0].base
    constant = sum((t for t in sp.Add.make_args(stretch) if not t.free_symbols & q), sp.Integer(0))
    if constant != 0 and not constant.could_extract_minus_sign():
        stretch = -stretch
    rest = f / squares[0]
    return f"{'' if rest == 1 else spoken(rest) + ' '}({sum_words(stretch, q)})²"


def short_form(expr: sp.Expr) -> sp.Expr:
    """A shorter form to name a piece with (products of sines and cosines recombined), within a small budget
    (remembered: the equations' mistakes name the same pieces again for the accelerations)."""
    if expr in _SHORT:
        return _SHORT[expr]

    def work() -> sp.Expr:
        best = sp.factor_terms(pythagoras(sp.expand(expr)))
        quick = sp.factor_terms(TR10i(best))  # cos θ₁ cos θ₂ + sin θ₁ sin θ₂ → cos(θ₁ − θ₂), cheaply
        best = quick if sp.count_ops(quick) < sp.count_ops(best) else best
        tried = sp.factor_terms(sp.trigsimp(best))
        return tried if sp.count_ops(tried) < sp.count_ops(best) else best

    found = within_budget(work, expr, NAME_WORK)
    if found is not expr and len(_SHORT) < 4096:  # (a form cut short by a busy machine is not remembered)
        _SHORT[expr] = found
    return found


def _magnitude(squared: sp.Expr) -> sp.Expr:
    """√(squared) as a reader writes it (R sin θ φ̇ for R² sin²θ φ̇²), taking every symbol positive."""
    symbols = sorted(squared.free_symbols, key=lambda s: s.name)
    positive = {s: sp.Dummy(s.name, positive=True) for s in symbols}
    back = {v: s for s, v in positive.items()}
    root = sp.sqrt(sp.factor(squared.xreplace(positive))).xreplace(back)
    return root.replace(sp.Abs, lambda x: x)


# ---- T -----------------------------------------------------------------------------------------


def _body(d: Derivation, i: int) -> str:
    particles = d.system.particles
    label = particles[i].label if i < len(particles) else ""
    return label or f"particle {i + 1}"


def _moved_alone(d: Derivation, i: int, body: str, q: sp.Symbol, qd: sp.Symbol, r: tuple, dr: tuple) -> str:
    """A concrete second hint for "the speed when only q changes": the body that carries it along, where one
    moves with q exactly as it does, and how to work the speed out from the body's position; never the velocity,
    which is the answer."""
    position = ", ".join(spoken(c) for c in r)
    carrier = ""
    for j, other in enumerate(d.mechanics.positions):
        # another body whose position moves with q alone, and exactly as this one's part does: it carries it
        moves = {s for c in other for s in c.free_symbols if s in d.table.q}
        if j != i and moves == {q} and tuple(sp.diff(c, q) for c in other) == dr:
            carrier = f"The {_body(d, j)} carries the {body} along with it. "
            break
    qn = unicode(q.name)
    return (
        f"{carrier}Hold every other coordinate fixed and change {qn} alone. Differentiate the {body}'s position "
        f"({position}) by {qn} and multiply by {unicode(qd.name)}: that is its velocity, and the speed is its size."
    )


def kinetic_mistakes(d: Derivation) -> Iterator[Mistake]:
    m, table = d.mechanics, d.table
    if m.T is None:
        return
    T = m.T
    if m.velocities:
        for i, (mass, r, v) in enumerate(zip(m.masses, m.positions, m.velocities, strict=True)):
            body = _body(d, i)
            key = slug(body)
            parts = [(q, qd, tuple(sp.diff(c, q) for c in r)) for q, qd in zip(table.q, table.qd, strict=True)]
            moving = tuple(sp.diff(c, table.t) for c in r)
            for q, qd, dr in parts:
                others = any(any(x) for p, _, x in parts if p != q) or any(moving)
                if not any(dr) or not others:
                    # the body's whole velocity: forgetting it is forgetting the body
                    continue
                # v' = v − (∂r/∂q) q̇: the velocity without this coordinate's part
                rest = tuple(c - x * qd for c, x in zip(v, dr, strict=True))
                wrong = (
                    T
                    - sp.Rational(1, 2) * mass * m.speeds_squared[i]
                    + sp.Rational(1, 2) * mass * pythagoras(sum(c**2 for c in rest))
                )
                speed = _magnitude(pythagoras(sum(x**2 for x in dr)) * qd**2)
                shown = spoken(speed)
                yield Mistake(
                    f"kinetic.velocity_part.{key}.{q.name}",
                    "velocity_part",
                    # not its size: the piece shows it, and the follow-up asks for it
                    f"the part of the {body}'s velocity that comes from {unicode(qd.name)}",
                    speed,
                    f"the {body}'s position depends on {unicode(q.name)}, so the {body} also moves when "
                    f"{unicode(q.name)} changes: its velocity has the part (∂r/∂{unicode(q.name)}) "
                    f"{unicode(qd.name)}",
                    sp.expand(wrong),
                    follow_up=FollowUp(
                        f"What is the speed of the {body} when only {unicode(q.name)} changes "
                        "(every other coordinate held fixed)?",
                        "kinetic",
                        speed,
                        "magnitude",
                        shown,
                        _moved_alone(d, i, body, q, qd, r, dr),
                    ),
                )
            if any(moving):
                rest = tuple(c - x for c, x in zip(v, moving, strict=True))
                wrong = (
                    T
                    - sp.Rational(1, 2) * mass * m.speeds_squared[i]
                    + sp.Rational(1, 2) * mass * pythagoras(sum(c**2 for c in rest))
                )
                speed = _magnitude(pythagoras(sum(x**2 for x in moving)))
                shown = spoken(speed)
                yield Mistake(
                    f"kinetic.moving_constraint.{key}",
                    "moving_constraint",
                    f"the part of the {body}'s velocity that comes from the moving constraint",
                    speed,
                    f"the {body}'s position depends on t itself (the constraint moves), so its velocity has the "
                    "part ∂r/∂t, even when no coordinate changes",
                    sp.expand(wrong),
                    follow_up=FollowUp(
                        f"How fast does the {body} move when every coordinate is held fixed?",
                        "kinetic",
                        speed,
                        "magnitude",
                        shown,
                        f"Hold every coordinate fixed and differentiate the {body}'s position "
                        f"({', '.join(spoken(c) for c in r)}) with respect to t alone; the speed is the size of "
                        "that velocity.",
                    ),
                )
            yield from _axes_left_out(d, i, body, key, mass, v)
            if len(m.masses) > 1:
                own = sp.expand(sp.Rational(1, 2) * mass * m.speeds_squared[i])
                yield Mistake(
                    f"kinetic.body_forgotten.{key}",
                    "body_forgotten",
                    f"the kinetic energy of the {body}",
                    own,
                    f"the {body} (mass {spoken(mass)}) moves too: T adds ½ m v² over every body",
                    sp.expand(T - own),
                    follow_up=FollowUp(
                        f"What is the kinetic energy of the {body} alone?",
                        "kinetic",
                        own,
                        "exact",
                        spoken(short_form(own)),
                    ),
                )
    yield from _cross_mistakes(d, T)
    if not m.velocities:
        yield from _parts_left_out(d, T, "kinetic", "T")


_AXES = ("x", "y", "z")


def _axes_left_out(d: Derivation, i: int, body: str, key: str, mass: sp.Expr, v: tuple) -> Iterator[Mistake]:
    """The body's velocity with one Cartesian component, or the two of a plane, left out."""
    m = d.mechanics
    moving = [a for a in range(3) if v[a] != 0]
    if len(moving) < 2:
        return
    options: list[tuple[int, ...]] = [(a,) for a in moving]
    if len(moving) == 3:
        # a plane, where its two components make a simpler speed than each alone (a circle: R α ż)
        for plane in ((0, 1), (0, 2), (1, 2)):
            together = pythagoras(sum(v[a] ** 2 for a in plane))
            if sp.count_ops(together) < sum(sp.count_ops(sp.expand(v[a] ** 2)) for a in plane):
                options.append(plane)
    for axes in options:
        lost = pythagoras(sum(v[a] ** 2 for a in axes))
        speed = _magnitude(lost)
        named = (
            f"the {_AXES[axes[0]]}-component of the {body}'s velocity"
            if len(axes) == 1
            else f"the {body}'s motion in the {_AXES[axes[0]]}–{_AXES[axes[1]]} plane"
        )
        yield Mistake(
            f"kinetic.velocity_axis.{key}.{''.join(_AXES[a] for a in axes)}",
            "velocity_axis",
            # not its speed: the follow-up asks for it (states_answer)
            named,
            speed,
            f"the {body}'s position ({', '.join(spoken(c) for c in m.positions[i])}) changes along "
            + " and ".join(_AXES[a] for a in axes)
            + ", and v² adds the squares of all three components",
            sp.expand(m.T - sp.Rational(1, 2) * mass * lost),
            follow_up=FollowUp(
                f"What is the {body}'s speed along " + " and ".join(_AXES[a] for a in axes) + "?",
                "kinetic",
                speed,
                "magnitude",
                spoken(speed),
            ),
        )


def velocity_monomials(expr: sp.Expr, rates: tuple[sp.Symbol, ...]) -> dict[sp.Expr, sp.Expr]:
    """expr split by its product of rates (q̇, q̈): {θ̇²: the θ̇² terms, 1: the terms without rates, …}."""
    out: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        if term == 0:
            continue
        c, monomial = term.as_independent(*rates, as_Add=False)
        out[monomial] = out.get(monomial, sp.Integer(0)) + term
    return {k: v for k, v in out.items() if sp.expand(v) != 0}


def monomial_words(monomial: sp.Expr) -> str:
    return "the terms without a velocity" if monomial == 1 else f"the {spoken(monomial)} terms"


def _cross_mistakes(d: Derivation, T: sp.Expr) -> Iterator[Mistake]:
    qd = d.table.qd
    groups = velocity_monomials(T, qd)
    for monomial, part in groups.items():
        powers = monomial.as_powers_dict()
        velocities = [v for v in qd if powers.get(v, 0) == 1]
        if len(velocities) != 2:
            continue
        a, b = velocities
        yield Mistake(
            f"kinetic.cross_term.{a.name}.{b.name}",
            "cross_term",
            f"the cross term in {unicode(a.name)} {unicode(b.name)}",
            short_form(part),
            f"a position depends on both {unicode(a.name[:-4])} and {unicode(b.name[:-4])}: squaring its velocity "
            f"gives the product of the two parts, 2 ({unicode(a.name)} part)·({unicode(b.name)} part)",
            sp.expand(T - part),
        )


def bodies_lumped(d: Derivation) -> Iterator[Mistake]:
    """T as one body of the total mass moving with the sum of the bodies' velocities, ½ (m₁ + m₂)(ẋ₁ + ẋ₂)², where
    each body has its own ½ m v².  (Tried after the pieces of T, and never carried into a later
    step.)"""
    m = d.mechanics
    if m.T is None or not m.velocities or len(m.masses) < 2:
        return
    total = sp.Add(*m.masses)
    summed = [sp.Add(*(v[axis] for v in m.velocities)) for axis in range(3)]
    lumped = sp.Rational(1, 2) * total * pythagoras(sum(c**2 for c in summed))
    shown = sp.factor(lumped)
    half = shown.as_coeff_Mul()[0] == sp.Rational(1, 2)
    # the student's own form where it is short, the ½ in front (½ (m₁ + m₂) (ẋ₁ + ẋ₂)²), else in words
    words = f"½ {spoken(2 * shown, d.table.q)}" if half else spoken(shown, d.table.q)
    said = f", {words}," if sp.count_ops(shown) <= 12 else ", with the total mass and the summed velocity,"
    yield Mistake(
        "kinetic.bodies_lumped",
        "bodies_lumped",
        f"the bodies taken as one{said} without each body's own ½ m v²",
        None,
        "each body has its own ½ m v², with its own mass and its own velocity, and T adds them; squaring the sum "
        "of the velocities mixes them",
        sp.expand(lumped),
    )


def _parts_left_out(d: Derivation, expr: sp.Expr, step: str, letter: str) -> Iterator[Mistake]:
    for monomial, part in velocity_monomials(expr, d.table.qd).items():
        yield Mistake(
            f"{step}.part_left_out.{slug(sp.sstr(monomial))}",
            "part_left_out",
            f"the {spoken(monomial)} part of {letter}" if monomial != 1 else f"the part of {letter} without velocities",
            short_form(part),
            f"{letter} has a term in {spoken(monomial)}" if monomial != 1 else f"{letter} has a velocity-free term",
            sp.expand(expr - part),
        )


# ---- U -----------------------------------------------------------------------------------------


def _springs(term: sp.Expr, dynamic: set[sp.Symbol]) -> list[tuple[sp.Expr, sp.Expr]]:
    """(the square's base, its constant part) for every (a + c)² in term whose c is constant."""
    out = []
    for power in term.atoms(sp.Pow):
        base, exponent = power.args
        if exponent == 2 and isinstance(base, sp.Add) and base.free_symbols & dynamic:
            constant = sp.Add(*(a for a in base.args if not (a.free_symbols & dynamic)))
            if constant != 0:
                out.append((base, constant))
    return out


SIGN_OF_KIND = {
    "the gravitational energy": "a height is measured upward, against gravity",
    "the spring energy": "a spring's energy is never negative",
}


def kind_of_term(term: sp.Expr, d: Derivation) -> str:
    names = {s.name for s in term.free_symbols}
    if "g" in names:
        return "the gravitational energy"
    if any(isinstance(p.args[0], sp.Add) or p.args[0] in d.table.q for p in term.atoms(sp.Pow) if p.args[1] == 2):
        return "the spring energy"
    return "the term"


def _in(term: sp.Expr, d: Derivation) -> str:
    """The coordinates a term of U holds, in words ("θ₁", "x₁ and x₂")."""
    names = [unicode(q.name) for q in d.table.q if term.has(q)]
    return " and ".join(names) if names else "t"


def _whose(term: sp.Expr, kind: str, d: Derivation) -> str:
    """A term of U in words, saying whose energy it is where the system has others of its kind
    ("the gravitational energy in y₁ and y₂" named the pulley's end masses' coordinates, not the middle mass
    whose term was left out): "the gravitational energy of the middle mass", "the energy of the spring κ"; else
    the kind alone."""
    names = {s.name for s in term.free_symbols}
    if kind == "the gravitational energy":
        bodies = [p.label for p in d.system.particles if p.label and p.mass in names]
        if bodies and len(bodies) < len(d.system.particles):
            return f"{kind} of the " + " and the ".join(bodies)
    if kind == "the spring energy":
        stiff = [p.name for p in d.system.parameters if p.unit in ("N/m", "kg/s²")]
        mine = [unicode(n) for n in stiff if n in names]
        if mine and len(mine) < len(stiff):
            return "the energy of the spring " + " and ".join(mine)
    return kind


def potential_mistakes(d: Derivation) -> Iterator[Mistake]:
    U = d.mechanics.U
    if U is None or U == 0:
        return
    dynamic = {*d.table.q, d.table.t}
    terms = [t for t in sp.Add.make_args(U) if t.free_symbols & dynamic]
    halves = [t for t in terms if kind_of_term(t, d) == "the spring energy" and t.as_coeff_Mul()[0].q == 2]
    if len(terms) > 1 and len(halves) == len(terms):
        # every spring's ½ lost at once (k x₁² + k x₂² + κ (x₂ − x₁)² got the step's rule)
        yield Mistake(
            "potential.spring_half.all",
            "doubled",
            "the ½ of ½ k × stretch² left out of every spring's energy",
            U,
            "a spring's energy is ½ k × stretch², the work done stretching it against a force that grows from "
            "zero to k × stretch",
            sp.expand(2 * U),
        )
    for term in terms:
        for base, constant in _springs(term, dynamic):
            stretch = base
            yield Mistake(
                f"potential.natural_length.{term_key(term)}",
                "natural_length",
                f"the spring's natural length {spoken(-constant if constant.could_extract_minus_sign() else constant)}",
                constant,
                # not the stretch itself: the follow-up asks for it (states_answer)
                "a spring stores energy by its stretch from its natural length, not by its whole length",
                sp.expand(U - term + term.xreplace({base: base - constant})),
                follow_up=FollowUp(
                    "By how much is the spring stretched beyond its natural length?",
                    "potential",
                    stretch,
                    "magnitude",
                    spoken(stretch),
                ),
            )
        kind = kind_of_term(term, d)
        coefficient, _ = term.as_coeff_Mul()
        if kind == "the spring energy" and coefficient.is_Rational and coefficient.q == 2:
            # ½ k × stretch²: the ½ lost gives twice the spring's energy, as the ½ of ½ m v² does in T
            yield Mistake(
                f"potential.spring_half.{term_key(term)}",
                "doubled",
                # quoted in the student's own term, as a textbook writes it: k (r − l)²
                f"the ½ of ½ k × stretch² left out of your term {spring_words(2 * term, d.table.q)}",
                term,
                "a spring's energy is ½ k × stretch², the work done stretching it against a force that grows from "
                "zero to k × stretch",
                sp.expand(U + term),
            )
        if len(terms) > 1:
            named = _whose(term, kind, d)
            yield Mistake(
                f"potential.term_left_out.{term_key(term)}",
                "term_left_out",
                f"{named} in {_in(term, d)}",
                term,
                f"U adds the energy of every force that has one: {named} in {_in(term, d)} is one of them",
                sp.expand(U - term),
            )
            yield Mistake(
                f"potential.term_sign.{term_key(term)}",
                "term_sign",
                f"the sign of your {kind.removeprefix('the ')} {spoken(-term)}",
                term,
                # each kind has its own reason: no spring is spoken of in a term of gravity
                SIGN_OF_KIND.get(kind, "U is the work done against the force"),
                sp.expand(U - 2 * term),
            )


def _weights(d: Derivation) -> tuple[sp.Symbol, list[tuple[str, sp.Expr, tuple]]] | None:
    """(g, [(body, mass, position)]) where U's gravity is Σ m g × z over the bodies, up to a constant; else None."""
    m, U = d.mechanics, d.mechanics.U
    g = next((s for s in U.free_symbols if s.name == "g"), None) if U is not None else None
    if g is None or not m.positions or len(m.masses) != len(m.positions):
        return None
    dynamic = {*d.table.q, d.table.t}
    weight = sum((mass * g * r[2] for mass, r in zip(m.masses, m.positions, strict=True)), sp.Integer(0))
    gravity = sp.Add(*(t for t in sp.Add.make_args(sp.expand(U)) if t.has(g)))
    if sp.expand(gravity - weight).free_symbols & dynamic:
        return None
    bodies = [(_body(d, i), mass, r) for i, (mass, r) in enumerate(zip(m.masses, m.positions, strict=True))]
    return g, bodies


def height_mistakes(d: Derivation) -> Iterator[Mistake]:
    """U = Σ m g z with each body's height written wrong: its x or y taken for its height (the helix
    bead's R sin(α z) for z), or a sine or cosine of its height squared (−m g R cos²θ), where a height holds each
    to the first power; named from the positions, never by printing U.  (Tried after the pieces of U, and never
    carried into a later step: a swapped sine there is named as a swap, a number off as a number.)"""
    found = _weights(d)
    if found is None:
        return
    g, bodies = found
    U, dynamic = d.mechanics.U, {*d.table.q, d.table.t}
    weight = sum((mass * g * r[2] for _, mass, r in bodies), sp.Integer(0))
    for axis in (0, 1):
        if not any(r[axis].free_symbols & dynamic for _, _, r in bodies):
            continue
        # U = Σ m g × (the body's x or y), where Σ m g z belongs
        wrong = sp.expand(U - weight + sum((mass * g * r[axis] for _, mass, r in bodies), sp.Integer(0)))
        if len(bodies) == 1:
            body, _, r = bodies[0]
            name = f"the {body}'s {_AXES[axis]}, {spoken(r[axis], d.table.q)}, taken for its height"
            where = f"U is m g times the height, and the {body}'s height is its z, measured upward"
        else:
            name = f"each body's {_AXES[axis]} taken for its height"
            where = "U is m g times each body's height, and a body's height is its z, measured upward"
        yield Mistake(f"potential.height_axis.{_AXES[axis]}", "height_axis", name, None, where, wrong)
    for body, mass, r in bodies:
        height = sp.expand(r[2])
        for f in sorted(height.atoms(sp.sin, sp.cos), key=sp.default_sort_key):
            if not f.args[0].free_symbols & dynamic or sp.degree(height.xreplace({f: _F}), _F) != 1:
                continue
            # the height's sine or cosine squared: U changes by m g (z with f → f²) − m g z
            wrong = sp.expand(U + mass * g * (height.xreplace({f: f**2}) - height))
            kind = "cosine" if isinstance(f, sp.cos) else "sine"
            yield Mistake(
                f"potential.height_squared.{slug(body)}.{slug(sp.sstr(f))}",
                "height_squared",
                f"{spoken(f, d.table.q)} squared in the {body}'s height",
                None,
                f"U is m g times the height, and a height is linear in {spoken(f, d.table.q)} (a length times the "
                f"{kind} of an angle, never its square)",
                wrong,
            )


_F = sp.Dummy("f")  # a sine or cosine of a height, stood in for to read the height's degree in it
