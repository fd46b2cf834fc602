"""Backward diagnosis: the smallest change to one of the system's own pieces that gives the answer.

``app.engine.tutor.mistake_families`` and ``mistake_equations`` list the mistakes a derivation invites
step by step; this module works from the truth's own pieces instead, so a slip nobody listed is
still named by what changed:

* a factor on one piece (each term of the truth, and the terms that hold one parameter together,
  such as the movable pulley's M terms): doubled (for a force already in U: counted twice),
  halved, four times (a velocity doubled), left out, of the wrong sign;
* the sign of one term inside a sum in a square or a product (a spring's stretch x₁ + x₂ for
  x₂ − x₁, its natural length with the wrong sign);
* sin and cos swapped, in one piece or throughout (positions written with them exchanged);
* the small-angle approximation of an acceleration;
* a rigid body's moment of inertia (a rod, a disc, a ring: about its centre, about a pivot, as a
  point mass, its spin forgotten, another kind's I_cm) and a rod's centre at l for l/2, read from T and U typed
  directly; and a declared wheel on a fixed axle (a massive pulley), read from the body: its turning left out, a
  ring's I for a disc's (or its mass moving with the string), another kind's I_cm, its centre taken to move; each
  explained by T = ½ M v_cm² + ½ I_cm θ̇² in the body's own symbols (rigid_kinetic_rule);
* mistakes that travel: a mistake of T or U carried into the equation of motion and into ω²
  ("your equation follows from a T that …"), and a rigid body's into the momentum;
* ω² with one term of U_eff left out or of the wrong sign (the centrifugal term, the spring's).

Every family is bounded by counts (pieces, parameters, candidates), never by time, so the same
answer gets the same words on an idle and on a busy machine.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator
from fractions import Fraction

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.derivation.dimensions import STIFFNESS_WORDS, Dims, add_dims, dimension, quantity, system_dimensions
from app.engine.display.names import unicode
from app.engine.document.notation import inertia
from app.engine.document.notation import text as frequency_letter
from app.engine.equations.bodies import INERTIA
from app.engine.equations.lagrange import euler_lagrange_of
from app.engine.tutor.check_answers import RELATIONS
from app.engine.tutor.mistake_families import (
    Correct,
    Mistake,
    kinetic_mistakes,
    potential_mistakes,
    says_how,
    short_form,
    slug,
    spoken,
    sum_words,
    term_key,
)
from app.engine.tutor.mistake_other import linear
from app.engine.tutor.mistakes import STIFFNESS_UNITS, has_springs

MAX_PIECES = 12  # terms of a truth taken one at a time (a longer truth is left to the listed families)
MAX_SUMS = 6  # sums inside the truth whose terms' signs are tried
MAX_TRAVEL = 16  # mistakes of T or U carried into a later step

# ---- pieces --------------------------------------------------------------------------------------


def _terms(truth: sp.Expr) -> list[sp.Expr]:
    terms = sorted(sp.Add.make_args(sp.expand(truth)), key=sp.default_sort_key)
    return terms if 1 < len(terms) <= MAX_PIECES else (terms if len(terms) == 1 else [])


def _groups(truth: sp.Expr, params: tuple[sp.Symbol, ...]) -> list[tuple[sp.Symbol, sp.Expr]]:
    """(parameter, the terms that hold it) where that is more than one term and not the whole."""
    terms = _terms(truth)
    out = []
    for s in params:
        held = [t for t in terms if t.has(s)]
        if 1 < len(held) < len(terms):
            out.append((s, sp.Add(*held)))
    return out


def _has_half(p: sp.Expr) -> bool:
    coefficient, _ = p.as_coeff_Mul()
    return bool(coefficient.is_Rational) and abs(coefficient.q) == 2


def swap_sin_cos(expr: sp.Expr) -> sp.Expr:
    """sin ↔ cos in every sine and cosine."""
    return expr.replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)),
        lambda e: sp.cos(e.args[0]) if isinstance(e, sp.sin) else sp.sin(e.args[0]),
    )


def _is_force_of_u(d: Derivation, step: str, p: sp.Expr) -> bool:
    rates = (*d.table.qd, *d.table.qdd)
    return step == "equation" and d.mechanics.U is not None and not p.has(*rates) and p != 0


def _derivative_why(p: sp.Expr, coordinate: str, coordinates: Iterable[sp.Symbol]) -> str:
    """Where a swapped sine in an equation's velocity-free term comes from: ∂L/∂q, differentiated; or, where the
    angle is a fixed parameter (an incline's α), the component of gravity taken, which no derivative touches."""
    trig = sorted(p.atoms(sp.sin, sp.cos), key=sp.default_sort_key)[0]
    x = trig.args[0]
    angle = spoken(x) if x.is_Symbol else f"({spoken(x)})"
    if not x.free_symbols & set(coordinates):
        # ∂/∂q leaves a fixed angle's sine and cosine as they are: along a slope at α gravity's part is g sin α,
        # across it g cos α, so the swap is a slip of geometry made before any derivative
        return (
            f"{angle} is a fixed angle of the set-up, not a coordinate, so no derivative acts on its sine or cosine: "
            f"the slip is in the component of gravity taken (along a slope at {angle} it is g sin {angle}, across "
            f"it g cos {angle})"
        )
    # d(cos x)/dx = −sin x and d(sin x)/dx = cos x: the truth's sine came from a cosine, and its cosine from a sine
    rule = (
        f"the derivative of cos {angle} is −sin {angle}"
        if isinstance(trig, sp.sin)
        else f"the derivative of sin {angle} is cos {angle}"
    )
    return (
        f"the term comes from ∂L/∂{unicode(coordinate)}, and {rule}; with T and U right, the slip is in that "
        "derivative, not in the positions"
    )


def _doubled_why(step: str, p: sp.Expr) -> str:
    """Why a piece is there once: a weight's energy m g × height (gravity counted twice), or any other piece."""
    if step in ("potential", "lagrangian", "hamiltonian") and any(s.name == "g" for s in p.free_symbols):
        return "each mass's weight enters U once, as m g times its height: gravity is counted twice here"
    return "this piece enters the answer once: it seems to be counted twice"


def _halved_why(d: Derivation, step: str, p: sp.Expr) -> str:
    """Why a piece is whole: a bob's height (a rod's centre would be halfway), or a factor 2 lost in a derivative."""
    if step == "potential" and d.system.particles and any(s.name == "g" for s in p.free_symbols):
        # a bob's height is the full length's; R/2 is where a rod's centre would be
        return (
            "the mass is a bob at the end, so it rises by the whole length's height; a rod's centre is at half its "
            "length, but there is no rod's mass here"
        )
    if step in ("equation", "momentum", "acceleration"):
        return (
            "the whole of this piece belongs in the answer (a factor 2 from differentiating a square, or from the "
            "chain rule, is easily lost)"
        )
    return "the whole of this piece belongs in the answer"


def _bob_swing(d: Derivation, step: str, p: sp.Expr) -> bool:
    """Whether p is a bob's ½ m l² θ̇²: T's term in one angle's velocity squared, in a system of point masses."""
    if step != "kinetic" or not d.system.particles:
        return False
    angles = {a for f in p.atoms(sp.sin, sp.cos) for a in f.args[0].free_symbols}
    squared = [v for v in d.table.qd if p.as_powers_dict().get(v, 0) == 2]
    trig = {a for f in (d.mechanics.U or sp.S.Zero).atoms(sp.sin, sp.cos) for a in f.args[0].free_symbols}
    return _has_half(p) and len(squared) == 1 and not angles and d.table.q[d.table.qd.index(squared[0])] in trig


def _label(step: str) -> str:
    return {"kinetic": "T", "potential": "U", "lagrangian": "L", "hamiltonian": "h"}.get(step, "")


def piece_mistakes(d: Derivation, step: str, k: int | None, truth: sp.Expr) -> Iterator[Mistake]:
    """A factor, a sign or a swapped function on one piece of the truth, named by the piece."""
    if step == "omega_squared":
        return
    moving = {*d.table.q, *d.table.qd, *d.table.qdd}
    base = f"{step}.piece"
    yield from _sums(truth, base, has_springs(d), d.table.q)
    if has_springs(d):
        yield from _stretch_parts(d, truth, base)
    rates = (*d.table.qd, *d.table.qdd)
    for p in _terms(truth):
        # the piece as a textbook prints it, once (the student's own piece is a multiple of it, or it swapped)
        short = short_form(p)
        shown = spoken(short)
        key = slug(sp.sstr(p))[:48]
        if _is_force_of_u(d, step, p):
            # gravity by its name (a term with g); no generalized force Q is spoken of, a problem may have none
            gravity = any(s.name == "g" for s in p.free_symbols)
            yield Mistake(
                f"{base}.counted_twice.{key}", "counted_twice",
                f"gravity counted twice (your term {shown} twice)" if gravity else f"the force {shown} counted twice",
                p, "this force comes from U, and ∂L/∂q already holds it: writing it again beside it counts it twice",
                truth + p,
            )  # fmt: skip
        elif _has_half(p):
            yield Mistake(
                f"{base}.half_missing.{key}", "doubled", f"your term {spoken(2 * short)} without its ½",
                p, "the ½ belongs to this piece (½ m v², ½ k x², a centre halfway along)", truth + p,
            )  # fmt: skip
        else:
            yield Mistake(
                f"{base}.doubled.{key}", "doubled", f"your term {spoken(2 * short)}, twice what it should be",
                p, _doubled_why(step, p), truth + p,
            )  # fmt: skip
        yield Mistake(
            f"{base}.halved.{key}", "halved", f"your term {spoken(short / 2)}, half of what it should be", p,
            _halved_why(d, step, p), truth - p / 2,
        )  # fmt: skip
        if _bob_swing(d, step, p):
            # ½ (⅓ m l²) θ̇² = ⅙ m l² θ̇²: a uniform rod's T about its end, where the mass is a bob at the end
            yield Mistake(
                f"{base}.rod_for_bob.{key}", "rigid", f"a rod's T for a bob (your term {spoken(short / 3)})", p,
                "a rod's I about its end is ⅓ m × length², but here the mass is a bob at the end of a massless rod or "
                "string, so all of it moves on the full circle: I = m times the length squared", truth - p + p / 3,
            )  # fmt: skip
        name, why = _left_out(d, step, p, truth, k)
        yield Mistake(f"{base}.left_out.{term_key(p)}", "left_out", name, p,
                      why or LEFT_OUT_WHY.get(step, "this term belongs in the answer"), truth - p)  # fmt: skip
        if step == "hamiltonian" and not p.has(*rates):
            # a term of U keeps its sign in h = T₂ − T₀ + U; a term of T free of the velocities (T₀) changes it
            # (the sign of the rotating wire's m g α ρ² was explained by the centrifugal term's reason)
            u_terms = set(sp.Add.make_args(sp.expand(d.mechanics.U))) if d.mechanics.U is not None else set()
            from_u = bool(u_terms) and set(sp.Add.make_args(sp.expand(p))) <= u_terms
            yield Mistake(
                f"{base}.sign_of_velocity_free.{key}", "term_sign", f"the sign of your term {spoken(-short)}", p,
                "U enters h = T₂ − T₀ + U with its own sign, as it enters the energy: only the part of T free of "
                "the velocities, T₀, changes sign" if from_u else
                "in h = Σ p q̇ − L the part of L free of the velocities changes sign, so h is not the energy T + U "
                "when T has such a part", truth - 2 * p,
            )  # fmt: skip
        if p == truth and step in WHOLE_SIGN_WHY:
            # one term is the whole answer: its sign is the answer's, and quoting it back as "your term" hides that
            yield Mistake(f"{base}.sign.{key}", "term_sign", "the sign of the whole answer", p,
                          WHOLE_SIGN_WHY[step], -truth)  # fmt: skip
        elif not (step == "equation" and p.has(*d.table.qdd)):  # (that sign is the rest's, a rule names it)
            why = (_cross_why(d, p) if step == "kinetic" else None) or SIGN_WHY.get(
                step, "each term's sign follows from the derivation"
            )
            yield Mistake(f"{base}.sign.{key}", "term_sign", f"the sign of your term {spoken(-short)}", p, why,
                          truth - 2 * p)  # fmt: skip
        if step != "momentum":  # a momentum short of a factor is named by that factor (app.engine.tutor.check)
            yield from _factors(p, truth, base, key, rates, d.table.params, _units_why(d, step, k, p, truth))
        if p.has(sp.sin, sp.cos):
            swapped = swap_sin_cos(p)
            # in an equation, a velocity-free term is a derivative of U (or of T by q): there a swap is a slip of
            # differentiating (d(−cos θ)/dθ = sin θ taken as cos θ), the positions being checked in T and U
            why = (
                _derivative_why(p, d.table.names[k], d.table.q)
                if step in ("equation", "acceleration") and k is not None and not p.has(*rates)
                else "check which component of the position has the sine and which the cosine, at a small angle"
            )
            # a solved acceleration's quotient whose numerator a swap leaves as it is (sin α cos α): the swap is in
            # the denominator, the inertia T gives, not in a component of gravity (it was said so)
            num, den = sp.fraction(sp.factor(p))
            if step == "acceleration" and den != 1 and sp.simplify(swap_sin_cos(num) - num) == 0 \
                    and sp.simplify(swap_sin_cos(den) - den) != 0:
                why = (f"the swap is in the denominator {spoken(den)}, which the inertia in T gives (the effective "
                       "mass), not in a component of gravity: check the cross term of T")  # fmt: skip
            yield Mistake(
                f"{base}.sin_cos.{key}", "sin_cos", f"sin and cos swapped in your term {spoken(swap_sin_cos(short))}",
                p, why, truth - p + swapped,
            )  # fmt: skip
            yield Mistake(
                f"{base}.sin_cos_height.{key}", "sin_cos", f"sin and cos swapped in your term {spoken(-swap_sin_cos(short))}",
                p, why, truth - p - swapped,
            )  # fmt: skip
    yield from _whole(d, step, truth, base)
    for s, group in _groups(truth, d.table.params):
        name = unicode(s.name)
        if step == "kinetic":
            yield Mistake(
                f"{base}.group_four.{s.name}", "velocity_doubled",
                f"the {name} terms four times too big: {_speed_doubled(d, s)}", group,
                "check how far this body moves when the coordinates change", truth + 3 * group,
            )  # fmt: skip
        # the student's own piece, twice the truth's, in the factored form a textbook prints (k (r − l)²); where
        # a constant is no part of the comparison, without the group's constant terms, which the student's answer
        # need not have (the pulley's −M g (y₁ + y₂), never −M (y₁ + y₂ + 2 c) g)
        varying = group
        if RELATIONS.get(step) == "constant":
            varying = sp.Add(*(t for t in sp.Add.make_args(sp.expand(group)) if t.free_symbols & moving)) or group
        yours = _factored(2 * varying)
        yield Mistake(
            # (in T a squared sum is a body's ½ m v², never a spring: the pulley's M (ẏ₁ + ẏ₂)²/4)
            f"{base}.group_doubled.{s.name}", "doubled",
            _doubled_name(name, yours, group, step != "kinetic" and _spring(group, s)), group,
            _half_why(step, group, s), truth + group,
        )  # fmt: skip
        yield Mistake(f"{base}.group_left_out.{s.name}", "left_out", f"every term with {name} left out", group,
                      f"every body's part belongs in the answer, {name}'s too", truth - group)  # fmt: skip


_DOTTED = {"x": "ẋ", "y": "ẏ", "z": "ż"}


def _speed_doubled(d: Derivation, mass: sp.Symbol) -> str:
    """Why a body's ½ m v² is four times too big, in its own velocity where it moves along one line (
    the pulley's middle mass moves at (ẏ₁ + ẏ₂)/2, half the sum of the end masses' speeds)."""
    t = d.table
    for particle, r in zip(d.system.particles, d.mechanics.positions, strict=False):
        if particle.mass != mass.name or not particle.label:
            continue
        # the velocity of each component: Σ ∂r/∂q q̇ (+ ∂r/∂t)
        v = [sum((sp.diff(c, q) * qd for q, qd in zip(t.q, t.qd, strict=True)), sp.diff(c, t.t)) for c in r]
        moving = [sp.factor(c) for c in v if c != 0]
        if len(moving) == 1:
            speed = -moving[0] if moving[0].could_extract_minus_sign() else moving[0]
            return (
                f"the {particle.label} moves at {spoken(speed)}, half as fast as {spoken(sp.factor(2 * speed))}"
            )
    return "that body's velocity is doubled (it moves half as far as you have it)"


def _cross_why(d: Derivation, p: sp.Expr) -> str | None:
    """Where a cross term of T comes from: the position components that hold both its coordinates.

    A component c(q) has the rate Σ_k (∂c/∂q_k) q̇_k; squared, it gives 2 (∂c/∂q_a)(∂c/∂q_b) q̇_a q̇_b, so the
    cross term's sign is that of the product of the two parts, which the geometry fixes."""
    m, t = d.mechanics, d.table
    powers = p.as_powers_dict()
    rates = [v for v in t.qd if powers.get(v, 0) == 1]
    if len(rates) != 2 or not m.velocities:
        return None
    (a, b), (qa, qb) = rates, (t.q[t.qd.index(rates[0])], t.q[t.qd.index(rates[1])])
    for i, r in enumerate(m.positions):
        # the components whose rate has both a q̇_a part and a q̇_b part
        both = [(axis, c) for axis, c in zip("xyz", r, strict=False) if sp.diff(c, qa) != 0 and sp.diff(c, qb) != 0]
        if not both:
            continue
        where = " and ".join(f"{axis} = {spoken(c)}" for axis, c in both)
        parts = "; ".join(
            f"{_DOTTED[axis]} = {spoken(sp.diff(c, qa) * a)} + {spoken(sp.diff(c, qb) * b)}".replace("+ −", "− ")
            for axis, c in both
        )
        return (
            f"the cross term comes from the {_body_name(d, i)}'s position, {where}: {parts}, and squaring gives "
            "twice the product of the two parts, with the signs this geometry gives them"
        )
    return _body_cross_why(d, (qa, a), (qb, b))


def _body_cross_why(
    d: Derivation, first: tuple[sp.Symbol, sp.Symbol], second: tuple[sp.Symbol, sp.Symbol]
) -> str | None:
    """Where a cross term of a rigid body's T comes from: its ½ M v_cm², with v_cm² the sum of the squares of the
    centre's velocity components (read from the body, as the derivation writes them), one of which holds both
    rates: expanding that square gives the cross term and its sign. ``first`` and ``second``: (coordinate, rate)."""
    (qa, a), (qb, b_rate) = first, second
    for b in d.mechanics.bodies:
        # the components of v_cm whose rate has both a q̇_a part and a q̇_b part
        if not any(sp.diff(c, qa) != 0 and sp.diff(c, qb) != 0 for c in b.centre):
            continue
        # where the term comes from, never the components themselves: v_cm² is the answer's larger part
        return (
            f"the cross term comes from the {b.body.label or b.body.kind}'s ½ {spoken(b.mass)} v_cm²: write v⃗_cm "
            f"component by component ({spoken(a)} and {spoken(b_rate)} both appear in one of them), square each and "
            "add, and the square that holds both rates gives the cross term with its sign"
        )
    return None


def _factored(p: sp.Expr) -> sp.Expr:
    """The factored form where it is no longer (½ k (r − l)², not (l²/2 + r²/2 − l r) k)."""
    f = sp.factor(p)
    return f if sp.count_ops(f) <= sp.count_ops(p) else short_form(p)


def _spring(group: sp.Expr, s: sp.Symbol) -> bool:
    """Whether the group is a spring's energy, c k (a + b)²."""
    f = sp.factor(group)
    return any(isinstance(a, sp.Pow) and a.exp == 2 and a.base.is_Add for a in sp.Mul.make_args(f)) and f.has(s)


def _doubled_name(name: str, yours: sp.Expr, group: sp.Expr, spring: bool) -> str:
    if spring:
        return f"the spring term {spoken(yours)} without its ½"
    if _has_half(group.as_ordered_terms()[0]) or sp.factor(group).as_coeff_Mul()[0] == sp.Rational(1, 2):
        return f"the {name} term {spoken(yours)} without its ½"
    return f"the {name} terms, {spoken(yours)}, twice what they should be"


def _half_why(step: str, group: sp.Expr, s: sp.Symbol) -> str:
    """Why a ½ belongs to this piece: a spring's ½ k x², a body's ½ m v², or a point moving half as far."""
    if step in ("potential", "lagrangian", "hamiltonian") and _spring(group, s):
        return "a spring stores ½ k × stretch², the ½ coming from the work ∫ k x dx"
    if step == "kinetic":
        return "every body's kinetic energy is ½ m v²"
    return (
        "this body's part appears once; a ½ (a point halfway along, such as a movable pulley's middle) is easily lost"
    )


def _carrier(d: Derivation, i: int, q: sp.Symbol) -> str | None:
    """The body that carries body i along when q changes: one whose position moves with q alone, exactly as
    body i's part from q does."""
    positions = d.mechanics.positions
    dr = tuple(sp.diff(c, q) for c in positions[i])
    if not any(dr):
        return None
    for j, other in enumerate(positions):
        moves = {s for c in other for s in c.free_symbols if s in d.table.q}
        if j != i and moves == {q} and tuple(sp.diff(c, q) for c in other) == dr:
            return _body_name(d, j)
    return None


def _body_name(d: Derivation, i: int) -> str:
    particles = d.system.particles
    return (particles[i].label if i < len(particles) else "") or f"particle {i + 1}"


def _left_out(
    d: Derivation, step: str, p: sp.Expr, truth: sp.Expr | None = None, k: int | None = None
) -> tuple[str, str | None]:
    """(name, why) of a term of T or U left out: by its cause where one body carries another (the block moves
    with the wedge, so its velocity includes Ẋ), else by its velocities, else by the term itself.
    In an equation, one body's weight left out of a coordinate's force is named as that body's weight."""
    t = d.table
    rates = [v for v in t.qd if p.has(v)]
    namespace = t.namespace()
    if step == "equation" and k is not None and truth is not None and not p.has(*t.qd, *t.qdd):
        weight = _weight_left_out(d, p, truth, k)
        if weight is not None:
            return weight
    if step in ("kinetic", "potential") and d.mechanics.positions:
        owners = [i for i, b in enumerate(d.system.particles) if b.mass in namespace and p.has(namespace[b.mass])]
        if len(owners) == 1:
            i = owners[0]
            body = _body_name(d, i)
            for q, v in zip(t.q, t.qd, strict=True):
                if not (p.has(v) if step == "kinetic" else p.has(q)):
                    continue
                carrier = _carrier(d, i, q)
                if carrier is None:
                    continue
                qn, vn = unicode(q.name), unicode(v.name)
                if step == "kinetic":
                    monomial = sp.Mul(*(x for x in sp.Mul.make_args(p) if x.has(*t.qd)))
                    return (f"the {body}'s {spoken(monomial)} term left out", f"the {body} moves with the {carrier}, "
                            f"so its velocity includes {vn}")  # fmt: skip
                return (f"the {qn} part of the {body}'s height left out", f"the {body} moves with the {carrier}, so "
                        f"its height includes {qn}'s part")  # fmt: skip
    if rates:
        monomial = sp.Mul(*(x for x in sp.Mul.make_args(p) if x.has(*t.qd, *t.qdd)))
        return f"a {spoken(monomial)} term left out", None
    # the term itself, as a textbook prints it (κ x₂/m, −k l₀/m₁, m Ẍ), never a list of its letters
    return f"the term {spoken(short_form(p), t.q)} left out", None


def _weight_left_out(d: Derivation, p: sp.Expr, truth: sp.Expr, k: int) -> tuple[str, str] | None:
    """A velocity-free term of q_k's equation holding g and one body's mass alone, left out: that body's weight,
    which acts on q_k too (the lower bob's m₂ g l₁ sin θ₁ in the equation for θ₁)."""
    t = d.table
    if not any(s.name == "g" for s in p.free_symbols):
        return None
    namespace = t.namespace()
    owners = [i for i, b in enumerate(d.system.particles) if b.mass in namespace and p.has(namespace[b.mass])]
    if len(owners) != 1 or not d.system.particles[owners[0]].label:
        return None
    body, q = _body_name(d, owners[0]), unicode(t.q[k].name)
    # the whole gravity term of this shape: every body's part with the same factors but its mass (m₁ + m₂) g l₁ sin θ₁
    same = [
        u for u in sp.Add.make_args(sp.expand(truth))
        if not u.has(*t.qd, *t.qdd) and not sp.cancel(u / p).free_symbols & {*t.q, t.t}
    ]  # fmt: skip
    whole = spoken(sp.factor(sp.Add(*same)))
    return (f"the {body}'s weight left out of the gravity term",
            f"the {body} moves when {q} changes, so its weight also acts on {q}: the gravity term is {whole}")  # fmt: skip


def _units_why(d: Derivation, step: str, k: int | None, p: sp.Expr, truth: sp.Expr) -> Callable[[sp.Expr], str | None]:
    """Why a factor f with units is missing from the piece p, where p is the whole answer (a longer answer short of
    it has terms whose units disagree, named before any mistake), said in units (−g sin θ for θ̈ is an
    acceleration, where θ̈ is a squared rate): a function of f, None for a factor without units."""
    what = unicode(d.table.qdd[k].name) if step == "acceleration" and k is not None else _label(step)
    known = system_dimensions(d) if what and sp.expand(p - truth) == 0 else {}

    def why(f: sp.Expr) -> str | None:
        unit = dimension(f, known) if known else None
        want, got = dimension(truth, known), dimension(p / f, known)
        if not unit or want is None or got is None or add_dims(got, unit) != want:
            return None
        # named quantities only, without their units' letters (a hint speaks in the page's own symbols): where one
        # has no plain name, the geometry's reason stands
        inverse = all(v < 0 for v in unit.values())
        names = [_plain(x) for x in (want, got, add_dims({}, unit, Fraction(-1)) if inverse else unit)]
        if None in names:
            return None
        said = f"in units, {what} is {names[0]}, but {spoken(p / f)} is {names[1]}, so "
        if inverse:
            # f = 1/R: a division by a length
            return said + f"it must still be divided by {names[2]} ({spoken(1 / f)})"
        return said + f"it still needs a factor with the units of {names[2]}, {spoken(f)}"

    return why


def _plain(d: Dims) -> str | None:
    """A dimension by its plain name without its unit ("a squared rate", "an acceleration", "a length"); None where it
    has none, or a name a system without springs would not use (kg/s² is a spring constant only beside a spring)."""
    words = quantity(d)
    if words.startswith("a quantity in") or words == STIFFNESS_WORDS:
        return None
    return words.split(" (")[0]


def _factors(
    p: sp.Expr,
    truth: sp.Expr,
    base: str,
    key: str,
    rates: tuple,
    params: tuple,
    units: Callable[[sp.Expr], str | None] = lambda f: None,
) -> Iterator[Mistake]:
    """One piece without one of its factors (sin α, sin²θ, 1/(1 + R² α²)), or with a parameter's square written
    as the parameter itself (R for R²); a factor with units is explained by the units (``units``)."""
    factors = [f for f in sp.Mul.make_args(p) if not f.is_Number and not f.has(*rates)]
    for f in sorted(set(factors), key=sp.default_sort_key)[:MAX_SUMS]:
        if f.is_Symbol:
            continue  # a single parameter dropped is a matter of units (app.engine.derivation.dimensions)
        yield Mistake(
            f"{base}.factor_left_out.{key}.{slug(sp.sstr(f))[:24]}", "factor_left_out",
            f"your term {spoken(p / f)} without a factor {spoken(f)}", p,
            units(f) or "this factor comes from the geometry (a component of the position, or the chain rule)",
            truth - p + p / f,
        )  # fmt: skip
    for s in params:
        squared = s**2
        if squared in factors:
            yield Mistake(
                f"{base}.not_squared.{key}.{s.name}", "factor_left_out",
                f"{unicode(s.name)} in place of {unicode(s.name)}² in your term {spoken(p / s)}", p,
                "a velocity's part is squared whole in v², its length or rate included", truth - p + p / s,
            )  # fmt: skip


# Why a term left out, or a term's sign, is wrong, in the words of the step it belongs to
LEFT_OUT_WHY = {
    "kinetic": "every body's ½ m v² gives all of its terms, one for each coordinate that moves it and the cross terms "
    "between them",
    "potential": "U adds mass × g × height for every mass and ½ k × stretch² for every spring",
    "lagrangian": "L = T − U keeps every term of T and of U",
    "momentum": "p = ∂L/∂q̇ takes every term of L that holds this velocity",
    "equation": "d/dt(∂L/∂q̇) and ∂L/∂q each give terms: differentiate every term of L that holds this coordinate or "
    "its velocity",
    "acceleration": "solving the equations for q̈ keeps every term they hold",
    "hamiltonian": "h = Σ p q̇ − L keeps every term of L, some with their sign changed",
}
SIGN_WHY = {
    "kinetic": "½ m v² is a sum of squares: its terms are positive, and a cross term takes the sign of its cosine",
    "potential": "U is + mass × g × height, with the height measured upward: check which way the coordinate moves the mass",
    "lagrangian": "L = T − U: U's terms change sign in L",
    "momentum": "p = ∂L/∂q̇ keeps the sign each term has in L",
    "equation": "in d/dt(∂L/∂q̇) − ∂L/∂q = Q the terms of ∂L/∂q change sign",
    "acceleration": "moving a term across the equals sign changes its sign",
    "hamiltonian": "in h = Σ p q̇ − L the part of L free of velocities changes sign",
}
# the sign of an answer that is one term: the direction the coordinate counts as positive decides it
WHOLE_SIGN_WHY = {
    "acceleration": "the acceleration points the way the forces push, so check which way the coordinate counts "
    "as positive and that each term changed sign once as it crossed the equals sign",
    "momentum": "p = ∂L/∂q̇ keeps the sign its term has in L, which is that of T's velocity-squared term",
}


def _sums(truth: sp.Expr, base: str, springs: bool, coordinates: Iterable[sp.Symbol] = ()) -> Iterator[Mistake]:
    """The sign of one term inside a sum held in a square or a product: (x₂ − x₁ − l₀) as (x₁ + x₂ − l₀); in a
    system without a spring, only inside an angle (a sum elsewhere is no stretch, and its sign is a term's)."""
    inner = [a for a in sp.preorder_traversal(truth) if isinstance(a, sp.Add) and a != truth]
    seen: list[sp.Expr] = []
    for a in sorted(set(inner), key=sp.default_sort_key)[:MAX_SUMS]:
        for term in sorted(a.args, key=sp.default_sort_key):
            changed = a - 2 * term
            wrong = truth.xreplace({a: changed})
            if wrong in seen:
                continue
            seen.append(wrong)
            # the reason fits where the sum sits: inside a sine or cosine it is an angle between two directions
            # (the rods' θ₁ − θ₂), elsewhere a stretch or a distance between two ends
            angle = any(isinstance(f, sp.sin | sp.cos) and a in f.args for f in truth.atoms(sp.sin, sp.cos))
            if not (angle or springs):
                continue
            even = all(isinstance(f, sp.cos) for f in truth.atoms(sp.sin, sp.cos) if a in f.args) and angle
            if even and len(a.args) == 2 and changed.could_extract_minus_sign():
                # cos(−x) = cos x: −(θ₁ + θ₂) is written θ₁ + θ₂, and the sign changed is the other term's
                changed, term = -changed, a - term
            if term.could_extract_minus_sign():
                term = -term  # the sign of θ₂, not of −θ₂
            # the sums without a common number (κ (2 x₁ − 2 x₂)/2, as ∂/∂x₁ of ½ κ (x₂ − x₁)² leaves it, is
            # κ (x₁ − x₂)): the student never wrote the 2
            content = a.primitive()[0]
            term = term / content
            why = (
                "the angle between two directions is the difference of their angles from the same reference"
                if angle
                else "a stretch is the change in length, the far end minus the near end, less the natural length"
            )
            # the sum as written and the sign at fault; the correct sum is kept for the student to ask for
            yield Mistake(
                f"{base}.inner_sign.{slug(sp.sstr(a))[:32]}.{slug(sp.sstr(term))[:16]}", "inner_sign",
                f"{sum_words(changed / content, coordinates)}: the sign of {spoken(term)} ({why})", a,
                "draw the two directions and measure both angles from the same line" if angle
                else "draw the two ends and ask which way each coordinate moves them", wrong,
                correct=Correct("angle" if angle else "stretch", a / content),
            )  # fmt: skip


def _stretch_parts(d: Derivation, truth: sp.Expr, base: str) -> Iterator[Mistake]:
    """One end's coordinate left out of a spring's stretch between two moving ends (½ κ x₂² for the
    middle spring, whose stretch is x₂ − x₁): the spring named by its stiffness where the system has several."""
    q = d.table.q
    stiff = [p.name for p in d.system.parameters if p.unit.replace(" ", "") in STIFFNESS_UNITS]
    for a in sorted({b.base for b in truth.atoms(sp.Pow) if b.exp == 2 and b.base.is_Add}, key=sp.default_sort_key):
        moving = [t for t in a.args if t.free_symbols & set(q)]
        if len(moving) < 2 or len(moving) > MAX_SUMS:
            continue
        # the spring whose energy holds this stretch, by its stiffness: "the spring κ"
        holders = [t for t in sp.Add.make_args(truth) if t.has(a)]
        names = sorted({s.name for t in holders for s in t.free_symbols} & set(stiff))
        spring = "the spring " + " and ".join(unicode(n) for n in names) if len(names) == 1 and len(stiff) > 1 else (
            "the spring")
        for term in sorted(moving, key=sp.default_sort_key):
            kept = a - term
            # a stretch is the far end's position less the near end's: both ends move, so both coordinates enter
            # the end left out named, the correct stretch kept for the student to ask for
            yield Mistake(
                f"{base}.stretch_part.{slug(sp.sstr(a))[:32]}.{slug(sp.sstr(term))[:16]}", "stretch_part",
                f"{sum_words(kept, q)} as the stretch of {spring}: {spoken(-term if term.could_extract_minus_sign() else term)} "
                "left out", a,
                f"{spring} joins two ends that both move, so its stretch is the far end's position less the near "
                "end's, which changes when either end moves", truth.xreplace({a: kept}),
                correct=Correct("stretch", a),
            )  # fmt: skip


def _whole(d: Derivation, step: str, truth: sp.Expr, base: str) -> Iterator[Mistake]:
    if len([f for f in truth.atoms(sp.sin, sp.cos)]) >= 1 and len(_terms(truth)) != 1:
        yield Mistake(
            f"{base}.sin_cos_throughout", "sin_cos", "sin and cos swapped throughout (the positions written with "
            "the sine and the cosine exchanged)", None,
            "the part of a position along the line its angle is measured from carries the angle's cosine, the part "
            "across that line its sine",
            swap_sin_cos(truth),
        )  # fmt: skip
    if step == "acceleration":
        coordinates = set(d.table.q)
        swap = {
            f: (sp.Integer(1) if isinstance(f, sp.cos) else f.args[0])
            for f in truth.atoms(sp.sin, sp.cos, sp.tan)
            if f.args[0].free_symbols & coordinates
        }
        if swap:
            yield Mistake(
                "acceleration.small_angle", "small_angle", "the small-angle approximation sin x ≈ x, cos x ≈ 1", None,
                "it holds only for small oscillations near zero angle; the exercise asks for the full acceleration",
                truth.xreplace(swap), approximation=True,
            )  # fmt: skip
        if len(d.table.q) > 1:
            # coupled coordinates: the acceleration to first order about rest, as the linearised equations give it
            small = linear(d, truth)
            if small is not None:
                yield Mistake(
                    "acceleration.small_angle.linearised", "small_angle", "the small-angle approximation (the "
                    "equations linearised about rest)", None, "it holds only for small oscillations near zero angle; "
                    "the exercise asks for the full acceleration", small, approximation=True,
                )  # fmt: skip


# ---- rigid bodies ----------------------------------------------------------------------------------

# the body a student takes a declared body for, by kind: a solid disc (a cylinder) for a thin ring (a hoop), and back
_MISTAKEN_FOR = {"disc": "ring", "ring": "disc"}
# each kind of INERTIA (app/engine/equations/bodies.py) in words, in the plane (a rod, a pulley) and as a body that rolls (the
# cylinder on the wedge), and the name of any other kind's I_cm put in for a body's
_KIND_WORDS = {"rod": "uniform rod", "disc": "uniform disc", "ring": "thin ring", "sphere": "solid sphere"}
_ROLLING_WORDS = {**_KIND_WORDS, "disc": "solid cylinder", "ring": "hoop"}
_WRONG_INERTIA = "the turning energy with the wrong moment of inertia:"

# I/(m L²) about the centre of each body a student meets, L its length or radius
_CENTRE = {"rod": Fraction(1, 12), "disc": Fraction(1, 2), "ring": Fraction(1)}


def _lengths_and_masses(d: Derivation, known) -> tuple[list[sp.Symbol], list[sp.Symbol]]:
    length, mass = {"m": Fraction(1)}, {"kg": Fraction(1)}
    params = d.table.params
    return [s for s in params if known.get(s) == length], [s for s in params if known.get(s) == mass]


def masses_of(d: Derivation, known) -> list[sp.Symbol]:
    """The parameters whose declared unit is a mass."""
    return _lengths_and_masses(d, known)[1]


def _rate_squared(rate: sp.Expr) -> str:
    """A turning rate squared as the derivation writes it, θ̇² or (ṡ/r)², never ω² (the pages keep ω for
    frequencies): a sign inside is dropped, as (−a)² = a²."""
    rate = -rate if rate.could_extract_minus_sign() else rate
    return f"{spoken(rate)}²" if rate.is_Symbol else f"({spoken(rate)})²"


def _typed_turning_rate(d: Derivation, known) -> sp.Expr | None:
    """The rate a rigid body typed in T turns at, read from T's q̇² term as rigid_alternatives reads it: q̇ itself
    for a body turning about a pivot (c m L² q̇²), q̇/R for one rolling (c m q̇², R the one length)."""
    T = d.mechanics.T
    if T is None or len(d.table.q) != 1:
        return None
    v = d.table.qd[0]
    lengths, masses = _lengths_and_masses(d, known)
    a = sp.expand(sp.diff(T, v, 2))
    if any(sp.nsimplify(a / (m * L**2)).is_Rational for m in masses for L in lengths):
        return v
    if len(lengths) == 1 and any(sp.nsimplify(a / m).is_Rational for m in masses):
        # rolling without slipping: the rim's speed R × (turning rate) is the centre's, q̇
        return v / lengths[0]
    return None


def rigid_kinetic_rule(d: Derivation, known) -> str:
    """The rule a rigid body's slip of T breaks, in the page's own symbols: T = ½ M v_cm² + ½ I_cm θ̇² (König's
    theorem, app/engine/equations/bodies.py), with the body's own mass letter and its own turning rate (θ̇, ẏ/R, ṡ/r) as the
    derivation prints them."""
    if d.mechanics.bodies:
        pieces = "; ".join(
            f"the {b.body.label or b.body.kind}'s T is ½ {spoken(b.mass)} v_cm² + ½ I_cm {_rate_squared(b.turning_rate)}"
            for b in d.mechanics.bodies
        )
        return (
            f"{pieces}, the motion of its centre plus its turning about it, I_cm its moment of inertia about the centre"
        )
    masses = masses_of(d, known)
    mass = spoken(masses[0]) if len(masses) == 1 else "m"
    rate = _typed_turning_rate(d, known)
    turning = f"½ I_cm {_rate_squared(rate)}" if rate is not None else "½ I_cm × (its rate of turning)²"
    return (
        f"a rigid body's T is ½ {mass} v_cm² + {turning}, the motion of its centre plus its turning about it, I_cm "
        "its moment of inertia about the centre"
    )


def axle_alternatives(d: Derivation) -> list[tuple[str, str, sp.Expr, sp.Expr, Correct | None]]:
    """(key, name, ΔT, ΔU, the correct part) for each declared wheel on a fixed axle (a massive pulley: a disc or a
    ring whose centre does not move, turned by a string that does not slip), read from the body itself: its
    turning left out, the other kind's moment of inertia (a disc's turning ½ (M R²)(v/R)² = ½ M v², a ring's, which
    is also what its whole mass moving with the string would give), and its centre taken to move with the string."""
    out: list[tuple[str, str, sp.Expr, sp.Expr, Correct | None]] = []
    for b in d.mechanics.bodies:
        if b.translation != 0 or b.rotation == 0 or b.body.kind not in ("disc", "ring"):
            continue
        name, rate = b.body.label or b.body.kind, spoken(b.turning_rate)
        # the rim's speed R × (turning rate) is the string's: ½ M (rim speed)² is the whole mass moving with it
        moving = sp.expand(b.mass * b.size**2 * b.turning_rate**2 / 2)
        inertia_about_axle = Correct(f"moment of inertia of the {name} about its axle", b.inertia)
        out.append((
            "rigid.axle_turning_forgotten", f"the {name}'s turning energy ½ I ({rate})² left out: the string does not "
            f"slip, so the {name} turns as the string runs, I its moment of inertia about the axle", -b.rotation,
            sp.Integer(0), inertia_about_axle,
        ))  # fmt: skip
        if b.body.kind == "disc":
            # I = M R² for ½ M R²: the turning energy doubled, ½ M v² for ¼ M v²
            out.append((
                "rigid.axle_ring", f"the {name}'s turning energy taken as {spoken(moving)}, as if the {name} were a "
                f"ring (I = {spoken(b.mass * b.size**2)}) or its whole mass moved with the string, in place of a "
                f"uniform disc's turning", moving - b.rotation, sp.Integer(0), inertia_about_axle,
            ))  # fmt: skip
        else:
            out.append((
                "rigid.axle_disc", f"a uniform disc's moment of inertia for the {name}, which is a ring: all its mass "
                "is at the rim", -b.rotation / 2, sp.Integer(0), inertia_about_axle,
            ))  # fmt: skip
        # any other kind's I_cm (a sphere's ⅖ M R²): the turning energy scaled by the ratio of the two
        for kind in INERTIA:
            if kind not in ("disc", "ring"):
                wrong = INERTIA[kind] * b.mass * b.size**2
                out.append((
                    f"rigid.axle_taken_as_{kind}", f"{_WRONG_INERTIA} I_cm of a {_KIND_WORDS[kind]}, {spoken(wrong)}, "
                    f"in place of a {_KIND_WORDS[b.body.kind]}'s", sp.expand(b.rotation * (wrong / b.inertia - 1)),
                    sp.Integer(0), inertia_about_axle,
                ))  # fmt: skip
        out.append((
            "rigid.axle_centre_moving", f"the {name}'s centre taken to move with the string ({spoken(moving)} added): "
            f"the centre is on the fixed axle and does not move, so only the {name}'s turning counts", moving,
            sp.Integer(0), None,
        ))  # fmt: skip
    return out


def rigid_alternatives(d: Derivation, known) -> list[tuple[str, str, sp.Expr, sp.Expr, Correct | None]]:
    """(key, name, ΔT, ΔU, the correct part the name points at) for the slips a rigid body typed in T (and U) invites, read from T's q̇² terms:
    c m L² q̇² (a body turning about a pivot: a rod about its end, a disc or a ring about its rim or centre)
    or c m q̇² with c > ½ (a disc or a ring rolling: ½ m v² + ½ I (v/R)²)."""
    T, U = d.mechanics.T, d.mechanics.U
    # a declared wheel on a fixed axle names its own slips, beside the particles the string carries
    out = axle_alternatives(d)
    if T is not None and d.mechanics.bodies and (d.system.particles or len(d.table.q) != 1):
        return out + _declared_body_alternatives(d)
    if T is None or d.system.particles or len(d.table.q) != 1:
        return out
    v = d.table.qd[0]
    lengths, masses = _lengths_and_masses(d, known)
    a = sp.expand(sp.diff(T, v, 2))  # I or m_eff
    for m in masses:
        for L in lengths:
            c = sp.nsimplify(a / (m * L**2))
            if c.is_Rational and c == sp.Rational(1, 3):
                # a rod about its end: I = m l²/12 + m (l/2)²
                dT = lambda i: (i - a) * v**2 / 2  # noqa: E731
                # the rod's own I about its end is what the student works out: named by the slip, shown on request
                end = Correct("moment of inertia about the end", m * L**2 / 3)
                out.append(("rigid.rod_point_mass", f"the rod taken as a point mass at its end: I = {spoken(m * L**2)}, "
                            "a bob's moment of inertia, in place of a rod's about its end", dT(m * L**2), sp.Integer(0),
                            end))  # fmt: skip
                out.append(("rigid.rod_centre_axis", f"I about the rod's centre, {spoken(m * L**2 / 12)}, in place of "
                            f"I about the pivot at its end (the parallel-axis term {spoken(m * (L / 2) ** 2)} is "
                            "missing)", dT(m * L**2 / 12), sp.Integer(0), end))  # fmt: skip
                # the parallel-axis term added to I about the pivot, which already holds it: m l²/3 + m (l/2)²
                out.append(("rigid.rod_parallel_axis_twice", f"the parallel-axis term {spoken(m * (L / 2) ** 2)} "
                            f"counted twice, since I about the pivot, {spoken(m * L**2 / 3)}, already holds it "
                            f"({spoken(m * L**2 / 3)} = {spoken(m * L**2 / 12)} + {spoken(m * (L / 2) ** 2)})",
                            dT(m * L**2 / 3 + m * (L / 2) ** 2), sp.Integer(0), None))  # fmt: skip
                # the centre, l/2 from the pivot, moves at (l/2) θ̇: ½ M (l/2)² θ̇² = M l² θ̇²/8, printed both ways
                centre_only = f"½ {spoken(m)} ({spoken(L / 2)})² {spoken(v)}² = {spoken(m * L**2 * v**2 / 8)}"
                # another kind's I_cm put in for the rod's, the parallel-axis term M (l/2)² added to it as it should be
                centre = Correct("moment of inertia about the centre", m * L**2 / 12)
                for kind in INERTIA:
                    if kind != "rod":
                        wrong = INERTIA[kind] * m * L**2
                        out.append((f"rigid.rod_taken_as_{kind}", f"{_WRONG_INERTIA} I_cm of a {_KIND_WORDS[kind]}, "
                                    f"{spoken(wrong)}, in place of a {_KIND_WORDS['rod']}'s",
                                    dT(wrong + m * (L / 2) ** 2), sp.Integer(0), centre))  # fmt: skip
                # its I_cm behind the disclosure, as on the other rigid bodies' pages, never in the name
                out.append(("rigid.rod_spin_forgotten", f"only the motion of the rod's centre, {centre_only}: its "
                            f"spin about the centre, ½ I_cm {spoken(v)}², is forgotten",
                            dT(m * (L / 2) ** 2), sp.Integer(0), centre))  # fmt: skip
                if U is not None and U.has(L):
                    # the centre at l rather than l/2: every l of U doubled
                    dU = U.xreplace({L: 2 * L}) - U
                    out.append(("rigid.rod_centre_at_end", f"the rod's centre at {spoken(L)} in place of {spoken(L / 2)}"
                                " (a uniform rod's centre is halfway along it)", sp.Integer(0), dU, None))  # fmt: skip
                    out.append(("rigid.rod_as_point_mass", f"the rod taken as a point mass at its end (a simple "
                                f"pendulum): I = {spoken(m * L**2)} and the centre at {spoken(L)}, a bob's, in place of "
                                "a rod's", dT(m * L**2), dU, end))  # fmt: skip
        c = sp.nsimplify(a / m) if a.has(m) else None
        if c is not None and c.is_Rational and c in (sp.Rational(3, 2), 2):
            body = "disc" if c == sp.Rational(3, 2) else "ring"
            other = "ring" if body == "disc" else "disc"
            k_other = _CENTRE[other]
            # rolling without slipping: it turns at q̇/R, R its radius (the one length), never said as ω
            rate = _typed_turning_rate(d, known)
            turning = (
                f"½ I_cm {_rate_squared(rate)}" if rate is not None and rate != v else "½ I_cm × (rate of turning)²"
            )
            out.append(("rigid.rolling_spin_forgotten", f"the {body}'s spin forgotten: it rolls, so T also has "
                        f"{turning}, I_cm its moment of inertia about its centre", (m - a) * v**2 / 2, sp.Integer(0),
                        None))  # fmt: skip
            out.append((f"rigid.rolling_{other}", f"a {other}'s moment of inertia ({spoken(sp.nsimplify(k_other))} m R²)"
                        f" in place of a {body}'s", (m * (1 + sp.nsimplify(k_other)) - a) * v**2 / 2, sp.Integer(0),
                        None))  # fmt: skip
    return out


def _declared_body_alternatives(d: Derivation) -> list[tuple[str, str, sp.Expr, sp.Expr, Correct | None]]:
    """The slips a declared rigid body invites where it moves with other bodies or in several coordinates (a cylinder
    rolling on a sliding wedge), read from its own two pieces of T, ½ m v_cm² + ½ I_cm θ̇²: its turning forgotten,
    a hoop's I for a solid cylinder's (or back), any other kind's I_cm (a sphere's), and the motion of the body that
    carries it left out of v_cm."""
    out: list[tuple[str, str, sp.Expr, sp.Expr, Correct | None]] = []
    for i, b in enumerate(d.mechanics.bodies):
        if b.translation == 0:
            continue  # a wheel on a fixed axle: axle_alternatives names its slips
        label = b.body.label or b.body.kind
        if b.rotation != 0:
            # T without ½ I_cm θ̇²: the body slides as a point at its centre; its rate said as the rate itself (ṡ/r)
            out.append((f"rigid.turning_forgotten.{i}", f"the {label}'s turning forgotten: T has only "
                        f"½ {spoken(b.mass)} v_cm² for the motion of its centre, with no "
                        f"½ I_cm {_rate_squared(b.turning_rate)} for its turning about the centre",
                        -b.rotation, sp.Integer(0), None))  # fmt: skip
            other = _MISTAKEN_FOR.get(b.body.kind)
            # the body's own I_cm is what the student works out: named by the slip, shown on request
            own = Correct("moment of inertia about the axis", b.inertia)
            if other is not None:
                # I_cm of the other kind: the rotation's piece scaled by the ratio of the two moments of inertia
                wrong = INERTIA[other] * b.mass * b.size**2
                out.append((f"rigid.taken_as_{other}.{i}", f"the {label} taken as a {_ROLLING_WORDS[other]}: I = "
                            f"{spoken(wrong)} in place of a {_ROLLING_WORDS[b.body.kind]}'s moment of inertia about its "
                            "axis", sp.expand(b.rotation * (wrong / b.inertia - 1)), sp.Integer(0), own))  # fmt: skip
            # any other kind's I_cm (a sphere's ⅖ m r² for a cylinder's): the rotation's piece scaled as above
            for kind in INERTIA:
                if kind not in (b.body.kind, other):
                    wrong = INERTIA[kind] * b.mass * b.size**2
                    out.append((f"rigid.taken_as_{kind}.{i}", f"{_WRONG_INERTIA} I_cm of a {_ROLLING_WORDS[kind]}, "
                                f"{spoken(wrong)}, in place of a {_ROLLING_WORDS[b.body.kind]}'s",
                                sp.expand(b.rotation * (wrong / b.inertia - 1)), sp.Integer(0), own))  # fmt: skip
        centre = set().union(*(c.free_symbols for c in b.centre)) & set(d.table.q)
        for j, position in enumerate(d.mechanics.positions):
            carrier = d.system.particles[j].label or f"mass {j + 1}"
            shared = [q for q in d.table.q if q in centre and any(q in c.free_symbols for c in position)]
            for q in shared:
                # v_cm taken relative to the carrier, as if it stood still: the translation without q's rate
                rate = d.table.qd[d.table.q.index(q)]
                change = sp.expand(b.translation.xreplace({rate: 0}) - b.translation)
                if change != 0:
                    out.append((f"rigid.carrier_left_out.{i}.{j}", f"the {carrier}'s motion left out of the "
                                f"{label}'s velocity: the {carrier} carries the {label}'s centre, so v_cm has "
                                f"{unicode(rate.name)} in it as well", change, sp.Integer(0), None))  # fmt: skip
    return out


def inertia_in_potential(d: Derivation, truth: sp.Expr, known) -> Iterator[Mistake]:
    """U times a pure-number sum that multiplies a velocity squared in T (the helix's 1 + R² α²): a factor of
    inertia, which a constraint's extra motion adds to T, put into U as if it added weight. A
    sum with units (a mass M + 4 m₁) in U is a units slip, named so first."""
    T, rates = d.mechanics.T, d.table.qd
    if T is None or truth == 0 or not truth.free_symbols & set(d.table.q):
        return
    seen: list[sp.Expr] = []
    for monomial, coefficient in sp.collect(sp.expand(T), list(rates), evaluate=False).items():
        if monomial == 1:
            continue
        for f, _ in sp.factor_list(sp.factor(coefficient))[1]:
            if not f.is_Add or f.free_symbols & set(rates) or f in seen or dimension(f, known) != {}:
                continue
            seen.append(f)
            alone = "U is m g × height alone" if any(x.name == "g" for x in truth.free_symbols) else "U has no such factor"
            yield Mistake(
                f"potential.inertia_factor.{len(seen)}", "inertia_in_u", f"the factor {spoken(f)}, which belongs to T",
                None,
                f"it multiplies {spoken(monomial)} there, from the extra motion the constraint adds; that is more "
                f"inertia, not more weight, so {alone}",
                truth * f,
            )  # fmt: skip


# ---- mistakes that travel --------------------------------------------------------------------------


def travelled(d: Derivation, step: str, k: int | None, truth: sp.Expr, known, asked: list) -> Iterator[Mistake]:
    """A rigid body's slips in T and U, and the mistakes of T and U (generated, and a rigid body's) carried
    into the equation and into ω²."""
    if d.mechanics.T is None:
        return
    rigid = rigid_alternatives(d, known)
    if step in ("kinetic", "potential"):
        for key, name, dT, dU, correct in rigid:
            change = dT if step == "kinetic" else dU
            # the reason is the step's own: T's for a slip of T, U's for a slip of U
            why = (
                rigid_kinetic_rule(d, known)
                if step == "kinetic"
                else "a rigid body's U is its mass × g × the height of its centre, where its weight acts"
            )
            if change != 0:
                yield Mistake(f"{step}.{key}", "rigid", name, None, why, truth + change,
                              correct=correct if step == "kinetic" else None)  # fmt: skip
        return
    if step == "momentum" and k is not None:
        # p = ∂L/∂q̇ of a T with a rigid body's slip: p changes by ∂(ΔT)/∂q̇ (the pulley's turning forgotten gives
        # (m₁ + m₂) ẏ), named as that slip
        for key, name, dT, dU, correct in rigid:
            change = sp.expand(sp.diff(dT - dU, d.table.qd[k]))
            if change != 0:
                yield Mistake(f"momentum.{key}", "rigid", name, None,
                              "your momentum is what such a T gives: p = ∂L/∂q̇ keeps every term of T with this "
                              "velocity in it", truth + change, correct=correct)  # fmt: skip
        return
    if step not in ("equation", "acceleration", "omega_squared"):
        return
    if step == "acceleration" and k is not None and len(d.table.q) != 1:
        # coupled accelerations: the equations' mistakes are carried by mistake_equations; a rigid body's slip
        # changes the mass matrix too, so its equations are solved anew (the turning forgotten: a block's s̈)
        yield from _rigid_coupled(d, k, rigid)
        return
    changes: list[tuple[str, str, sp.Expr, sp.Expr, Correct | None]] = list(rigid)
    T, U = d.mechanics.T, d.mechanics.U
    for m in list(kinetic_mistakes(d))[:MAX_TRAVEL]:
        changes.append((f"from_kinetic.{m.key}", f"a T {_slip_words(m)}", m.expr - T, sp.Integer(0), m.correct))
    if U is not None:
        for m in list(potential_mistakes(d))[:MAX_TRAVEL]:
            if step == "equation" and k is not None and m.family == "term_sign" and m.piece is not None:
                yield from _force_sign(d, k, truth, m.piece)
            if step == "equation" and k is not None and m.family == "doubled" and _one_term_doubled(m, U):
                yield from _force_twice(d, k, truth, m.piece)
            changes.append((f"from_potential.{m.key}", f"a U {_slip_words(m)}", sp.Integer(0), m.expr - U, m.correct))
    for key, name, dT, dU, correct in changes[: 2 * MAX_TRAVEL]:
        if step == "equation" and k is not None:
            # L = T − U changes by ΔT − ΔU, and the equation by its Euler–Lagrange expression
            change = euler_lagrange_of(d.table, k, dT - dU)
            wrong = truth + change
            if key.startswith("rigid"):
                yield Mistake(f"equation.{key}", "rigid", name, None,
                              "your equation is what such a step gives: if your earlier step has that slip, fix it "
                              "there and derive again", wrong)  # fmt: skip
                continue
            lost = _terms_lost(d, k, truth, change, dT - dU, name)
            if lost is not None:
                yield Mistake(f"equation.{key}", "terms_left_out", *lost, wrong)
                continue
            yield Mistake(f"equation.{key}", "travelled", name, None,
                          "your equation is what such a step gives: if your earlier step has that slip, fix it there "
                          "and derive again", wrong, correct=correct)  # fmt: skip
        elif step == "acceleration":
            # one coordinate: E' = a q̈ + f, so q̈ = −f/a
            E = d.equations.residuals[0] + euler_lagrange_of(d.table, 0, dT - dU)
            a = sp.diff(E, d.table.qdd[0])
            if a != 0:
                family = "rigid" if key.startswith("rigid") else "travelled"
                yield Mistake(f"acceleration.{key}", family, name, None,
                              "your acceleration is what such a step gives: if your earlier step has that slip, fix it "
                              "there and derive again",
                              sp.cancel(-E.subs(d.table.qdd[0], 0) / a), correct=correct)  # fmt: skip
        elif step == "omega_squared":
            if name.startswith(_WRONG_INERTIA):
                # another kind's I_cm only scales ω² by a number, which has many causes (the rod's 2g/(3l), a disc's
                # I_cm, is also the number 2/3 upside down): named at T and the equation alone
                continue
            for w in _omega_changed(d, dT, dU, asked):
                family = "rigid" if key.startswith("rigid") else "travelled"
                w2 = f"{frequency_letter('frequency', d)}²"  # Ω² where ω is a parameter
                yield Mistake(f"omega_squared.{key}", family, name, None,
                              f"your {w2} follows from it: {w2} is the effective potential's second derivative over "
                              f"the {inertia(d).words}, at the equilibrium", w, correct=correct)  # fmt: skip


# the turning forgotten leaves a body that slides as a point, as a block does: its accelerations are a block's
_SLIDES = "that is the acceleration of a body that slides without turning, such as a block"


def _rigid_coupled(d: Derivation, k: int, rigid: list) -> Iterator[Mistake]:
    """q̈_k from every equation of an L with a rigid body's slip, solved together: M' q̈ = f'."""
    t = d.table
    zero = dict.fromkeys(t.qdd, sp.Integer(0))
    for key, name, dT, dU, correct in rigid:
        # each equation changes by the Euler–Lagrange expression of ΔL = ΔT − ΔU
        wrong = [sp.expand(r + euler_lagrange_of(d.table, j, dT - dU)) for j, r in enumerate(d.equations.residuals)]
        M = sp.Matrix([[sp.diff(r, a) for a in t.qdd] for r in wrong])
        if M.det() == 0:
            continue
        solved = sp.factor(M.LUsolve(sp.Matrix([-r.xreplace(zero) for r in wrong]))[k])
        why = _SLIDES if key.startswith("rigid.turning_forgotten") else "your acceleration is what such a T gives"
        # the slip by its short name (the part before its own colon): a hint's sentence holds one colon
        yield Mistake(f"acceleration.{key}", "rigid", name.split(": ")[0], None,
                      f"{why}. If your T has that slip, fix it there and derive again", solved,
                      correct=correct)  # fmt: skip


def _terms_lost(
    d: Derivation, k: int, truth: sp.Expr, change: sp.Expr, dL: sp.Expr, slip: str
) -> tuple[str, None, str] | None:
    """A slip of T or U that, carried into the equation of q_k, only leaves some of the equation's terms out: named
    by the terms of this equation that are missing, with where they come from, and the earlier step blamed only
    conditionally and second (a correct T was blamed for an equation's own dropped terms).

    ``change`` is the equation's change, E(ΔL) with ΔL = ΔT − ΔU; ``slip`` is "a T that …" or "a U …"."""
    lost = sp.expand(-change)
    right = set(sp.Add.make_args(sp.expand(truth)))
    if lost == 0 or not set(sp.Add.make_args(lost)) <= right or lost == sp.expand(truth):
        return None
    # the terms of T (or of U) left out that give these terms of the equation: the part of ΔL whose
    # Euler–Lagrange expression for q_k is not zero
    source = sp.Add(*(t for t in sp.Add.make_args(sp.expand(-dL)) if euler_lagrange_of(d.table, k, t) != 0))
    piece, what = ("T", source) if slip.startswith("a T") else ("U", -source)
    t = d.table
    moving = (*t.q, *t.qd, *t.qdd)  # each product's coordinates after its constants: m₂ l₁ l₂ (θ̈₁ cos(θ₁ − θ₂) …)
    several = len(sp.Add.make_args(lost)) > 1
    terms = f"the terms {_constants_first(short_form(lost), moving)}" if several else f"the term {spoken(short_form(lost), moving)}"
    # a term of T with two different velocities is the cross term of the squared velocity
    cross = piece == "T" and len(sp.Add.make_args(what)) == 1 and sum(what.has(v) for v in t.qd) == 2
    kind = "the cross term" if cross else "the terms" if len(sp.Add.make_args(what)) > 1 else "the term"
    origin = f"{kind} {spoken(short_form(what), moving)} of {piece}"
    own = slip.split(" ", 2)[2] if slip.startswith(("a T ", "a U ")) else slip
    comes = "they come" if several else "it comes"
    return (
        f"{terms} left out",
        None,
        f"{comes} from {origin}. If your {piece} {_as_verb(own)}, that is where the slip is; if your {piece} has "
        f"{kind.replace('the ', 'that ', 1).replace('terms', 'part')}, the slip is in differentiating it",
    )


def _constants_first(expr: sp.Expr, moving: tuple[sp.Symbol, ...]) -> str:
    """A product of constants and a sum, the constants first: m₂ l₁ l₂ (θ̈₁ cos(θ₁ − θ₂) − θ̇₁² sin(θ₁ − θ₂))."""
    constant, rest = sp.factor_terms(expr).as_independent(*moving, as_Add=False)
    if constant == 1 or not rest.is_Add:
        return spoken(expr, moving)
    sign = "−" if constant.could_extract_minus_sign() else ""
    return f"{sign}{spoken(-constant if sign else constant)} ({spoken(rest, moving)})"


def _as_verb(clause: str) -> str:
    """A clause after "a T" ("that leaves out …", "with … reversed") said after "if your T": "leaves out …",
    "has … reversed"."""
    if clause.startswith("that "):
        return clause[len("that ") :]
    if clause.startswith("with "):
        return "has " + clause[len("with ") :]
    return clause


def _force_sign(d: Derivation, k: int, truth: sp.Expr, u: sp.Expr) -> Iterator[Mistake]:
    """A force from one term u of U written with its sign reversed in the equation: named as that force, since no
    U is typed in this step (the same equation as a U with u's sign reversed)."""
    q = d.table.q[k]
    # the generalized force of u along q is −∂u/∂q; the equation d/dt(∂L/∂q̇) − ∂L/∂q holds +∂u/∂q
    force = -sp.diff(u, q)
    if force == 0:
        return
    shown, term = spoken(short_form(force)), spoken(sp.factor(u))
    yield Mistake(
        f"equation.force_sign.{slug(sp.sstr(u))[:48]}", "force_sign", f"the sign of your force {spoken(-force)}",
        force, f"the force along {spoken(q)} from the term {term} of U is −∂/∂{spoken(q)} of it, {shown}",
        truth - 2 * sp.diff(u, q),
    )  # fmt: skip


def _one_term_doubled(m: Mistake, U: sp.Expr) -> bool:
    """Whether a mistake of U is one of U's terms (its piece, not the whole U) counted twice."""
    return m.piece is not None and m.piece != U and sp.expand(m.expr - U - m.piece) == 0


def _force_twice(d: Derivation, k: int, truth: sp.Expr, u: sp.Expr) -> Iterator[Mistake]:
    """A force from one term u of U written twice in the equation (m ẍ₂ = −k x₂ − κ (x₂ − x₁) − k x₂).
    The same equation follows from a U with u doubled (a spring's ½ lost), so both causes are said."""
    q = d.table.q[k]
    # the generalized force of u along q is −∂u/∂q; the equation d/dt(∂L/∂q̇) − ∂L/∂q holds +∂u/∂q once
    force = -sp.diff(u, q)
    if force == 0:
        return
    yield Mistake(
        f"equation.force_twice.{slug(sp.sstr(u))[:48]}", "counted_twice",
        f"the force {spoken(short_form(force))} counted twice", force,
        f"each force enters the equation once, as −∂/∂{spoken(q)} of its term of U (here {_with_half(u)}): "
        f"either this force was written again beside it, or it came from a U with {_with_half(2 * u)} where "
        f"{_with_half(u)} belongs", truth + sp.diff(u, q),
    )  # fmt: skip


def _with_half(term: sp.Expr) -> str:
    """A term as a textbook prints it, its ½ in front: ½ k x₂², never k x₂²/2."""
    c, rest = sp.factor(term).as_coeff_Mul()
    return f"½ {spoken(rest)}" if c == sp.Rational(1, 2) else spoken(term)


def _slip_words(m: Mistake) -> str:
    """A mistake of T or U as a clause after "a T" or "a U": "with the sign of … reversed", "with the ½ of … left
    out of …", "that leaves out …".  No T or U is typed in the step the clause is said in, so the name's "your
    term" is "the term"; a name that already says what is left out (or how a term is wrong) takes "with", so that
    no clause says "leaves out … left out"."""
    name = re.sub(r"\byour\b", "the", m.name)
    if m.family == "term_sign":
        return f"with {name} reversed"
    if says_how(name):
        return f"with {name}"
    return f"that leaves out {name}"


def _omega_changed(d: Derivation, dT: sp.Expr, dU: sp.Expr, asked: list) -> list[sp.Expr]:
    red = d.reduction
    if red is None or red.momenta or len(d.table.q) != 1:
        return []
    q, v = d.table.q[0], d.table.qd[0]
    # U_eff = U − T₀ (the part of T free of the velocity); m_eff = ∂²T/∂q̇²
    dT0 = dT.subs(v, 0)
    ueff = red.effective_potential + dU - dT0
    meff = red.effective_mass + sp.diff(dT, v, 2)
    out = []
    for e in asked:
        w = (sp.diff(ueff, q, 2) / meff).subs(q, e.position)
        out.append(sp.simplify(w))
    return out


def effective_terms(d: Derivation, asked: list) -> Iterator[Mistake]:
    """ω² with one term of U_eff left out, or of the wrong sign (the centrifugal term, a spring's, gravity's)."""
    red = d.reduction
    if red is None:
        return
    r = next(s for s in d.table.q if s.name == red.coordinate)
    U = d.mechanics.U
    own = set(sp.Add.make_args(sp.expand(U))) if U is not None else set()
    terms = sorted(sp.Add.make_args(sp.expand(red.effective_potential)), key=sp.default_sort_key)
    if len(terms) > MAX_PIECES:
        return
    for e in asked:
        w = e.omega_squared
        for u in terms:
            part = sp.diff(u, r, 2) / red.effective_mass
            part = part.subs(r, e.position)
            if part == 0:
                continue
            # a term of U_eff that is not a term of U comes from the motion: p²/(2 m r²), −½ m ω² ρ²
            centrifugal = u.has(*red.momenta) or (U is not None and u not in own)
            params = sorted((unicode(x.name) for x in u.free_symbols if x != r), key=str)
            what = "the centrifugal term" if centrifugal else f"the term with {', '.join(params)}"
            yield Mistake(
                f"omega_squared.effective_left_out.{term_key(u)}", "left_out", f"{what} of U_eff left out", u,
                f"{frequency_letter('frequency', d)}² is the effective potential's second derivative at the "
                f"equilibrium over the {inertia(d).words}: it "
                "takes every term of the effective potential, the motion's (centrifugal) ones as well as U's", w - part,
            )  # fmt: skip
            yield Mistake(
                f"omega_squared.effective_sign.{term_key(u)}", "term_sign", f"the sign of {what} of U_eff", u,
                "the centrifugal term of the effective potential pushes outward: it is minus the part of T free of "
                "the velocities, and falls away from the axis", w - 2 * part,
            )  # fmt: skip
