"""Two wrong answers that are right answers to another question, named as that question.

* **another coordinate's answer**: the momentum, equation or acceleration of q_j typed where q_k's is asked
  for (p_θ₁ in the box of p_θ₂: "the momentum conjugate to θ₁: you differentiated with respect to θ̇₁");
* **the answer of a limit**: the truth with one body's mass taken to infinity, the body held still (the block
  on a wedge, D̈ = g sin α: the fixed wedge's answer, while the wedge recoils).

Both are bounded by counts: one candidate per other coordinate, one per body with a mass of its own.
"""

from __future__ import annotations

from collections.abc import Iterator

import sympy as sp

from app.engine.derive import Derivation
from app.engine.mistake_families import Mistake, spoken
from app.engine.names import unicode

MAX_BODIES = 4  # bodies whose held-still limit is tried, per step


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


def held_still(d: Derivation, step: str, truth: sp.Expr) -> Iterator[Mistake]:
    """The truth with one body's mass taken to infinity (that body held still), where the limit is finite and
    differs from the truth."""
    if step not in ("acceleration", "omega_squared"):
        return
    namespace = d.table.namespace()
    bodies = [(p.mass, p.label) for p in d.system.particles if p.mass in namespace][:MAX_BODIES]
    if len(bodies) < 2:
        return  # one body: nothing else to hold still
    for mass_name, label in bodies:
        M = namespace[mass_name]
        limit = _at_infinity(truth, M)
        if limit is None or limit == 0 or limit.has(M) or sp.simplify(limit - truth) == 0:
            continue
        body = label or f"body of mass {unicode(mass_name)}"
        shown = unicode(mass_name)
        yield Mistake(
            f"{step}.limit.held_still.{mass_name}", "limit",
            f"{spoken(limit)}, the answer if the {body} were held still ({shown} → ∞)", None,
            f"here the {body} is free to move: it recoils as the rest moves, so its mass {shown} stays in the answer",
            limit,
        )  # fmt: skip


def _at_infinity(expr: sp.Expr, M: sp.Symbol) -> sp.Expr | None:
    """lim_{M→∞} of a rational function of M: the ratio of the leading coefficients when the degrees agree
    (None otherwise, or when expr is not rational in M)."""
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    try:
        top, bottom = sp.Poly(num, M), sp.Poly(den, M)
    except sp.PolynomialError:
        return None
    if top.degree() != bottom.degree() or top.degree() <= 0:
        return None
    # lim (a_n Mⁿ + …)/(b_n Mⁿ + …) = a_n / b_n
    return sp.factor(top.LC() / bottom.LC())
