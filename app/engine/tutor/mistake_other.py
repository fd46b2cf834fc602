"""Two wrong answers that are right answers to another question, named as that question.

* **another coordinate's answer**: the momentum, equation or acceleration of q_j typed where q_k's is asked
  for (p_θ₁ in the box of p_θ₂: "the momentum conjugate to θ₁: you differentiated with respect to θ̇₁");
* **the answer of a limit**: the truth with one body's mass taken to infinity or to zero (the block
  on a wedge, D̈ = g sin α: the fixed wedge's answer, while the wedge recoils); for T and L the body
  held still (T = ½ m Ḋ²: the wedge's Ẋ set to zero, in its own ½ M Ẋ² and in the block's velocity).

Both are bounded by counts: one candidate per other coordinate; three limits (held still, without mass,
infinitely heavy) for each of at most ``MAX_BODIES`` bodies with a mass of their own.
"""

from __future__ import annotations

from collections.abc import Iterator

import sympy as sp

from app.engine.derivation.comparisons import MAX_BODIES, mass_limit, stops_when_heavy
from app.engine.derivation.derive import Derivation
from app.engine.display.names import unicode
from app.engine.display.spoken import spoken
from app.engine.tutor.mistake_families import Mistake


def other_coordinates(d: Derivation, step: str, k: int | None) -> Iterator[Mistake]:
    """The same step's answer for each other coordinate."""
    if k is None or step not in ("momentum", "equation", "acceleration"):
        return
    eqs, names = d.equations, d.table.names
    asked, asked_rate = unicode(names[k]), unicode(f"{names[k]}_dot")
    for j, other in enumerate(names):
        if j == k:
            continue
        q, rate = unicode(other), unicode(f"{other}_dot")
        if step == "momentum":
            yield Mistake(
                f"momentum.other_coordinate.{other}", "other_coordinate", f"the momentum conjugate to {q}", None,
                f"you differentiated L with respect to {rate}; the momentum conjugate to {asked} is ∂L/∂{asked_rate}",
                eqs.momenta[j],
            )  # fmt: skip
        elif step == "equation":
            yield Mistake(
                f"equation.other_coordinate.{other}", "other_coordinate", f"the equation for {q}", None,
                f"that is d/dt(∂L/∂{rate}) − ∂L/∂{q}; the equation for {asked} differentiates L by {asked_rate} "
                f"and by {asked}", eqs.residuals[j],
            )  # fmt: skip
        else:
            yield Mistake(
                f"acceleration.other_coordinate.{other}", "other_coordinate", f"the acceleration of {q}", None,
                f"this box asks for the second derivative of {asked}, solved from the equations of motion",
                eqs.accelerations[j],
            )  # fmt: skip


def held_still(d: Derivation, step: str, truth: sp.Expr, k: int | None = None) -> Iterator[Mistake]:
    """The truth with one body's mass taken to a limit: to infinity where that holds the body still (its one
    coordinate's acceleration then vanishes, and may be the answer: the wedge's Ẍ = 0), to zero (a body without
    mass), then to infinity otherwise (a body nothing else can move); each where the limit is finite, not zero
    (but for a body held still), and differs from the truth.  An equation: the held body's coordinate fixed."""
    namespace = d.table.namespace()
    bodies = [(i, p.mass, p.label) for i, p in enumerate(d.system.particles) if p.mass in namespace][:MAX_BODIES]
    # a declared rigid body counts among the bodies in an acceleration, though its own mass is not tried (the
    # cylinder on the wedge: its equation and T name the wedge's motion left out of v_cm, mistake_pieces)
    carried = len(d.mechanics.bodies) if step == "acceleration" else 0
    if len(bodies) + carried < 2:
        return  # one body: nothing else to hold still or to leave out
    if step == "equation" and k is not None:
        yield from _fixed_in_equation(d, bodies, truth, k)
        return
    if step in ("kinetic", "lagrangian"):
        yield from _fixed_in_energy(d, bodies, truth, step)
        return
    if step not in ("acceleration", "omega_squared"):
        return
    still, light, heavy = [], [], []
    for i, mass_name, label in bodies:
        M, shown = namespace[mass_name], unicode(mass_name)
        body = label or f"body of mass {shown}"
        key = f"{step}.limit"
        zero = mass_limit(truth, M, 0)
        if zero is not None:
            light.append(Mistake(
                f"{key}.massless.{mass_name}", "limit", f"{spoken(zero)}, the answer if the {body} had no mass "
                f"({shown} → 0)", None, f"the {body} has mass {shown} and pushes or pulls on the rest, so {shown} "
                "stays in the answer", zero,
            ))  # fmt: skip
        held = stops_when_heavy(d, i, M)
        infinite = mass_limit(truth, M, sp.oo, allow_zero=held)
        if infinite is None:
            continue
        if held and step == "acceleration":
            # the carrier's acceleration → 0 as M → ∞: the answer of the carrier held fixed (the fixed wedge's
            # s̈ = 2g sin α/3), where its recoil couples the equations
            equations = " and ".join(unicode(q) for q in d.table.names)
            still.append(Mistake(
                f"{key}.held_still.{mass_name}", "limit", f"the acceleration with the {body} held fixed ({shown} → ∞)",
                None, f"here the {body} recoils, so the {equations} equations are solved together", infinite,
            ))  # fmt: skip
        elif held:
            still.append(Mistake(
                f"{key}.held_still.{mass_name}", "limit", f"the answer with the {body} treated as fixed, as if held "
                f"still ({shown} → ∞)", None, f"here the {body} is free to move and recoils as the rest moves, so "
                f"its mass {shown} stays in the answer", infinite,
            ))  # fmt: skip
        else:
            heavy.append(Mistake(
                f"{key}.infinitely_heavy.{mass_name}", "limit", f"{spoken(infinite)}, the answer if the {body} "
                f"were infinitely heavy ({shown} → ∞), so that nothing else could push or pull it", None,
                f"the rest pushes and pulls on the {body} too, so its mass {shown} stays in the answer", infinite,
            ))  # fmt: skip
    for m in (*still, *light, *heavy):
        if sp.expand(m.expr - truth) != 0:
            yield m
    if step == "acceleration" and k is not None:
        yield from _own_equation_alone(d, k)
    if step == "acceleration":
        # a one-body limit taken at small angles as well (the upper bob as a simple pendulum, θ̈₁ = −g θ₁/l₁)
        for m in light:
            small = linear(d, m.expr)
            if small is not None and sp.expand(small - m.expr) != 0:
                yield Mistake(
                    f"{m.key}.small_angle", "small_angle", f"the small-angle approximation sin x ≈ x of {m.name}",
                    None, f"{m.where}; and sin x ≈ x holds only near zero angle, while the exercise asks for the "
                    "full acceleration", small, approximation=True,
                )  # fmt: skip


def _own_equation_alone(d: Derivation, k: int) -> Iterator[Mistake]:
    """q̈_k solved from q_k's own equation alone, every other acceleration in it set to zero, as if what those
    coordinates move were held still (the pulley's ÿ₁ as an Atwood machine with the right mass
    fixed, g (M/2 − m₁)/(m₁ + M/4)): where the equations are coupled through their accelerations."""
    eqs, t = d.equations, d.table
    others = [j for j in range(len(t.q)) if j != k and eqs.mass_matrix[k, j] != 0]
    if not others or eqs.mass_matrix[k, k] == 0:
        return
    # M_kk q̈_k + f_k = 0, with f_k = E_k at q̈ = 0
    forcing = sp.expand(eqs.residuals[k]).xreplace(dict.fromkeys(t.qdd, sp.Integer(0)))
    alone = sp.cancel(-forcing / eqs.mass_matrix[k, k])
    moved = {t.q[j] for j in others}
    positions = d.mechanics.positions
    labels = [p.label or f"body of mass {unicode(p.mass)}" for p in d.system.particles]
    # the bodies the other coordinates alone move (held still), and those that move with both (which couple them)
    held = [b for b, r in zip(labels, positions, strict=False) if (_moved(r, t) and _moved(r, t) <= moved)]
    joint = [b for b, r in zip(labels, positions, strict=False) if t.q[k] in _moved(r, t) and _moved(r, t) & moved]
    accelerations = " and ".join(unicode(t.qdd[j].name) for j in others)
    coordinate = unicode(t.names[k])
    together = " and ".join([coordinate, *(unicode(t.names[j]) for j in others)])
    still = f"the {' and the '.join(held)} were held still" if held else f"{accelerations} were zero"
    moves = f"the {' and the '.join(held)} moves too" if held else "the other coordinates change too"
    couples = (
        f"the {' and the '.join(joint)} moves with both {together}, which puts {accelerations} into the equation "
        f"for {coordinate}"
        if joint
        else f"the equation for {coordinate} holds {accelerations}"
    )
    yield Mistake(
        f"acceleration.limit.own_equation.{t.names[k]}", "limit",
        f"the answer from the equation for {coordinate} alone, with {accelerations} = 0, as if {still}", None,
        f"{moves}, so {accelerations} is not zero; {couples}, so the equations are solved together", alone,
    )  # fmt: skip


def _moved(r: tuple, t) -> set[sp.Symbol]:
    """The coordinates a body's position holds."""
    return {s for c in r for s in c.free_symbols if s in t.q}


def linear(d: Derivation, expr: sp.Expr) -> sp.Expr | None:
    """expr to first order about rest at zero (every coordinate and velocity 0), where that is an equilibrium
    (expr vanishes there) and expr holds a sine or cosine of a coordinate; else None."""
    t = d.table
    angles = [q for q in t.q if any(f.args[0].has(q) for f in expr.atoms(sp.sin, sp.cos))]
    if not angles:
        return None
    rest = {**{q: 0 for q in t.q}, **{v: 0 for v in t.qd}}
    if sp.cancel(expr.xreplace(rest)) != 0:
        return None
    # f ≈ Σ (∂f/∂q)₀ q + Σ (∂f/∂q̇)₀ q̇
    out = sum((sp.diff(expr, x).xreplace(rest) * x for x in (*t.q, *t.qd)), sp.Integer(0))
    return sp.expand(sp.cancel(out))


def _fixed_in_equation(d: Derivation, bodies: list, truth: sp.Expr, k: int) -> Iterator[Mistake]:
    """q_k's equation with a body held still: that body's one coordinate q_j neither moving nor accelerating
    (q̇_j = q̈_j = 0), as if its mass were infinite; j ≠ k."""
    namespace, t = d.table.namespace(), d.table
    for i, mass_name, label in bodies:
        M, shown = namespace[mass_name], unicode(mass_name)
        if not stops_when_heavy(d, i, M):
            continue
        moves = {s for c in d.mechanics.positions[i] for s in c.free_symbols if s in t.q}
        j = t.q.index(next(iter(moves)))
        if j == k:
            continue
        fixed = sp.expand(truth.xreplace({t.qd[j]: 0, t.qdd[j]: 0}))
        if fixed == 0 or sp.expand(fixed - truth) == 0:
            continue
        body = label or f"body of mass {shown}"
        yield Mistake(
            f"equation.limit.held_still.{mass_name}", "limit", f"the equation with the {body} treated as fixed, as "
            f"if held still ({shown} → ∞), which has no {unicode(t.qdd[j].name)}", None,
            f"here the {body} is free to move and recoils as the rest moves, so {unicode(t.names[j])} changes and "
            "its acceleration stays in the equation", fixed,
        )  # fmt: skip


def _fixed_in_energy(d: Derivation, bodies: list, truth: sp.Expr, step: str) -> Iterator[Mistake]:
    """T (or L) with a body held still: that body's one coordinate q_j not moving (q̇_j = 0), as if its mass were
    infinite; this drops the body's own ½ M v² and the q̇_j part of every body it carries (only a body that
    carries another is held still: one that carries none is forgotten)."""
    namespace, t = d.table.namespace(), d.table
    letter = "T" if step == "kinetic" else "L"
    whole = "the kinetic energy" if step == "kinetic" else "the Lagrangian"
    for i, mass_name, label in bodies:
        M, shown = namespace[mass_name], unicode(mass_name)
        if not stops_when_heavy(d, i, M):
            continue
        q = next(s for c in d.mechanics.positions[i] for s in c.free_symbols if s in t.q)
        j = t.q.index(q)
        # T(q̇_j = 0): the held body's coordinate neither moves nor carries anything along
        fixed = sp.expand(truth.xreplace({t.qd[j]: 0}))
        if fixed == 0 or sp.expand(fixed - truth) == 0:
            continue
        body, rate = label or f"body of mass {shown}", unicode(t.qd[j].name)
        # the bodies whose positions hold q_j: the held body carries them along
        carried = [
            p.label or f"body of mass {unicode(p.mass)}"
            for n, p in enumerate(d.system.particles)
            if n != i and any(c.has(q) for c in d.mechanics.positions[n])
        ]
        if not carried:
            continue  # a body that carries nothing, held still, is a body forgotten (app.engine.tutor.mistake_families)
        carries = f" and carries the {' and the '.join(carried)} with it"
        yield Mistake(
            f"{step}.limit.held_still.{mass_name}", "limit", f"{whole} with the {body} treated as fixed, as if held "
            f"still ({shown} → ∞), which has no {rate}", None,
            f"here the {body} moves{carries}, so {letter} has the {body}'s own ½ {shown} v² and the {rate} terms of "
            "every body it moves", fixed,
        )  # fmt: skip
