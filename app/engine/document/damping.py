"""A damped equilibrium of one coordinate as a textbook writes it: the auxiliary equation and its roots.

Linearised about an equilibrium q₀, a one-coordinate equation of motion q̈ = a(q, q̇) becomes

    η̈ + 2β η̇ + ω₀² η = 0,   2β = −∂a/∂q̇,  ω₀² = −∂a/∂q   (both at q = q₀, q̇ = 0),

and η ∝ e^{σt} turns it into the auxiliary equation σ² + 2β σ + ω₀² = 0, whose roots are

    σ = −β ± √(β² − ω₀²)

(Taylor writes r for them, but r names the positions r⃗ on every page, and s is the unit beside them: the
page writes λ, or σ where λ is a constraint's multiplier, app/engine/notation.exponent).
Where ω₀² < 0 (the pendulum's top, −g/R) it is no squared frequency: the report writes η̈ + 2β η̇ − (g/R) η = 0.
The motion is critically damped at β = ω₀: solved for the damping parameter (b on the damped pendulum) this is its critical value.  With light damping
(β < ω₀) the amplitude decays as e^{−βt}, so the energy, quadratic in it, as e^{−2βt} on average.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from app.engine.algebra.budget import within_budget
from app.engine.algebra.simplify import tidy
from app.engine.derivation.derive import Derivation
from app.limits import SOLVE_WORK


@dataclass(frozen=True)
class Damped:
    beta: sp.Expr  # half the damping rate: β = b/(2 m R²) on the damped pendulum
    omega0_squared: sp.Expr  # the undamped ω₀² at the equilibrium
    # the damping parameter and its critical value (β = ω₀), when β holds one parameter to the first power
    critical: tuple[sp.Symbol, sp.Expr] | None


def damped(d: Derivation, position: sp.Expr) -> Damped | None:
    """β and ω₀² about the equilibrium at ``position`` of a one-coordinate system with a velocity term; None
    without one (or with an explicit time dependence, or more coordinates)."""
    if len(d.table.q) != 1 or not d.equations.closed_form:
        return None
    q, qd = d.table.q[0], d.table.qd[0]
    a = d.equations.accelerations[0]
    at = {q: position, qd: 0}
    # 2β = −∂a/∂q̇ and ω₀² = −∂a/∂q at the equilibrium
    beta = tidy(-sp.diff(a, qd).xreplace(at) / 2)
    omega0_squared = tidy(-sp.diff(a, q).xreplace(at))
    moving = {*d.table.q, *d.table.qd, sp.Symbol("t", real=True)}
    if beta == 0 or beta.free_symbols & moving or omega0_squared.free_symbols & moving:
        return None
    return Damped(beta, omega0_squared, _critical(beta, omega0_squared))


def _critical(beta: sp.Expr, omega0_squared: sp.Expr) -> tuple[sp.Symbol, sp.Expr] | None:
    """The damping parameter's value at β = ω₀ (β² = ω₀²), for the parameter β is proportional to."""
    linear = [p for p in beta.free_symbols if not sp.cancel(beta / p).has(p) and not omega0_squared.has(p)]
    if len(linear) != 1:
        return None
    p = linear[0]
    positive = sp.Symbol(p.name, positive=True)
    others = {s: sp.Symbol(s.name, positive=True) for s in (beta.free_symbols | omega0_squared.free_symbols) - {p}}
    # β is proportional to p: p_c = p ω₀/β, positive where the parameters are
    value = within_budget(lambda: sp.simplify(p * sp.sqrt(omega0_squared) / beta), None, SOLVE_WORK)
    if value is None or value.xreplace({**others, p: positive}).is_positive is False:
        return None
    return p, value
