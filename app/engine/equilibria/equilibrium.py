"""One equilibrium and its normal modes, and the numbers the equilibria's searches share.

An ``Equilibrium`` holds its position (in numbers, and in closed form when solved), its verdict from the
full linearization, M and K there and its modes; a ``Mode`` is omega^2 with its shape, matched to a closed
form when one is found.  The helpers evaluate expressions and matrices at the default parameters, as the
equilibria at rest (``app.engine.equilibria.modes``) and the steady motions (``app.engine.equilibria.steady``) both do.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from app.engine.algebra.kinks import away_from_kinks
from app.engine.equilibria import modes_exact
from app.engine.equilibria.stability import UNSTABLE, Linear
from app.engine.parser.symbols import SymbolTable
from app.scenes.types import System

MAX_EQUILIBRIA = 8  # equilibria linearized (a polynomial condition can have many roots)


@dataclass(frozen=True)
class Mode:
    omega_squared: float
    shape: tuple[float, ...]  # largest component 1
    exact: sp.Expr | None = None


@dataclass(frozen=True)
class Equilibrium:
    position: dict[str, float]
    exact: dict[str, sp.Expr] | None  # the symbolic position, when solved
    kind: str  # stable, neutral or unstable (from the full linearization, velocity terms included)
    mass: sp.Matrix  # M at the equilibrium (symbolic when the position is)
    stiffness: sp.Matrix  # K at the equilibrium
    modes: tuple[Mode, ...]
    coordinates: tuple[str, ...]  # the coordinates the modes are written in
    momenta: dict[str, float] = field(default_factory=dict)  # conserved momenta held fixed (reduction)
    linear: Linear | None = None  # exponents, frequencies and the gyroscopic verdict

    @property
    def stable(self) -> bool:
        """No direction grows exponentially (neutral directions drift, but do not run away)."""
        return self.kind != UNSTABLE


def defaults(system: System, table: SymbolTable) -> dict[sp.Symbol, float]:
    """Each parameter's symbol and its default value."""
    return {s: float(p.default) for s, p in zip(table.params, system.parameters, strict=True)}


def numeric(expr: sp.Expr, values: Mapping[sp.Symbol, float]) -> complex:
    """The value of an expression at the given values of its symbols."""
    return complex(sp.N(sp.sympify(expr).xreplace(dict(values))))


def array(matrix: sp.Matrix, values: Mapping[sp.Symbol, float]) -> np.ndarray:
    """A matrix as real numbers at the given values (NaN throughout where an entry is complex there)."""
    out = np.array([[numeric(x, values) for x in row] for row in matrix.tolist()], dtype=complex)
    if np.any(np.abs(out.imag) > 1e-9 * max(1.0, float(np.abs(out.real).max()))):
        return np.full(out.shape, np.nan)
    return out.real


def function(exprs: list, args: list[sp.Symbol]) -> Callable[..., np.ndarray]:
    """The expressions as one numpy function of ``args`` (a kink's Dirac deltas read as 0)."""
    # dummify: user names never reach the generated source
    # (a piecewise-smooth U, with Abs, has Dirac deltas in its Hessian: 0 off the kinks)
    exprs = [[away_from_kinks(x) for x in row] if isinstance(row, list) else away_from_kinks(row) for row in exprs]
    f = sp.lambdify(args, exprs, modules=["numpy"], dummify=True)
    return lambda *x: np.asarray(f(*x), dtype=float)


def vanishes(g: Callable[..., np.ndarray], jac: Callable[..., np.ndarray], x: np.ndarray, k: list[float]) -> bool:
    """The equilibrium condition holds at a point (each equation relative to its own row of K there)."""
    with np.errstate(all="ignore"):
        r, j = np.asarray(g(*x, *k), dtype=float).ravel(), np.asarray(jac(*x, *k), dtype=float)
    if not (np.all(np.isfinite(r)) and np.all(np.isfinite(j))):
        return False
    j = j.reshape(len(r), -1)
    rows = np.abs(j).max(axis=1)
    rows = np.where(rows > 0, rows, max(float(rows.max()), 1.0))
    size = max(1.0, float(np.abs(x).max())) if len(x) else 1.0
    return bool(np.all(np.abs(r) <= 1e-9 * rows * size + 1e-300))


def modes_of(
    M: sp.Matrix,
    K: sp.Matrix,
    lin: Linear,
    values: Mapping[sp.Symbol, float],
    exact: bool,
    assume: Mapping[sp.Symbol, sp.Symbol],
) -> tuple[Mode, ...]:
    """omega^2 and shapes from the numbers, each matched to a closed form when one is found in time."""
    closed = modes_exact.eigenvalues(M, K, assume) if exact else []
    out = []
    for w, shape in zip(lin.omega_squared, lin.shapes, strict=True):
        match = None
        for c in closed:
            value = numeric(c, values)
            if abs(value.imag) <= 1e-9 * max(1.0, abs(value)) and abs(value.real - w) <= 1e-8 * max(1.0, abs(w)):
                match = c
                closed.remove(c)
                break
        out.append(Mode(float(w), shape, match))
    return tuple(out)
