"""Cyclic coordinates, the Hamiltonian h, the energy E, and whether h = E.

    p_k = dL/dq_dot_k is conserved when q_k is absent from L and Q_k = 0,
    h = sum_k p_k q_dot_k - L,   dh/dt = -dL/dt|explicit + sum_k Q_k q_dot_k.

Writing T = T2 + T1 + T0 by degree in the velocities, Euler's theorem on
homogeneous functions gives sum_k q_dot_k dT/dq_dot_k = 2 T2 + T1, hence

    h = T2 - T0 + U   and   E - h = T1 + 2 T0,

which vanishes exactly when T is a homogeneous quadratic form.  T1 and T0 have
two possible origins, and the reason given names each one present: positions
that depend explicitly on time (a moving constraint: with r(q, t),
v = sum_k dr/dq_k q_dot_k + dr/dt, so T1 = sum m v_q . dr/dt and
T0 = sum m |dr/dt|^2 / 2), or terms the user wrote into T directly (a
velocity-linear, gyroscopic or magnetic term; a velocity-free term such as a
rotating frame's centrifugal one).  When only L is given, T and U cannot be
told apart and whether h = E is left undecided (None), never claimed.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

import sympy as sp

from app.engine.algebra.simplify import is_zero, tidy
from app.engine.display.names import unicode
from app.engine.equations.lagrange import Equations
from app.engine.equations.mechanics import Mechanics
from app.engine.equations.noether import symmetries


@dataclass(frozen=True)
class Conserved:
    name: str
    latex_name: str
    expr: sp.Expr
    reason: str


@dataclass(frozen=True)
class Energetics:
    cyclic: tuple[str, ...]
    conserved: tuple[Conserved, ...]
    dL_dt: sp.Expr
    hamiltonian: sp.Expr
    energy: sp.Expr
    energy_minus_h: sp.Expr
    h_equals_e: bool | None  # None: undecidable (only L was given)
    reason: str
    power: sp.Expr
    h_conserved: bool
    h_conserved_reason: str


# the most coordinates whose common translations are tried (2^n − n − 1 subsets)
TRANSLATION_MAX_COORDINATES = 4


def _translations(mech: Mechanics, eqs: Equations, cyclic: tuple[str, ...]) -> list[Conserved]:
    """Sums of momenta conserved because L is unchanged when several coordinates move together (the rail's
    p_x₁ + p_x₂, the total momentum): Σ ∂L/∂q_k = 0 over the set and no generalized force along it."""
    table = mech.table
    free = [k for k, name in enumerate(table.names) if name not in cyclic]
    if len(table.names) > TRANSLATION_MAX_COORDINATES:
        return []
    found: list[Conserved] = []
    groups: list[set[int]] = []
    for size in range(2, len(free) + 1):
        for group in combinations(free, size):
            # a smaller set already conserved inside this one would only add its sum again
            if any(g <= set(group) for g in groups):
                continue
            # d/dt Σ p_k = Σ (∂L/∂q_k + Q_k): zero when moving the set together changes neither L nor does work
            if is_zero(sp.Add(*(eqs.dL_dq[k] for k in group))) and sp.Add(*(mech.Q[k] for k in group)) == 0:
                names = [table.names[k] for k in group]
                groups.append(set(group))
                found.append(
                    Conserved(
                        " + ".join(f"p_{n}" for n in names),
                        " + ".join(f"p_{{{table.latex_names()[table.q[k]]}}}" for k in group),
                        sp.Add(*(eqs.momenta[k] for k in group)),
                        f"Moving {', '.join(unicode(n) for n in names[:-1])} and {unicode(names[-1])} together "
                        f"leaves L unchanged ({' + '.join(f'∂L/∂{unicode(n)}' for n in names)} = 0) and no "
                        "generalized force acts along that motion, so the sum of their momenta is conserved.",
                    )
                )
    return found


def velocity_degrees(expr: sp.Expr, velocities: tuple[sp.Symbol, ...]) -> dict[int, sp.Expr]:
    """Split a polynomial in the velocities into its homogeneous parts by degree."""
    parts: dict[int, list[sp.Expr]] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        degree = _degree(term, velocities)
        parts.setdefault(degree, []).append(term)
    return {degree: sp.Add(*terms) for degree, terms in parts.items()}


def _degree(term: sp.Expr, velocities: tuple[sp.Symbol, ...]) -> int:
    """The degree of one product in the velocities: read off its powers, else (a velocity inside a function) SymPy's."""
    powers = term.as_powers_dict()
    plain = sum(int(e) for v, e in powers.items() if v in velocities and e.is_Integer)
    inside = [b for b, e in powers.items() if b not in velocities or not e.is_Integer]
    if any(b.has(*velocities) for b in inside):
        return sum(sp.degree(term, v) for v in velocities)
    return plain


def energetics(mech: Mechanics, eqs: Equations) -> Energetics:
    table = mech.table
    qd = table.qd
    L = mech.L
    forced = any(f != 0 for f in mech.Q)

    cyclic = tuple(name for name, g, f in zip(table.names, eqs.dL_dq, mech.Q, strict=True) if is_zero(g) and f == 0)
    conserved = [
        Conserved(
            f"p_{name}",
            f"p_{{{table.latex_names()[table.q[table.names.index(name)]]}}}",
            eqs.momenta[table.names.index(name)],
            f"{unicode(name)} does not appear in L and no generalized force acts on it, so "
            f"d{unicode('p_' + name)}/dt = ∂L/∂{unicode(name)} = 0.",
        )
        for name in cyclic
    ]
    conserved += _translations(mech, eqs, cyclic)
    # rotations and translations that leave L unchanged up to a total derivative (Noether), each verified
    conserved += [Conserved(s.name, s.latex_name, s.expr, s.reason) for s in symmetries(mech, eqs, cyclic)]

    # dL/dt at fixed q and q_dot: the explicit time dependence
    dL_dt = sp.diff(L, table.t)
    dL_dt = sp.Integer(0) if is_zero(dL_dt) else dL_dt
    # h = sum_k p_k q_dot_k - L
    h = sp.expand(sum(p * v for p, v in zip(eqs.momenta, qd, strict=True)) - L)
    if eqs.velocity_dependent:
        # terms with roots of the velocities over one denominator: mc²√(1 − ẋ²/c²) + mẋ²/√(1 − ẋ²/c²) is
        # mc²/√(1 − ẋ²/c²), the γmc² a textbook writes
        moving = sum((term for term in sp.Add.make_args(h) if term.has(*qd)), sp.Integer(0))
        h = sp.cancel(sp.together(moving)) + (h - moving)
    # dh/dt = -dL/dt|explicit + sum_k Q_k q_dot_k  (the power of the non-conservative forces)
    power = sp.expand(sum(f * v for f, v in zip(mech.Q, qd, strict=True)))

    equal: bool | None
    if mech.T is None:
        E = h
        diff = sp.Integer(0)
        equal = None
        reason = (
            "Only L was given, so T and U cannot be told apart: the energy T + U is not defined here and whether "
            "h equals it cannot be decided, so h alone is reported (the energy bars and plots draw h, no E)."
        )
    else:
        parts = velocity_degrees(mech.T, qd)
        unexpected = sorted(d for d in parts if d not in (0, 1, 2))
        # E = T + U
        E = sp.expand(mech.T + mech.U)
        # E - h = T1 + 2 T0
        diff = sp.expand(E - h)
        equal = is_zero(diff)
        diff = sp.Integer(0) if equal else tidy(diff)
        if equal:
            reason = (
                "T is a homogeneous quadratic form in the velocities (no constraint moves with time), "
                "so Σ q̇ ∂T/∂q̇ = 2T and h = 2T − T + U = T + U = E."
            )
        elif unexpected:
            reason = "T is not a polynomial of degree at most two in the velocities, so h differs from E."
        else:
            causes = "; and ".join(_sources_of_t1_t0(mech, parts))
            # E − h = T₁ + 2T₀, naming only the parts this T has (a bead on a spun wire has T₀ and no T₁)
            # with T₀ alone, say that T₁ is absent here (else a reader wonders where E − h = T₁ + 2T₀ lost it)
            alone = _present(parts, 0) and not _present(parts, 1)
            reason = f"{causes}. " + ("T has no part of degree 1 here (T₁ = 0), so " if alone else "So ")
            reason += f"E − h = {_t1_t0(parts)} ≠ 0."

    # dh/dt = -dL/dt|explicit + sum_k Q_k q_dot_k
    working = forced and not is_zero(power)
    h_conserved = dL_dt == 0 and not working
    if h_conserved:
        name = "E" if equal else "h"
        if forced:
            why = "L has no explicit time dependence and the generalized forces do no work (Σ Q q̇ = 0), so dh/dt = 0"
        else:
            why = "L has no explicit time dependence and no non-conservative force acts, so dh/dt = −∂L/∂t = 0"
        why += ", and h = E here." if name == "E" else "."
        conserved.append(Conserved(name, name, E if name == "E" else h, why))
        h_why = why
    else:
        parts_of_change = []
        if dL_dt != 0:
            parts_of_change.append("L depends explicitly on time (∂L/∂t ≠ 0)")
        if working:
            parts_of_change.append("the generalized forces do work at the rate Σ Q q̇")
        joined = " and ".join(parts_of_change)
        # the page prints "h is not conserved." in bold before this reason: the reason does not say it again
        h_why = f"{joined[0].upper()}{joined[1:]}: dh/dt = −∂L/∂t + Σ Q q̇ along the motion."

    return Energetics(cyclic, tuple(conserved), dL_dt, h, E, diff, equal, reason, power, h_conserved, h_why)


def _present(parts: dict[int, sp.Expr], degree: int) -> bool:
    return not is_zero(parts.get(degree, sp.Integer(0)))


def _degrees(parts: dict[int, sp.Expr]) -> str:
    """Which of T's parts of degree 1 and 0 are there, in words."""
    one, zero = _present(parts, 1), _present(parts, 0)
    if one and zero:
        return "parts of degree 1 and 0"
    return "a part of degree 1 (T₁)" if one else "a part of degree 0 (T₀)"


def _t1_t0(parts: dict[int, sp.Expr]) -> str:
    """E − h = T₁ + 2T₀ with only the parts that are there."""
    one, zero = _present(parts, 1), _present(parts, 0)
    return "T₁ + 2T₀" if one and zero or not (one or zero) else ("T₁" if one else "2T₀")


def _sources_of_t1_t0(mech: Mechanics, parts: dict[int, sp.Expr]) -> list[str]:
    """Where T's parts of degree 1 and 0 in the velocities come from, each in a sentence."""
    t = mech.table.t
    # with particles, T1 and T0 come only from dr/dt: positions that depend on time
    moving = [str(i) for i, r in enumerate(mech.positions, start=1) if any(c.has(t) for c in r)]
    if moving:
        if len(mech.positions) == 1:
            which = "the particle"
        else:
            which = "particle " + moving[0] if len(moving) == 1 else "particles " + ", ".join(moving)
        return [
            f"The positions depend explicitly on time (a moving constraint: the position of {which} contains t), "
            f"so T has {_degrees(parts)} in the velocities"
        ]
    # T written by the user: sort the terms of T1 and T0 by whether they contain t
    timed, linear, free = False, False, False
    for degree in (1, 0):
        part = parts.get(degree, sp.Integer(0))
        if is_zero(part):
            continue
        for term in sp.Add.make_args(part):
            if term.has(t):
                timed = True
            elif degree == 1:
                linear = True
            else:
                free = True
    causes = []
    if timed:
        causes.append(
            "T depends explicitly on time in its parts of degree 1 and 0 in the velocities, as a moving constraint makes it"
        )
    if linear:
        causes.append("T has terms linear in the velocities as written (a gyroscopic or magnetic term), a part T₁")
    if free:
        causes.append(
            "T has a part T₀ without velocities as written: the kinetic energy of a motion the constraints impose "
            "(a hoop or a wire turned at a set rate), which is there when every coordinate stands still"
        )
    return [causes[0][0].upper() + causes[0][1:], *causes[1:]] if causes else ["T has parts of degree 1 and 0"]
