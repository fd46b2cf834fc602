"""The accelerations beside those a problem compares them with, read from the system: a declared rigid body that
rolls beside a body that slides without turning (the cylinder beside a block on the same wedge), and every
acceleration with a body that carries another held fixed (its mass → ∞: the fixed wedge's 2g sin α/3)."""

from __future__ import annotations

import sympy as sp

from app.engine.derive import Derivation
from app.engine.mistake_other import held_fixed, limit
from app.engine.mistake_pieces import euler_lagrange


def sliding(d: Derivation) -> list[sp.Expr] | None:
    """The accelerations with the turning energy ½ I_cm θ̇² of every declared body carried by another taken out of
    L, each body then sliding as a point at its centre; None where no carried body turns (a pendulum's rod turns
    about its pivot: taken as a point it is another problem, not a comparison the statement asks for)."""
    carried = set().union(*(c.free_symbols for r in d.mechanics.positions for c in r)) & set(d.table.q)
    turning = [
        b.rotation
        for b in d.mechanics.bodies
        if b.rotation != 0 and b.translation != 0 and set().union(*(c.free_symbols for c in b.centre)) & carried
    ]
    if not turning or not d.equations.closed_form:
        return None
    t = d.table
    # ΔL = −Σ ½ I_cm θ̇²: each equation changes by d/dt ∂ΔL/∂q̇ − ∂ΔL/∂q, and ℳ q̈ = f is solved anew
    dL = -sp.Add(*turning)
    wrong = [sp.expand(r + euler_lagrange(d, j, dL)) for j, r in enumerate(d.equations.residuals)]
    M = sp.Matrix([[sp.diff(r, a) for a in t.qdd] for r in wrong])
    if M.det() == 0:
        return None
    zero = dict.fromkeys(t.qdd, sp.Integer(0))
    # cos² written 1 − sin², as the page's own accelerations are (M + m sin² α, never M + m − m cos² α)
    squared = (lambda e: e.is_Pow and isinstance(e.base, sp.cos) and e.exp == 2, lambda e: 1 - sp.sin(e.base.args[0]) ** 2)
    return [sp.factor(sp.cancel(x.replace(*squared))) for x in M.LUsolve(sp.Matrix([-r.xreplace(zero) for r in wrong]))]


def held(d: Derivation) -> list[tuple[sp.Symbol, list[sp.Expr | None]]]:
    """(M, the accelerations as M → ∞) for each body that carries another and is held fixed as its mass M → ∞
    (its own acceleration then vanishes); a limit that is not finite is None."""
    out = []
    for M in held_fixed(d):
        out.append((M, [limit(a, M) for a in d.equations.accelerations]))
    return out
