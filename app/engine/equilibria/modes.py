"""Equilibria, their stability and normal modes, for any number of coordinates.

Write L = 1/2 q_dot . M(q, t) q_dot + b(q, t) . q_dot + L0(q, t).  A state at rest
at q0 stays at rest when the Euler-Lagrange equations give q_ddot = 0 at q_dot = 0;
there d/dt(dL/dq_dot) = db/dt, so the condition is

    g(q) = dV/dq + db/dt - Q(q, 0) = 0,   V = -L0 = U - T0,

with T0 the velocity-free part of T (a moving constraint's centrifugal term).
The db/dt term is what a uniformly accelerating support leaves (the pendulum in a
car hangs at theta = -atan(A/g)), and it cancels the extra force of a total time
derivative added to L (L + d/dt(c x^2 t) has the oscillator's equilibria).
When g still depends on t, a state stays at rest only where g = 0 at every t
(checked at several times); otherwise there is no equilibrium (a support that
moves periodically).

Every root of g = 0 is sought twice and the results merged: in closed form by
SymPy within a time budget (``app.engine.equilibria.modes_exact``), and by a bounded
numerical search over one period of each angle and a range of each other
coordinate at the default parameters (``app.engine.equilibria.roots``).  The list is called
complete only when the conditions are polynomial in the coordinates (SymPy's
solve then returns every root) and the search found nothing more.

About each equilibrium, q = q0 + e to first order gives M e'' + G e' + K e = 0,

    K = dg/dq at q0,   G = -d f/d q_dot at rest (f: M q_ddot = f)

and ``app.engine.equilibria.stability`` classifies it from the exponents of the full system
(gyroscopic and damping terms included).  The mode shapes and omega^2 are the
eigenvalues of K relative to M, the undamped, ungyroscopic problem.

When every coordinate but one is cyclic, the one-coordinate reduction adds its
relative equilibria (a circular or conical orbit): U_eff'(r0) = 0 at given
values of the conserved momenta, omega^2 = U_eff''(r0) / m_eff(r0).

The whole step has its own time budget, and any failure inside it becomes a
sentence in the document (no equilibria, and why), never a refused derivation.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from app.engine.algebra.budget import work_limit
from app.engine.algebra.work import WorkExceeded
from app.engine.display.names import unicode
from app.engine.equations.lagrange import Equations
from app.engine.equations.mechanics import Mechanics
from app.engine.equations.reduction import Reduction
from app.engine.equilibria import modes_exact, roots
from app.engine.equilibria.equilibrium import (
    MAX_EQUILIBRIA,
    Equilibrium,
    array,
    defaults,
    function,
    modes_of,
    numeric,
    vanishes,
)
from app.engine.equilibria.stability import NEUTRAL, STABLE, UNSTABLE, linearize
from app.engine.equilibria.steady import relative
from app.engine.equilibria.time_factor import TIMES, common_factor_time
from app.engine.parser.symbols import SymbolTable
from app.limits import MODES_WORK, SEARCH_EVALUATIONS
from app.scenes.types import System

__all__ = ["NEUTRAL", "STABLE", "UNSTABLE", "NormalModes", "normal_modes"]

log = logging.getLogger(__name__)

MAX_SYMBOLIC_SIZE = 3  # coordinates up to which M and K are kept symbolic at an exact equilibrium


@dataclass(frozen=True)
class NormalModes:
    potential: sp.Expr  # V = U - T0
    condition: tuple[sp.Expr, ...]  # dV/dq + db/dt - Q(q, 0), zero at an equilibrium
    solved: bool  # every equilibrium found in closed form, and provably all of them
    equilibria: tuple[Equilibrium, ...]
    singular: tuple[dict[str, float], ...]  # equilibria where M is singular (a coordinate singularity)
    damped: bool  # velocity terms (damping, gyroscopic) present at some equilibrium
    note: str = ""  # why there is nothing, when there is nothing
    kinks: tuple[dict[str, float], ...] = ()  # equilibria at a kink of a piecewise-smooth U (|x|): no linearization
    searched: str = ""  # where the numerical search looked (empty when the closed forms are complete)
    moving_frame: bool = False  # db/dt contributes (an accelerating support)
    failed: str = ""  # the step could not be completed: why (the rest of the document stands)
    unclassified: tuple[dict[str, float], ...] = ()  # at rest for all t, but the linearization changes with t
    found: int = 0  # equilibria found (more than listed when capped at MAX_EQUILIBRIA)
    angles_only: bool = False  # every coordinate is an angle, so the search covered all of configuration space
    family: bool = False  # a closed-form solution leaves a coordinate free (shown at 0)
    # the closed-form families: each a coordinate's name -> its value in the coordinates left free
    families: tuple[dict[str, sp.Expr], ...] = ()
    everywhere: bool = False  # V is constant and nothing else pushes: every configuration is an equilibrium
    singular_exact: tuple[dict[str, sp.Expr] | None, ...] = ()  # the closed forms of ``singular``, where known
    common_factor: bool = False  # M, G, K change with t by one common factor, divided out (app.engine.equilibria.time_factor)
    unclassified_exact: tuple[dict[str, sp.Expr] | None, ...] = ()  # the closed forms of ``unclassified`` (π)


def _time_free(exprs: list[sp.Expr], args: list[sp.Symbol], t: sp.Symbol, k: list[float]) -> bool:
    """The expressions take the same values at several times (sin²ωt + cos²ωt left over counts as free of t)."""
    if not any(sp.sympify(e).has(t) for e in exprs):
        return True
    f = function(exprs, [*args, t])
    rng = np.random.default_rng(7)
    for _ in range(3):
        x = rng.uniform(-1.3, 1.3, len(args) - len(k))
        with np.errstate(all="ignore"):
            values = [f(*x, *k, s) for s in TIMES]
        if not all(np.allclose(v, values[0], rtol=1e-9, atol=1e-12) for v in values[1:]):
            return False
    return True


def _failed(reason: str) -> NormalModes:
    return NormalModes(sp.Integer(0), (), False, (), (), False, reason, failed=reason)


def normal_modes(
    system: System,
    mech: Mechanics,
    eqs: Equations,
    reduction: Reduction | None,
    momenta: Mapping[str, float] | None = None,
) -> NormalModes:
    """Equilibria, their classification and normal modes, with numbers at the default parameters.

    From the declared system (its default parameters and nonnegative distances), L's mechanics, its
    Euler-Lagrange equations and the one-coordinate reduction (for the steady motions).  ``momenta`` gives values of the conserved momenta for the reduction's relative
    equilibria (1 each when not given).  Never raises: a failure is reported in ``failed``.
    """
    try:
        with work_limit(MODES_WORK):
            return _normal_modes(system, mech, eqs, reduction, momenta or {})
    except WorkExceeded:
        return _failed(
            "Finding the equilibria needs more work than the engine allows this step, so they are left out; "
            "the rest of the derivation is complete."
        )
    except (ArithmeticError, ValueError, TypeError, AttributeError, np.linalg.LinAlgError, NotImplementedError) as exc:
        log.warning("equilibria step failed: %r", exc)
        return _failed(
            "The equilibria could not be computed for this system (a limit of this step, not of what you wrote), "
            "so they are left out; the rest of the derivation is complete."
        )


def _at_rest(expr: sp.Expr, v: sp.Symbol, zero_v: Mapping[sp.Symbol, sp.Expr]) -> sp.Expr:
    """∂expr/∂v at rest (every velocity 0).

    The other velocities are set to 0 before the derivative is taken: ∂/∂v does not touch them, so the order does
    not change the value, and the expression differentiated is only its part that survives at rest in all but v
    (a chain's forces hold products of velocities; no ∂f/∂v at rest needs them)."""
    alone = expr.xreplace({w: z for w, z in zero_v.items() if w != v})
    # term by term, the sum of the derivatives at v = 0: a term without v gives 0, c·v gives c, c·vⁿ (n ≥ 2) gives
    # 0 (a chain's centripetal terms: not differentiated only to be set to 0), any other is differentiated
    terms = []
    for term in sp.Add.make_args(alone):
        if not term.has(v):
            continue
        coefficient, part = term.as_independent(v, as_Add=False)
        if part == v:
            terms.append(coefficient)
        elif not (part.is_Pow and part.base == v and part.exp.is_Integer and part.exp >= 2):
            terms.append(sp.diff(term, v).xreplace({v: zero_v[v]}))
    return sp.Add(*terms)


def _normal_modes(
    system: System, mech: Mechanics, eqs: Equations, reduction: Reduction | None, momenta: Mapping[str, float]
) -> NormalModes:
    table = mech.table
    q, t = list(table.q), table.t
    zero_v = dict.fromkeys(table.qd, sp.Integer(0))
    # V = -L(q, q_dot = 0) = U - T0
    V = -mech.L.xreplace(zero_v)
    # b = dL/dq_dot at rest; d/dt of the momentum at rest is db/dt
    b_t = [sp.diff(_at_rest(mech.L, v, zero_v), t) for v in table.qd]
    Q0 = [f.xreplace(zero_v) for f in mech.Q]
    # the equilibrium condition dV/dq + db/dt - Q(q, 0) = 0
    g_exprs = [sp.diff(V, s) + bt - f for s, bt, f in zip(q, b_t, Q0, strict=True)]
    moving_frame = any(bt != 0 for bt in b_t)
    # M = W(q, 0, t): the matrix multiplying q̈ in W q̈ = f, at rest (W is M itself when L is quadratic in q̇;
    # linearising W(q, q̇) q̈ about a rest point, where q̈ = 0, leaves W(q₀, 0) δq̈)
    M = eqs.mass_matrix.xreplace(zero_v)
    # G = -d f/d q_dot at rest: damping and gyroscopic terms of M q_ddot = f
    G = sp.Matrix([[-_at_rest(f, v, zero_v) for v in table.qd] for f in eqs.forcing])
    values = defaults(system, table)
    k = [values[s] for s in table.params]
    args = [*q, *table.params]
    # explicit t that cancels numerically (sin² + cos² of a rotation) is set to 0; what remains truly depends on t
    timed_g = not _time_free(g_exprs, args, t, k)
    if not timed_g:
        g_exprs = [e.xreplace({t: 0}) for e in g_exprs]
    timed_lin = not _time_free([*M, *G], args, t, k)
    if not timed_lin:
        M, G = M.xreplace({t: 0}), G.xreplace({t: 0})
    nonnegative = {i for i, name in enumerate(table.names) if name in system.nonnegative}

    points, complete, periodic, families = _equilibria(system, table, g_exprs, q, t, timed_g, nonnegative, values, k)
    # K = dg/dq
    J = sp.Matrix([[sp.diff(e, s) for s in q] for e in g_exprs])
    equilibria: list[Equilibrium] = []
    singular: list[dict[str, float]] = []
    singular_exact: list[dict[str, sp.Expr] | None] = []
    kinks: list[dict[str, float]] = []
    unclassified: list[dict[str, float]] = []
    unclassified_exact: list[dict[str, sp.Expr] | None] = []
    common_factor = False
    damped = False
    # over the cap: the ones nearest q = 0, listed in order
    shown = sorted(sorted(points, key=lambda p: float(np.abs(p[1]).sum()))[:MAX_EQUILIBRIA], key=lambda p: tuple(p[1]))
    for exact, x in shown:
        position = {name: float(v) for name, v in zip(table.names, x, strict=True)}
        at = {}
        if timed_g or timed_lin:
            # at rest for all t, and M, G, K change with t: constant after dividing by a common factor c(t),
            # or no constant-coefficient linearization at all
            t0 = common_factor_time((M, G, J), args, t, [*x, *k])
            if t0 is None:
                unclassified.append(position)
                found = exact if exact is not None else _recognized(g_exprs, q, x)
                unclassified_exact.append({s.name: v for s, v in found.items()} if found is not None else None)
                continue
            at, common_factor = {t: sp.nsimplify(t0)}, True
        e = _linearized(system, table, M.xreplace(at), J.xreplace(at), G.xreplace(at), exact, x, values)
        if e is None:
            singular.append(position)
            singular_exact.append({s.name: v for s, v in exact.items()} if exact is not None else None)
        elif e == "kink":
            kinks.append(position)
        else:
            assert isinstance(e, Equilibrium)
            damped = damped or bool(e.linear and e.linear.moving)
            equilibria.append(e)
    if not (timed_g or timed_lin):
        equilibria.extend(_without_mirrors(system, table, relative(system, table, reduction, momenta)))
    note = ""
    if not (equilibria or singular or kinks or unclassified):
        note = (
            "No equilibrium: L depends on time explicitly (the support moves, or a force is driven), and no "
            "configuration has every generalized force zero at all times, so no state stays at rest."
            if timed_g
            else "No configuration makes every generalized force vanish: no equilibrium."
        )
    searched = "" if complete else _searched(table.names, periodic, nonnegative, k)
    return NormalModes(
        V,
        tuple(g_exprs),
        complete,
        tuple(equilibria),
        tuple(singular),
        damped,
        note,
        tuple(kinks),
        searched,
        moving_frame,
        "",
        tuple(unclassified),
        len(points),
        bool(periodic) and all(periodic),
        bool(families),
        tuple({s.name: v for s, v in sol.items()} for sol in families),
        all(e == 0 for e in g_exprs),
        tuple(singular_exact),
        common_factor,
        tuple(unclassified_exact),
    )


def _recognized(g_exprs: list[sp.Expr], q: list[sp.Symbol], x: np.ndarray) -> dict[sp.Symbol, sp.Expr] | None:
    """A point found numerically, as a closed form where one is recognized (θ = π, not 3.142): each coordinate a
    rational multiple of π or a small rational, kept only when every equilibrium condition vanishes there exactly,
    for every t and every value of the parameters (the shaken pivot's m g l sin θ + m a l w² cos(wt) sin θ at π)."""
    guess = {s: sp.nsimplify(float(v), [sp.pi], tolerance=1e-9, rational=False) for s, v in zip(q, x, strict=True)}
    if any(sp.count_ops(v) > 4 for v in guess.values()):
        return None
    # the conditions at the guessed point, identically zero
    return guess if all(sp.simplify(e.xreplace(guess)) == 0 for e in g_exprs) else None


def _searched(names: tuple[str, ...], periodic: list[bool], nonnegative: set[int], k: list[float]) -> str:
    """Where the numerical search looked, in the words a reader reads ("x between −80 and 80 and θ over a
    full turn"): names as printed, a true minus sign, no exponent notation."""
    big = max([abs(v) for v in k if math.isfinite(v)] + [3.0 / 4])
    parts = []
    for i, name in enumerate(names):
        shown = unicode(name)
        if i < len(periodic) and periodic[i]:
            parts.append(f"{shown} over a full turn")
        else:
            low = "0" if i in nonnegative else _plain(-4 * big)
            parts.append(f"{shown} between {low} and {_plain(4 * big)}")
    return parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]


def _plain(x: float) -> str:
    """A search bound as a reader writes it: at most three significant figures, a true minus sign."""
    text = f"{x:,.3g}" if abs(x) < 1e5 else f"{x:,.0f}"
    return text.replace("-", "−")


def _equilibria(
    system: System,
    table: SymbolTable,
    g_exprs: list[sp.Expr],
    q: list[sp.Symbol],
    t: sp.Symbol,
    timed: bool,
    nonnegative: set[int],
    values: Mapping[sp.Symbol, float],
    k: list[float],
) -> tuple[
    list[tuple[dict[sp.Symbol, sp.Expr] | None, np.ndarray]], bool, list[bool], list[dict[sp.Symbol, sp.Expr]]
]:
    """Closed-form and numerical roots merged, whether the list is provably complete, which q are angles,
    and the closed-form families (solutions that leave a coordinate free)."""
    if all(e == 0 for e in g_exprs):
        # nothing ever pushes: every configuration is an equilibrium (shown at q = 0)
        return [({s: sp.Integer(0) for s in q}, np.zeros(len(q)))], True, [False] * len(q), [{}]
    args = [*q, *table.params]
    at_zero = [e.xreplace({t: 0}) for e in g_exprs]
    J = [[sp.diff(e, s) for s in q] for e in at_zero]
    g = function(at_zero, args)
    jac = function(J, args)
    found, periodic = roots.search(g, jac, len(q), k, nonnegative, SEARCH_EVALUATIONS)
    if timed:
        # at rest for all t: the condition holds at every one of several instants
        every = function(g_exprs, [*args, t])
        with np.errstate(all="ignore"):
            found = [
                x
                for x in found
                if all(
                    np.abs(every(*x, *k, s)).max() <= 1e-8 * max(1.0, float(np.abs(jac(*x, *k)).max())) for s in TIMES
                )
            ]
        return [(None, x) for x in found], False, periodic, []
    solutions = modes_exact.solve(g_exprs, q, system, table)
    exact_points: list[tuple[dict[sp.Symbol, sp.Expr], np.ndarray]] = []
    for sol in solutions or []:
        exact = {s: sol.get(s, sp.Integer(0)).xreplace({r: 0 for r in q if r not in sol}) for s in q}
        try:
            xc = np.array([numeric(exact[s], values) for s in q])
        except (TypeError, ValueError):
            continue
        if np.any(np.abs(xc.imag) > 1e-12 * np.maximum(1, np.abs(xc.real))) or not np.all(np.isfinite(xc.real)):
            continue
        x = xc.real
        if any(x[i] < -1e-12 for i in nonnegative) or not vanishes(g, jac, x, k):
            continue
        wrapped = roots.wrap(x, periodic)
        if not np.allclose(wrapped, x, rtol=0, atol=1e-12):
            # 2 pi away from the one the search lists: keep the number in (-pi, pi]
            continue
        if not any(roots.same_point(x, y, periodic) for _, y in exact_points):
            exact_points.append((exact, x))
    merged: list[tuple[dict[sp.Symbol, sp.Expr] | None, np.ndarray]] = list(exact_points)
    families = [sol for sol in solutions or [] if len(sol) < len(q)]
    extra = [
        x
        for x in found
        if not any(roots.same_point(x, y, periodic) for _, y in exact_points)
        and not any(_on_family(sol, q, x, values, periodic) for sol in families)
    ]
    merged += [(_snapped(g_exprs, q, x, periodic), x) for x in extra]
    # the numerical search may miss exact ones that it did not reach, never the other way round
    complete = solutions is not None and not extra and modes_exact.polynomial(g_exprs, q)
    merged.sort(key=lambda p: tuple(p[1]))
    return merged, complete, periodic, families


# values a numerical root is tried at exactly: 0 and, for an angle, the quarter turns
_ROUND = (sp.Integer(0), sp.pi, -sp.pi, sp.pi / 2, -sp.pi / 2)


def _snapped(
    g_exprs: list[sp.Expr], q: list[sp.Symbol], x: np.ndarray, periodic: list[bool]
) -> dict[sp.Symbol, sp.Expr] | None:
    """A numerical root in closed form when every coordinate is within rounding of 0 (or of a quarter turn, for an
    angle) and every condition there is exactly zero for all parameter values (θ = π, not 3.14159); else None."""
    at: dict[sp.Symbol, sp.Expr] = {}
    for i, s in enumerate(q):
        near = [c for c in (_ROUND if i < len(periodic) and periodic[i] else _ROUND[:1]) if abs(float(x[i]) - float(c)) < 1e-9]
        if not near:
            return None
        at[s] = near[0]
    try:
        # exactly zero, symbolically (with the parameters left as symbols; sin π and cos(π/2) evaluate to 0
        # on substitution): no tolerance decides it
        if all(sp.expand(sp.sympify(e).xreplace(at)) == 0 for e in g_exprs):
            return at
    except (TypeError, ValueError, NotImplementedError):
        return None
    return None


def _on_family(
    sol: dict[sp.Symbol, sp.Expr],
    q: list[sp.Symbol],
    x: np.ndarray,
    values: Mapping[sp.Symbol, float],
    periodic: list[bool],
) -> bool:
    """A root of the search lies on a closed-form family of equilibria (a coordinate left free)."""
    point = {**values, **dict(zip(q, (float(v) for v in x), strict=True))}
    try:
        y = np.array([numeric(sol[s], point).real if s in sol else float(v) for s, v in zip(q, x, strict=True)])
    except (TypeError, ValueError):
        return False
    return bool(np.all(np.isfinite(y))) and roots.same_point(x, y, periodic)


def _linearized(
    system: System,
    table: SymbolTable,
    M: sp.Matrix,
    J: sp.Matrix,
    G: sp.Matrix,
    exact: dict[sp.Symbol, sp.Expr] | None,
    x: np.ndarray,
    values: Mapping[sp.Symbol, float],
) -> Equilibrium | str | None:
    """The equilibrium with its verdict and modes; None where M is singular, "kink" at a kink of V."""
    q = list(table.q)
    symbolic = exact is not None and len(q) <= MAX_SYMBOLIC_SIZE
    at = {s: (exact[s] if exact is not None else sp.Float(float(v))) for s, v in zip(q, x, strict=True)}
    if symbolic:
        M0, K0 = M.xreplace(at).applyfunc(modes_exact.cheap), J.xreplace(at).applyfunc(modes_exact.cheap)
    else:
        # found numerically at the defaults: M and K as numbers there
        M0 = M.xreplace(at).xreplace(dict(values)).evalf()
        K0 = J.xreplace(at).xreplace(dict(values)).evalf()
    if K0.has(sp.DiracDelta) or M0.has(sp.DiracDelta):
        # U = |x| at x = 0: the force jumps there, so no quadratic approximation (and no omega) exists
        return "kink"
    G0 = G.xreplace(at)
    lin = linearize(array(M0, values), array(K0, values), array(G0, values))
    if lin is None:
        return None
    return Equilibrium(
        {name: float(v) for name, v in zip(table.names, x, strict=True)},
        {s.name: v for s, v in exact.items()} if exact is not None else None,
        lin.kind,
        M0,
        K0,
        modes_of(M0, K0, lin, values, symbolic, modes_exact.positive(system, table)),
        tuple(table.names),
        linear=lin,
    )


def _without_mirrors(system: System, table: SymbolTable, steady: list[Equilibrium]) -> list[Equilibrium]:
    """Each steady motion once: r₀ < 0 is left out when r₀ > 0 is listed and every body is at the same place at
    (−r, φ + π) as at (r, φ), φ each cyclic angle (the spherical pendulum's cone at −θ₀ is the cone at θ₀ traced
    from the other side).  Decided on the bodies' positions, so only for systems declared by their particles."""
    particles = system.particles
    if not particles or not steady:
        return steady
    r = table.q[table.names.index(steady[0].coordinates[0])]
    shift = {s: s + sp.pi for s in table.q if s != r}
    flip = {r: -r, **shift}
    values = defaults(system, table)
    rng = np.random.default_rng(11)
    for particle in particles:
        for axis in particle.position:
            x = sp.sympify(axis, locals={s.name: s for s in (*table.q, *table.params, table.t)})
            # the same position after the map, at a few random configurations
            for _ in range(3):
                point = {**values, **{s: float(v) for s, v in zip(table.q, rng.uniform(-1.3, 1.3, len(table.q)), strict=True)}}
                if abs(numeric(x.xreplace(flip), point) - numeric(x, point)) > 1e-9 * max(1.0, abs(numeric(x, point))):
                    return steady
    kept = []
    for e in steady:
        x0 = e.position[e.coordinates[0]]
        mirrored = any(
            f is not e and abs(f.position[f.coordinates[0]] + x0) <= 1e-9 * max(1.0, abs(x0)) for f in steady
        )
        if not (mirrored and x0 < 0):
            kept.append(e)
    return kept
