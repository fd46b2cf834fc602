"""Steady motions: relative equilibria of the one-coordinate reduction (``app.engine.equations.reduction``).

When every coordinate but one (r) is cyclic, holding the conserved momenta at given values leaves
the one-dimensional motion in U_eff(r); a root of U_eff'(r0) = 0 is a steady motion (a circular
orbit, a conical pendulum, a precessing top) with omega^2 = U_eff''(r0) / m_eff(r0).  As for the
equilibria at rest, SymPy's closed forms and the numerical search (``app.engine.equilibria.roots``) are both
used and merged.  A root at 0 or pi where U_eff' is 0/0 (the sleeping top, whose Euler angles have a
pole there) is recognised by continuity and its omega^2 taken as a two-sided limit.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import sympy as sp

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
from app.engine.equilibria.stability import linearize
from app.engine.parser.symbols import SymbolTable
from app.limits import SEARCH_EVALUATIONS
from app.scenes.types import System


def relative(
    system: System, table: SymbolTable, red: Reduction | None, momenta: Mapping[str, float]
) -> list[Equilibrium]:
    """Relative equilibria of the one-coordinate reduction: U_eff'(r0) = 0 at the given conserved momenta."""
    if red is None or not red.momenta:
        return []
    r = table.q[table.names.index(red.coordinate)]
    values = defaults(system, table)
    values.update({P: float(momenta.get(P.name, 1.0)) for P in red.momenta})
    held = {P.name: values[P] for P in red.momenta}
    dU = red.equilibrium_condition
    if not dU.has(r):
        return []
    nonnegative = {0} if red.coordinate in system.nonnegative else set()
    # the cyclic coordinates may still appear in an unsimplified form (sin² ψ + cos² ψ): any value will do
    others = {s: sp.Integer(0) for s in table.q if s != r}
    values.update(others)
    at_values = sp.sympify(dU).xreplace(dict(values))
    g = function([at_values], [r])
    jac = function([[sp.diff(at_values, r)]], [r])
    found, periodic = roots.search(g, jac, 1, [], nonnegative, SEARCH_EVALUATIONS)
    points: list[tuple[sp.Expr | None, float]] = []
    for e in red.equilibria:
        v = numeric(e.position, values)
        if abs(v.imag) > 1e-12 * max(1.0, abs(v)) or not math.isfinite(v.real):
            continue
        x = np.array([v.real])
        if (nonnegative and v.real < -1e-12) or not vanishes(g, jac, x, []):
            continue
        if np.allclose(roots.wrap(x, periodic), x, atol=1e-12) and not any(
            roots.same_point(x, np.array([y]), periodic) for _, y in points
        ):
            points.append((e.position, v.real))
    for x in found:
        # a root a rounding error away from 0 or pi, where U_eff' is 0/0 (a sleeping top): the exact point
        snapped = _snap(at_values, r, float(x[0]))
        if snapped is not None:
            x = np.array([float(snapped)])
        if not any(roots.same_point(x, np.array([y]), periodic) for _, y in points):
            points.append((snapped, float(x[0])))
    points.sort(key=lambda p: p[1])
    out = []
    for exact, x0 in points[:MAX_EQUILIBRIA]:
        at = {r: exact if exact is not None else sp.Float(x0)}
        mass = sp.sympify(red.effective_mass).xreplace(others)
        potential = sp.sympify(red.effective_potential).xreplace(others)
        m0, k0 = mass.xreplace(at), sp.diff(potential, r, 2).xreplace(at)
        if exact is not None:
            m0, k0 = _finite(mass, r, exact, values), _finite(potential, r, exact, values, second=True)
            m0, k0 = modes_exact.cheap(m0), modes_exact.cheap(k0)
        else:
            # an effective mass free of r (m R² of a spherical pendulum) stays as the reader knows it
            m0 = m0 if not mass.has(r) else sp.sympify(m0.xreplace(values)).evalf()
            k0 = sp.sympify(k0.xreplace(values)).evalf()
        Mm, Km = sp.Matrix([[m0]]), sp.Matrix([[k0]])
        # the reduced motion has no velocity term (a linear one is a total derivative in one dimension)
        lin = linearize(array(Mm, values), array(Km, values), np.zeros((1, 1)))
        if lin is None:
            continue
        out.append(
            Equilibrium(
                {red.coordinate: float(x0)},
                {red.coordinate: exact} if exact is not None else None,
                lin.kind,
                Mm,
                Km,
                modes_of(Mm, Km, lin, values, exact is not None, modes_exact.positive(system, table)),
                (red.coordinate,),
                held,
                lin,
            )
        )
    return out


def _snap(condition: sp.Expr, r: sp.Symbol, x0: float) -> sp.Expr | None:
    """0 or +-pi when x0 is within rounding of it and the condition's limit there is 0."""
    for c in (sp.Integer(0), sp.pi, -sp.pi):
        if abs(x0 - float(c)) < 1e-5:
            value = abs(numeric(condition, {r: c}))
            if not math.isfinite(value):
                # 0/0 at c: the values just beside it, against those a step away (continuity)
                # (a root there shrinks in proportion: a thousandth of the step, a thousandth of the value)
                near = max(abs(numeric(condition, {r: c + s * sp.Float(1e-4)})) for s in (1, -1))
                far = max(abs(numeric(condition, {r: c + s * sp.Float(0.1)})) for s in (1, -1))
                if math.isfinite(far) and near <= 1e-2 * far:
                    return c
            elif value <= 1e-9:
                return c
    return None


def _finite(
    expr: sp.Expr, r: sp.Symbol, at: sp.Expr, values: Mapping[sp.Symbol, float], second: bool = False
) -> sp.Expr:
    """expr (or its second derivative in r, when ``second``) at r = at.

    Where the value is 0/0 (a removable singularity of U_eff, as at a sleeping top) it is the limit,
    taken numerically from both sides with Richardson's extrapolation (no point at r = at is used).
    """
    value = sp.diff(expr, r, 2).xreplace({r: at}) if second else sp.sympify(expr).xreplace({r: at})
    number = numeric(value, values)
    if math.isfinite(number.real) and math.isfinite(number.imag):
        return value
    f = function([sp.sympify(expr).xreplace(dict(values))], [r])
    x0 = float(at)

    def estimate(h: float) -> float:
        with np.errstate(all="ignore"):
            a, b, c, e = (float(f(x0 + s * h)[0]) for s in (2, 1, -1, -2))
        # (f(2h) - f(h) - f(-h) + f(-2h)) / 3h^2 = f'' + O(h^2); (f(h) + f(-h))/2 = f + O(h^2)
        return (a - b - c + e) / (3 * h * h) if second else (b + c) / 2

    h = 1e-2
    return sp.Float((4 * estimate(h / 2) - estimate(h)) / 3)
