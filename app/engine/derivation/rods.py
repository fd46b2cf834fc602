"""Fixed distances between particles: where the positions themselves say a rod (or a string) is.

A particle whose distance from the origin, or from another particle, does not
change as the coordinates and time change is held by something rigid.  The
engine proves it on the declared positions: with D = |r_j − r_i|² (r_i = 0 for
the origin), the distance is fixed exactly when ∂D/∂q_k = 0 for every
coordinate and ∂D/∂t = 0, each decided by the budgeted zero test.  A pair
the test cannot decide is left out here; the viz layer tries it numerically.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from app.engine.algebra.simplify import is_zero
from app.engine.derivation.derive import Derivation

MAX_PAIRS = 28  # eight particles and the origin: far more than a drawing needs


def fixed_distances(d: Derivation) -> list[dict[str, Any]]:
    """[{"from": i or None (the origin), "to": j}] for each pair at a distance proven constant."""
    positions, table = d.mechanics.positions, d.table
    moving = (*table.q, table.t)
    out: list[dict[str, Any]] = []
    checked = 0
    for j, r in enumerate(positions):
        if not any(e.has(*moving) for e in r):
            continue  # a particle that never moves needs no rod
        for i in (None, *range(j)):
            checked += 1
            if checked > MAX_PAIRS:
                return out
            other = (sp.Integer(0),) * 3 if i is None else positions[i]
            # D = |r_j - r_i|^2, fixed when no coordinate and not time changes it
            distance2 = sum(((a - b) ** 2 for a, b in zip(r, other, strict=True)), sp.Integer(0))
            if distance2 == 0 or not distance2.has(*moving):
                continue
            if all(is_zero(sp.diff(distance2, s)) for s in moving):
                out.append({"from": i, "to": j})
    return out
