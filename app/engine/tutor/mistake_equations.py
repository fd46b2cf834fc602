"""Mistakes of the momenta, the Euler–Lagrange equations, the accelerations and ω², from the derivation.

For the equation E_k = d/dt p_k − ∂L/∂q_k − Q_k of a coordinate q_k:

* each chain-rule term of d/dt p_k = Σ_j (∂p_k/∂q̇_j) q̈_j + Σ_j (∂p_k/∂q_j) q̇_j + ∂p_k/∂t
  left out, named by the factor of p_k it differentiates ("the derivative of
  cos(θ₁ − θ₂) along the motion");
* each part of ∂L/∂q_k left out: the parts of ∂T/∂q_k by their velocities ("T depends
  on θ through sin²θ, so ∂L/∂θ has the φ̇² term"), the force of each term of U (for a
  system given by L alone, ∂/∂q_k of each term of L);
* ∂(½ a q̇²)/∂q̇ taken as ½ a q̇ (the 2 of the square lost);
* Q_k doubled or of the wrong sign; sin x ≈ x and cos x ≈ 1 for every angle (an
  approximation, named so, with when it holds); each part's sign.

The accelerations are what each wrong equation gives with the same mass matrix,
M q̈ = f'.  Momenta: each velocity's part of p_k left out.  ω²: another equilibrium's.
"""

from __future__ import annotations

from collections.abc import Iterator

import sympy as sp

from app.engine.algebra.budget import within_budget
from app.engine.derivation.derive import Derivation
from app.engine.display.names import unicode
from app.engine.display.textbook import unicode_text
from app.engine.document.notation import inertia
from app.engine.tutor.mistake_families import (
    MAX_PER_STEP,
    NAME_WORK,
    FollowUp,
    Mistake,
    kind_of_term,
    kinetic_mistakes,
    potential_mistakes,
    short_form,
    slug,
    spoken,
    sum_words,
    term_key,
    velocity_monomials,
)


def momentum_mistakes(d: Derivation, k: int) -> Iterator[Mistake]:
    p = d.equations.momenta[k]
    name = unicode(d.table.names[k])
    for monomial, part in velocity_monomials(p, d.table.qd).items():
        # in words, never a program's p_y₂: the term that is missing, and why the momentum has it
        what = f"the {spoken(monomial)} term" if monomial != 1 else "the term without velocities"
        dot = unicode(d.table.qd[k].name)
        yield Mistake(
            f"momentum.part_left_out.{slug(sp.sstr(monomial))}",
            "momentum_part",
            f"{what} missing",
            short_form(part),
            f"L has a term with {dot} times "
            + (spoken(monomial) if monomial != 1 else "no other velocity")
            + f", so ∂L/∂{dot}, the momentum conjugate to {name}, keeps it",
            sp.expand(p - part),
        )
    # a position typed where its velocity belongs (m R² θ for m R² θ̇): every factor else may be right
    for q, qd in zip(d.table.q, d.table.qd, strict=True):
        if p.has(qd):
            shown, dot = unicode(q.name), unicode(qd.name)
            yield Mistake(
                f"momentum.position_for_velocity.{slug(q.name)}",
                "position_for_velocity",
                f"{shown} where {dot} belongs (a momentum is a mass times a velocity)",
                None,
                f"p = ∂L/∂{unicode(d.table.qd[k].name)} is taken from the velocity terms of T, and differentiating "
                f"½ a {dot}² by {dot} leaves a {dot}, never {shown}",
                p.xreplace({qd: q}),
            )


def _factors_with(expr: sp.Expr, q: sp.Symbol) -> list[sp.Expr]:
    """The factors of expr's terms that hold q (cos(θ₁ − θ₂), sin²θ, r²): its terms with q, recombined."""
    holding = sp.Add(*(t for t in sp.Add.make_args(sp.expand(expr)) if t.has(q)))
    short = within_budget(lambda: sp.factor(sp.trigsimp(holding)), holding, NAME_WORK)
    found: dict[str, sp.Expr] = {}
    for term in sp.Add.make_args(short):
        for factor in sp.Mul.make_args(term):
            if factor.has(q):
                found.setdefault(sp.sstr(factor), factor)
    return [found[k] for k in sorted(found)]


def _through(p: sp.Expr, q: sp.Symbol) -> str:
    """The factors of p that depend on q, in words: 'cos(θ₁ − θ₂)', 'sin²(θ)'."""
    found = _factors_with(p, q)
    return ", ".join(spoken(f) for f in found) if found else spoken(q)


_EQUATIONS: dict[tuple[int, int], tuple[Derivation, list[Mistake]]] = {}


def equation_mistakes(d: Derivation, k: int) -> list[Mistake]:
    """The mistakes of q_k's equation (remembered per derivation: each acceleration's catalogue uses them all)."""
    found = _EQUATIONS.get((id(d), k))
    if found is not None and found[0] is d:
        return found[1]
    made = list(_equation_mistakes(d, k))
    if len(_EQUATIONS) > 256:
        _EQUATIONS.clear()
    _EQUATIONS[(id(d), k)] = (d, made)
    return made


def _equation_mistakes(d: Derivation, k: int) -> Iterator[Mistake]:
    eqs, m, table = d.equations, d.mechanics, d.table
    E, p = eqs.residuals[k], eqs.momenta[k]
    qdot = unicode(table.qd[k].name)
    dl = f"∂L/∂{qdot}"
    for q, qd in zip(table.q, table.qd, strict=True):
        # the chain rule's term (∂p_k/∂q_j) q̇_j of d/dt p_k
        term = sp.diff(p, q) * qd
        if term == 0:
            continue
        factor = _through(p, q)
        rate = _through_expr(p, q, table)
        shared = len({s for f in _factors_with(p, q) for s in f.free_symbols} & set(table.q)) > 1
        what = f"the derivative of {factor} along the motion" + (
            f" (its part from {unicode(q.name)} changing)" if shared else ""
        )
        yield Mistake(
            f"equation.chain_rule.{q.name}",
            "chain_rule",
            what,
            short_form(term),
            f"{dl} depends on {unicode(q.name)} through {factor}, so its time derivative has the term "
            f"(∂/∂{unicode(q.name)} of {dl}) {unicode(qd.name)}",
            sp.expand(E - term),
            follow_up=FollowUp(
                f"What is the time derivative of {factor} along the motion?",
                "momentum",
                rate,
                "exact",
                f"d/dt {factor} = {spoken(short_form(rate))}",
            )
            if rate is not None
            else None,
        )
    # every velocity-squared term left out at once (the rotating wire's 4 m α² ρ ρ̇²): the chain rule's
    # terms Σ_j (∂p_k/∂q_j) q̇_j of d/dt p_k, less the velocity part of ∂T/∂q_k they partly cancel
    chain = sp.expand(sum((sp.diff(p, q) * qd for q, qd in zip(table.q, table.qd, strict=True)), sp.Integer(0)))
    rates = set(table.qd)
    dT_dq = sp.Add(*(t for t in sp.Add.make_args(sp.expand(eqs.dL_dq[k])) if t.free_symbols & rates))
    net = sp.expand(chain - dT_dq)
    if chain != 0 and dT_dq != 0 and net != 0:
        yield Mistake(
            "equation.chain_rule.all",
            "chain_rule",
            f"the chain-rule terms of d/dt({dl}) left out, with the velocity terms of ∂L/∂{unicode(table.names[k])}"
            f" (together {spoken(short_form(net))})",
            short_form(net),
            f"{dl} depends on the coordinates, so its time derivative has the chain-rule terms "
            f"{spoken(short_form(chain))}; ∂L/∂{unicode(table.names[k])} takes away {spoken(short_form(dT_dq))}, "
            f"and {spoken(short_form(net))} is left in the equation",
            sp.expand(E - net),
        )
    moving = sp.diff(p, table.t)
    if moving != 0:
        yield Mistake(
            "equation.chain_rule.t",
            "chain_rule",
            f"the change of {dl} with t itself, {spoken(short_form(moving))}",
            short_form(moving),
            f"{dl} depends on t (a constraint moves), so d/dt has the term ∂/∂t of {dl}",
            sp.expand(E - moving),
        )
    # ∂(½ a q̇²)/∂q̇ taken as ½ a q̇: p' = p − ½ M_kk q̇_k
    half = sp.Rational(1, 2) * eqs.mass_matrix[k, k] * table.qd[k]
    wrong_p = table.dt(p - half)
    yield Mistake(
        "equation.half_momentum",
        "half_momentum",
        f"the 2 from differentiating the square left out: ∂/∂{qdot} of ½ a {qdot}² is a {qdot}, not ½ a {qdot}",
        half,
        f"the term ½ ({spoken(short_form(eqs.mass_matrix[k, k]))}) {qdot}² of T, differentiated by {qdot}",
        sp.expand(wrong_p - eqs.dL_dq[k] - m.Q[k]),
    )
    yield from _dl_dq_mistakes(d, k, E)
    Q = m.Q[k]
    if Q != 0:
        yield Mistake(
            "equation.force_doubled",
            "force_doubled",
            f"the generalized force Q_{unicode(table.names[k])} = {spoken(Q)} counted twice",
            Q,
            "the force that no potential describes enters once, on the right: d/dt(∂L/∂q̇) − ∂L/∂q = Q",
            sp.expand(E - Q),
        )
        yield Mistake(
            "equation.force_sign",
            "force_sign",
            f"the sign of the generalized force Q_{unicode(table.names[k])} = {spoken(Q)}",
            Q,
            "Q is on the right of d/dt(∂L/∂q̇) − ∂L/∂q = Q: moved to the left it changes sign",
            sp.expand(E + 2 * Q),
        )
    small = _small_angle(E, table)
    if small is not None:
        yield Mistake(
            "equation.small_angle",
            "small_angle",
            "the small-angle approximation sin x ≈ x, cos x ≈ 1",
            sp.expand(E - small),
            "it holds only for small oscillations near zero angle (|angle| ≪ 1 rad); the exercise asks for the "
            "full equation, valid at every angle",
            small,
            approximation=True,
        )
    for monomial, part in velocity_monomials(E, (*table.qd, *table.qdd)).items():
        yield Mistake(
            f"equation.term_sign.{slug(sp.sstr(monomial))}",
            "term_sign",
            f"the sign of your term {spoken(short_form(-part))}",
            short_form(part),
            "each term's sign follows from d/dt(∂L/∂q̇) − ∂L/∂q = Q",
            sp.expand(E - 2 * part),
        )


def _through_expr(p: sp.Expr, q: sp.Symbol, table) -> sp.Expr | None:
    """d/dt of the one factor of p that holds q (cos(θ₁ − θ₂) → sin(θ₁ − θ₂)(θ̇₂ − θ̇₁)), for a follow-up."""
    found = _factors_with(p, q)
    return table.dt(found[0]) if len(found) == 1 and not found[0].is_Symbol else None


def _dl_dq_mistakes(d: Derivation, k: int, E: sp.Expr) -> Iterator[Mistake]:
    m, table = d.mechanics, d.table
    q = table.q[k]
    qn = unicode(q.name)
    kinetic = m.T if m.T is not None else m.L
    letter = "T" if m.T is not None else "L"
    dT = sp.diff(kinetic, q)
    if m.T is None:
        yield from _lagrangian_terms(d, k, E)
        return
    for monomial, part in velocity_monomials(dT, table.qd).items():
        factor = _through(sp.Add(*(t for t in sp.Add.make_args(sp.expand(kinetic)) if t.has(q))), q)
        yield Mistake(
            f"equation.dl_dq_part.{slug(sp.sstr(monomial))}",
            "dl_dq_part",
            f"the {spoken(monomial)} term of ∂L/∂{qn}" if monomial != 1 else f"the velocity-free term of ∂L/∂{qn}",
            short_form(part),
            f"{letter} depends on {qn} through {factor}, so ∂L/∂{qn} has this term",
            sp.expand(E + part),
            follow_up=FollowUp(f"What is ∂{letter}/∂{qn}?", "kinetic", dT, "exact", spoken(short_form(dT))),
        )
    if m.U is not None:
        dynamic = {*table.q, table.t}
        for term in (t for t in sp.Add.make_args(m.U) if t.free_symbols & dynamic):
            force = sp.diff(term, q)
            if force == 0:
                continue
            kind = kind_of_term(term, d)
            spring = _joining_spring(d, term, q)
            yield Mistake(
                f"equation.force_left_out.{term_key(term)}",
                "force_left_out",
                spring[0] if spring else f"the force from {kind[4:]} (its ∂/∂{qn})",
                short_form(force),
                spring[1] if spring else f"∂L/∂{qn} = ∂T/∂{qn} − ∂U/∂{qn}, and {kind} depends on {qn}",
                sp.expand(E - force),
                follow_up=FollowUp(
                    f"What is ∂U/∂{qn}?", "potential", sp.diff(m.U, q), "exact", spoken(short_form(sp.diff(m.U, q)))
                ),
            )


def _stretch(d: Derivation, term: sp.Expr, q: sp.Symbol) -> tuple[sp.Expr, sp.Expr] | None:
    """(stiffness, stretch) of a spring's energy u whose force on q, −∂u/∂q, is stiffness × stretch, the stretch
    with q's own term taken away (κ and x₂ − x₁ for ½ κ (x₂ − x₁)² on x₁); None where u is no such square."""
    force = sp.factor(-sp.diff(term, q))
    sums = [f for f in sp.Mul.make_args(force) if f.is_Add and f.free_symbols & set(d.table.q)]
    if len(sums) != 1:
        return None
    stretch, stiffness = sums[0], force / sums[0]
    # −κ (x₁ − x₂) read as κ (x₂ − x₁): the coordinate pulled on taken away, as the spring's pull says it
    if sp.expand(stretch).coeff(q) > 0:
        stretch, stiffness = -stretch, -stiffness
    return stiffness, sp.expand(stretch)


def _joining_spring(d: Derivation, term: sp.Expr, q: sp.Symbol, over: sp.Expr = sp.S.One) -> tuple[str, str] | None:
    """(name, where) of the force left out from a spring that joins q to another coordinate ("the
    force from spring energy (its ∂/∂x₁)" did not say which spring): the coupling spring, by its force (over
    ``over``, the mass, in an acceleration); None for any other term of U."""
    held = [c for c in d.table.q if term.has(c)]
    found = _stretch(d, term, q)
    if kind_of_term(term, d) != "the spring energy" or len(held) < 2 or found is None:
        return None
    stiffness, stretch = found
    springs = [t for t in sp.Add.make_args(d.mechanics.U) if kind_of_term(t, d) == "the spring energy"]
    owner = "the coupling spring's" if len(springs) > 1 else "the spring's"
    others = " and ".join(unicode(c.name) for c in held if c != q)
    qn, coordinates = unicode(q.name), d.table.q
    stretched = f"({sum_words(stretch, coordinates)})"
    # the force κ (x₂ − x₁), over the mass in an acceleration: κ (x₂ − x₁)/m
    force = f"{spoken(stiffness, coordinates)} {stretched}" + ("" if over == 1 else f"/{spoken(over, coordinates)}")
    # its energy as a textbook prints it, the ½ in front: ½ κ (x₂ − x₁)²
    energy = sp.factor(term / stretch**2)
    half = energy.as_coeff_Mul()[0] == sp.Rational(1, 2)
    energy_words = f"½ {spoken(2 * energy)}" if half else spoken(energy)
    return (
        f"{owner} force {force} left out",
        f"the spring joins {qn} to {others}, so its energy {energy_words} {stretched}² changes with {qn} too, and "
        f"its force on {qn} is −∂/∂{qn} of that energy",
    )


def _lagrangian_terms(d: Derivation, k: int, E: sp.Expr) -> Iterator[Mistake]:
    """For a system given by L alone: ∂/∂q_k of each term of L as declared, left out."""
    q = d.table.q[k]
    qn = unicode(q.name)
    for term in sp.Add.make_args(d.mechanics.L):
        part = sp.diff(term, q)
        if part == 0:
            continue
        yield Mistake(
            f"equation.dl_dq_part.{term_key(term)}",
            "dl_dq_part",
            f"∂/∂{qn} of the term {spoken(term)} of L",
            short_form(part),
            f"the term {spoken(term)} of L depends on {qn}, so ∂L/∂{qn} has its derivative",
            sp.expand(E + part),
            follow_up=FollowUp(
                f"What is ∂L/∂{qn}?", "kinetic", d.equations.dL_dq[k], "exact", spoken(short_form(d.equations.dL_dq[k]))
            ),
        )


def _small_angle(E: sp.Expr, table) -> sp.Expr | None:
    """E with sin x → x, cos x → 1, tan x → x for every x that holds a coordinate; None when nothing changes."""
    coordinates = set(table.q)
    swap = {}
    for f in E.atoms(sp.sin, sp.cos, sp.tan):
        if f.args[0].free_symbols & coordinates:
            swap[f] = sp.Integer(1) if isinstance(f, sp.cos) else f.args[0]
    if not swap:
        return None
    small = sp.expand(E.xreplace(swap))
    return small if small != sp.expand(E) else None


def acceleration_mistakes(d: Derivation, k: int) -> Iterator[Mistake]:
    """Each coordinate's equation mistakes, carried through M q̈ = f' to q̈_k (the same mass matrix)."""
    eqs, table = d.equations, d.table
    n = len(table.names)
    zero = dict.fromkeys(table.qdd, sp.Integer(0))
    dynamic = {*table.q, table.t}
    springs = {f"equation.force_left_out.{term_key(u)}": u for u in sp.Add.make_args(d.mechanics.U or sp.S.Zero)
               if u.free_symbols & dynamic}  # fmt: skip
    # q̈_k alone in its equation (the mass matrix's row and column k diagonal): a force on q_k moves q_k alone, by
    # the force over the mass, and is named so (κ (x₂ − x₁)/m, never "(in the equation for x₁)")
    alone = all(eqs.mass_matrix[k, i] == 0 and eqs.mass_matrix[i, k] == 0 for i in range(n) if i != k)
    for j in range(n):
        for mistake in equation_mistakes(d, j):
            if mistake.family in ("half_momentum", "term_sign") or not mistake.expr.has(*table.qdd):
                continue
            wrong = list(eqs.residuals)
            wrong[j] = mistake.expr
            M = sp.Matrix([[sp.diff(r, a) for a in table.qdd] for r in wrong])
            if M != eqs.mass_matrix:
                continue
            forcing = sp.Matrix([-sp.expand(r).xreplace(zero) for r in wrong])
            solved = M.LUsolve(forcing)[k]
            where = f"in the equation for {unicode(table.names[j])}" if n > 1 else ""
            # what happened to the piece said before where it happened: "… left out (in the equation for x₁)"
            name, why = mistake.said + (f" ({where})" if where else ""), mistake.where
            spring = springs.get(mistake.key)
            if spring is not None and j == k and alone:
                name, why = _joining_spring(d, spring, table.q[k], eqs.mass_matrix[k, k]) or (name, why)
            yield Mistake(
                mistake.key.replace("equation.", "acceleration.", 1) + (f".{table.names[j]}" if n > 1 else ""),
                mistake.family,
                name,
                mistake.piece,
                why,
                solved,
                mistake.approximation,
            )


def omega_mistakes(d: Derivation, asked: list) -> Iterator[Mistake]:
    red = d.reduction
    if red is None:
        return
    r = unicode(red.coordinate)
    for n, e in enumerate(red.equilibria):
        if e in asked or e.omega_squared is None:
            continue
        at = f"{r} = {unicode_text(e.position)}"  # θ = π, θ = arccos(g/(Rw²)): as the step's answer prints it
        # the other equilibrium's ω² the asked one's turned over (−g/R beside g/R): a U of the wrong sign gives it
        # too, so that cause is said beside it
        # (only where U_eff is U: where it holds more, a U turned over alone gives another answer)
        alone = d.mechanics.U is not None and sp.simplify(red.effective_potential - d.mechanics.U) == 0
        turned = alone and any(
            a.omega_squared is not None and sp.expand(a.omega_squared + e.omega_squared) == 0 for a in asked
        )
        asked_at = ", ".join(f"{r} = {unicode_text(a.position)}" for a in asked) or "the equilibrium asked for"
        sign = f". Or, at {asked_at}, your U has its sign reversed, which turns ω² over" if turned else ""
        yield Mistake(
            f"omega_squared.other_equilibrium.{n}",
            "other_equilibrium",
            f"ω² at the other equilibrium {at}",
            e.omega_squared,
            f"ω² (the effective potential's second derivative over the {inertia(d).words}) is taken at the equilibrium asked for; {at} is another one{sign}",
            e.omega_squared,
        )


def generated(d: Derivation, step: str, k: int | None, asked: list | None = None) -> list[Mistake]:
    """The generated mistakes of one step (at most MAX_PER_STEP), most specific first."""
    if step == "kinetic":
        found = list(kinetic_mistakes(d))
    elif step == "potential":
        found = list(potential_mistakes(d))
    elif step == "momentum" and k is not None:
        found = list(momentum_mistakes(d, k))
    elif step == "equation" and k is not None:
        found = list(equation_mistakes(d, k))
    elif step == "acceleration" and k is not None:
        found = list(acceleration_mistakes(d, k))
    elif step == "omega_squared":
        found = list(omega_mistakes(d, asked or []))
    else:
        found = []
    return found[:MAX_PER_STEP]
