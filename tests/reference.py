"""An independent route to the equations: sympy.physics.mechanics.

The declaration's strings are read here with ``sympify`` (trusted test input),
particles become ``Particle`` objects in an inertial frame, bodies ``RigidBody`` objects with their own
principal moments, and
``LagrangesMethod`` forms the equations.  Generalized forces Q are added to
its forcing vector: M q_ddot = f + Q.
"""

from __future__ import annotations

import random

import sympy as sp
import sympy.physics.mechanics as me

from app.scenes.types import System

# the principal moments about the centre over M size², about the body's x, y (normal to the plane of motion) and
# z axes, written out here from the solid's geometry, independently of the engine's table: a thin rod along x
# (none about its own axis), a disc and a ring in the x–z plane (half the moment about the normal for each
# diameter: the perpendicular-axis theorem), a solid sphere
_PRINCIPAL = {
    "rod": (0, sp.Rational(1, 12), sp.Rational(1, 12)),
    "disc": (sp.Rational(1, 4), sp.Rational(1, 2), sp.Rational(1, 4)),
    "ring": (sp.Rational(1, 2), 1, sp.Rational(1, 2)),
    "sphere": (sp.Rational(2, 5), sp.Rational(2, 5), sp.Rational(2, 5)),
}


def _reader(system: System):
    names = list(system.coordinates)
    qs = me.dynamicsymbols(" ".join(names), seq=True)
    t = me.dynamicsymbols._t
    plain = {n: sp.Symbol(n, real=True) for n in names}
    local = {p.name: sp.Symbol(p.name, real=True) for p in system.parameters}
    local.update(plain)
    local.update({f"{n}_dot": sp.Symbol(f"{n}_dot", real=True) for n in names})
    local["t"] = sp.Symbol("t", real=True)
    to_dyn = {plain[n]: q for n, q in zip(names, qs, strict=True)}
    to_dyn.update({local[f"{n}_dot"]: q.diff(t) for n, q in zip(names, qs, strict=True)})
    to_dyn[local["t"]] = t

    def read(text: str) -> sp.Expr:
        return sp.sympify(text, locals=local).xreplace(to_dyn)

    return qs, read


def lagranges_method(system: System):
    """LagrangesMethod on the declaration, its equations formed; returns it and the reader."""
    qs, read = _reader(system)
    N = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(N, 0)
    if system.particles or system.bodies:
        bodies = []
        for i, part in enumerate(system.particles):
            r = sum((read(c) * e for c, e in zip(part.position, (N.x, N.y, N.z), strict=True)), 0 * N.x)
            P = origin.locatenew(f"P{i}", r)
            P.set_vel(N, P.pos_from(origin).dt(N))
            bodies.append(me.Particle(f"B{i}", P, read(part.mass)))
        for i, body in enumerate(system.bodies):
            r = sum((read(c) * e for c, e in zip(body.centre, (N.x, N.y, N.z), strict=True)), 0 * N.x)
            C = origin.locatenew(f"C{i}", r)
            C.set_vel(N, C.pos_from(origin).dt(N))
            # the body's frame turned by its angle about y, the axis normal to the plane of motion
            F = N.orientnew(f"F{i}", "Axis", [read(body.angle), N.y])
            mass = read(body.mass)
            inertia = me.inertia(F, *(c * mass * read(body.size) ** 2 for c in _PRINCIPAL[body.kind]))
            bodies.append(me.RigidBody(f"R{i}", C, F, mass, (inertia, C)))
        L = me.Lagrangian(N, *bodies) - read(system.potential)
    elif system.kinetic is not None:
        L = read(system.kinetic) - read(system.potential)
    else:
        L = read(system.lagrangian)
    lm = me.LagrangesMethod(L, qs)
    lm.form_lagranges_equations()
    return lm, qs, read


def reference_accelerations(system: System) -> tuple[list[sp.Expr], dict[str, sp.Expr]]:
    """q_ddot from LagrangesMethod, expressed in the project's plain symbols."""
    lm, qs, read = lagranges_method(system)
    Q = sp.Matrix([read(system.forces.get(n, "0")) for n in system.coordinates])
    acc = lm.mass_matrix.LUsolve(lm.forcing + Q)
    t = me.dynamicsymbols._t
    back = {}
    for n, q in zip(system.coordinates, qs, strict=True):
        back[q.diff(t)] = sp.Symbol(f"{n}_dot", real=True)
    for n, q in zip(system.coordinates, qs, strict=True):
        back[q] = sp.Symbol(n, real=True)
    back[t] = sp.Symbol("t", real=True)
    return [a.subs(back) for a in acc], back


def random_point(symbols, seed: int = 7) -> dict[sp.Symbol, sp.Float]:
    """A generic point (away from the special values 0, 1, pi/2) for numeric comparison."""
    rng = random.Random(seed)
    return {s: sp.Float(rng.uniform(0.4, 1.3)) for s in symbols}


def numerically_equal(a: sp.Expr, b: sp.Expr, symbols, trials: int = 3, tol: float = 1e-9) -> bool:
    for seed in range(trials):
        point = random_point(symbols, seed)
        va, vb = complex(sp.N(a.xreplace(point))), complex(sp.N(b.xreplace(point)))
        if abs(va - vb) > tol * max(1.0, abs(va), abs(vb)):
            return False
    return True
