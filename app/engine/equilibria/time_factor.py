"""Linearised equations that change with t only through a factor common to all their coefficients.

At an equilibrium held for all t, the linearised equations are M(t) δq̈ + G(t) δq̇ + K(t) δq = 0.  When
every coefficient is the same function c(t) times a constant,
    M(t) = c(t) M₀,   G(t) = c(t) G₀,   K(t) = c(t) K₀,
dividing by c(t) leaves M₀ δq̈ + G₀ δq̇ + K₀ δq = 0, with constant exponents, frequencies and damping.
Caldirola–Kanai, L = e^{γt}(½mẋ² − ½kx²), is the textbook case: c = e^{γt}, and ẍ + γẋ + (k/m)x = 0.

The factor is found numerically at the equilibrium: the coefficients at the instants TIMES are compared
with those at the first of them; each must be a multiple of it (to 1e-9), never by 0.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import sympy as sp

# instants at which a time-dependent condition or coefficient is tested (away from special values); one home,
# used by app.engine.equilibria.modes too
TIMES = (0.0, 0.61, 1.7, 4.3)


def common_factor_time(
    matrices: Sequence[sp.Matrix], args: Sequence[sp.Symbol], t: sp.Symbol, point: Sequence[float]
) -> float | None:
    """An instant t₀ at which the coefficients, divided by a common c(t), take their constant values M₀, G₀, K₀
    (``point``: the values of ``args``, the equilibrium and the parameters); None when there is no such factor."""
    entries = [x for matrix in matrices for x in matrix]
    f = sp.lambdify([*args, t], entries, modules=["numpy"], dummify=True)
    with np.errstate(all="ignore"):
        values = [np.asarray(f(*point, s), dtype=complex) for s in TIMES]
    if not all(np.all(np.isfinite(v)) for v in values):
        return None
    first = values[0]
    size = float(np.abs(first).max())
    if size == 0:
        return None
    for v in values[1:]:
        # the best multiple c of the first instant's coefficients: c = ⟨v, v₀⟩ / ⟨v₀, v₀⟩
        c = complex(np.vdot(first, v) / np.vdot(first, first))
        if c == 0 or not np.allclose(v, c * first, rtol=1e-9, atol=1e-12 * abs(c) * size):
            return None
    return TIMES[0]
