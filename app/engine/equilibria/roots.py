"""Every root of an equilibrium condition g(q) = 0 at given parameter values: a bounded numerical search.

The search is the net under the closed forms (``app.engine.equilibria.modes``): it always
runs, and what it finds is merged with what SymPy found.  It covers

* an angle (a coordinate in which g repeats after 2 pi) over one period, (-pi, pi];
* any other coordinate over [-3, 3] and over the scales the parameters set
  (+-s/2, +-s, +-2s, +-4s for each parameter value s), so that a length of 100 m
  is searched at 100 m, not only near 1.

One coordinate: g is sampled on a fine grid, every sign change is refined by
bisection (brentq), and every local minimum of |g| by Newton (a double root
touches zero without changing sign).  Several coordinates: Newton's method
(MINPACK's hybrid) from a grid of starting points, or random ones beyond three
coordinates.  Roots are merged modulo 2 pi in the angles and within a relative
tolerance elsewhere.  Whatever is found is a root (the residual is checked);
what lies outside the searched box, or between starting points, may be missed.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence

import numpy as np

from app import late

SCAN_POINTS = 4001  # grid of the one-coordinate scan
SAME = 1e-6  # relative distance within which two roots are one


def periodic_axes(g: Callable[..., np.ndarray], n: int, k: Sequence[float]) -> list[bool]:
    """Coordinates in which g repeats after 2 pi (angles)."""
    rng = np.random.default_rng(13)
    out = []
    for i in range(n):
        same = True
        for _ in range(3):
            x = rng.uniform(0.2, 1.3, n)
            y = x.copy()
            y[i] += 2 * math.pi
            with np.errstate(all="ignore"):
                a, b = g(*x, *k), g(*y, *k)
            if not (np.all(np.isfinite(a)) and np.allclose(a, b, rtol=1e-9, atol=1e-12)):
                same = False
                break
        out.append(same)
    return out


def wrap(x: np.ndarray, periodic: Sequence[bool]) -> np.ndarray:
    """Angles into (-pi, pi]."""
    y = np.array(x, dtype=float)
    for i, p in enumerate(periodic):
        if p:
            y[i] = math.pi - (math.pi - y[i]) % (2 * math.pi)
            if y[i] < -math.pi + 1e-9:  # -pi and pi are one angle: the end of the interval that is kept
                y[i] = math.pi
    y[np.abs(y) < 1e-12] = 0.0
    return y


def same_point(x: np.ndarray, y: np.ndarray, periodic: Sequence[bool]) -> bool:
    """Equal modulo 2 pi in the angles and within a relative tolerance elsewhere."""
    for i, p in enumerate(periodic):
        d = x[i] - y[i]
        if p:
            d = (d + math.pi) % (2 * math.pi) - math.pi
        if abs(d) > SAME * max(1.0, abs(x[i]), abs(y[i])):
            return False
    return True


def _axis(periodic: bool, nonnegative: bool, count: int, scales: Sequence[float]) -> np.ndarray:
    if periodic:
        return np.linspace(-math.pi, math.pi, count, endpoint=False) + math.pi / count
    base = np.linspace(0.05, 3.0, count) if nonnegative else np.linspace(-3.0, 3.0, count)
    extra = [f * s for s in scales for f in (0.5, 1.0, 2.0, 4.0) if s > 3.0 or s < 0.3]
    extra += [-x for x in extra] if not nonnegative else []
    return np.unique(np.concatenate([base, np.array(extra, dtype=float)]))


def _is_root(g: Callable[[np.ndarray], np.ndarray], x: np.ndarray, rows: np.ndarray) -> bool:
    """|g_i(x)| small relative to its own row of the Jacobian (so equations of very different sizes each count)."""
    with np.errstate(all="ignore"):
        r = g(x)
    if not np.all(np.isfinite(r)):
        return False
    size = max(1.0, float(np.abs(x).max()))
    return bool(np.all(np.abs(r) <= 1e-9 * np.maximum(rows, 1e-300) * size + 1e-300))


def _on_grid(g: Callable[[np.ndarray], np.ndarray], grid: np.ndarray) -> np.ndarray:
    """g at every point of the grid: in one call where g's expression broadcasts over an array (a lambdified
    NumPy expression does; 4,001 calls one point at a time were a tenth of a single pendulum's document),
    else point by point (an expression free of the coordinate gives one number, not one per point)."""
    with np.errstate(all="ignore"):
        try:
            y = np.asarray(g(grid[np.newaxis, :]), dtype=float).ravel()
        except (TypeError, ValueError):
            y = np.empty(0)
        if y.shape == grid.shape:
            return y
        return np.array([float(g(np.array([x]))[0]) for x in grid])


def _scan_1d(g: Callable[[np.ndarray], np.ndarray], lo: float, hi: float) -> list[float]:
    """Sign changes and touching minima of a scalar g on [lo, hi]."""
    grid = np.linspace(lo, hi, SCAN_POINTS)
    y = _on_grid(g, grid)
    opt = late.module("scipy.optimize")
    found: list[float] = []
    size = float(np.nanmax(np.abs(y[np.isfinite(y)]))) if np.any(np.isfinite(y)) else 1.0
    f = lambda x: float(g(np.array([x]))[0])  # noqa: E731
    for i in range(len(grid) - 1):
        a, b, ya, yb = grid[i], grid[i + 1], y[i], y[i + 1]
        if not (np.isfinite(ya) and np.isfinite(yb)):
            continue
        if ya == 0:
            found.append(float(a))
        elif ya * yb < 0:
            # disp=False: where rounding in a steep g keeps Brent's method from meeting the tolerance it
            # returns its best estimate instead of raising; the test below decides whether it is a root
            with np.errstate(all="ignore"):
                x0 = opt.brentq(f, a, b, xtol=1e-15, disp=False)
            # a sign change across a pole is not a root
            if abs(f(x0)) <= 1e-8 * max(abs(ya), abs(yb), 1.0):
                found.append(float(x0))
        elif 0 < i and np.isfinite(y[i - 1]) and abs(ya) <= abs(y[i - 1]) and abs(ya) <= abs(yb):
            # a local minimum of |g| that may touch zero (a double root): Newton from there
            if abs(ya) <= 1e-3 * max(size, 1e-300):
                with np.errstate(all="ignore"):
                    try:
                        x0 = opt.newton(f, a, tol=1e-14, maxiter=50)
                    except (RuntimeError, OverflowError, ZeroDivisionError):
                        continue
                found.append(float(x0))
    return found


def search(
    g: Callable[..., np.ndarray],
    jac: Callable[..., np.ndarray],
    n: int,
    k: Sequence[float],
    nonnegative: set[int],
    evaluations: int,
) -> tuple[list[np.ndarray], list[bool]]:
    """Roots of g(q, k) = 0 (wrapped and merged), and which coordinates are angles.

    The Newton searches from the starts, nearest the origin first, stop after the one at which ``evaluations``
    evaluations of g and its Jacobian have been used: a count, not a clock, so the roots found are a
    function of the system alone."""
    periodic = periodic_axes(g, n, k)
    scales = [abs(float(v)) for v in k if math.isfinite(v) and v != 0]
    G = lambda x: np.asarray(g(*x, *k), dtype=float).ravel()  # noqa: E731
    J = lambda x: np.asarray(jac(*x, *k), dtype=float).reshape(n, n)  # noqa: E731

    def rows_at(x: np.ndarray) -> np.ndarray:
        """The size of each equation near x: its largest Jacobian entry (1 where unknown)."""
        with np.errstate(all="ignore"):
            j = J(x)
        if not np.all(np.isfinite(j)):
            return np.ones(n)
        rows = np.abs(j).max(axis=1)
        return np.where(rows > 0, rows, max(float(rows.max()), 1.0))

    candidates: list[np.ndarray] = []
    if n == 1:
        if periodic[0]:
            spans = [(-math.pi - 0.05, math.pi + 0.05)]  # past both ends: a root at pi is not on the edge
        else:
            spans = [(-3.0, 3.0)] + [(-4 * s, 4 * s) for s in scales if s > 3.0 or s < 0.3]
            spans = [(0.0, hi) if 0 in nonnegative else (lo, hi) for lo, hi in spans]
        for lo, hi in spans:
            candidates += [np.array([x]) for x in _scan_1d(G, lo, hi)]
    per_axis = {1: 13, 2: 11, 3: 6}.get(n, 3)
    axes = [_axis(periodic[i], i in nonnegative, per_axis, scales) for i in range(n)]
    if n <= 3:
        starts: list[np.ndarray] = [np.array(s, dtype=float) for s in itertools.product(*axes)]
        # nearest the origin first: when the evaluations run out, the far-out starts (the parameters' scales) are the ones cut
        starts.sort(key=lambda x: float(np.abs(x).max()))
    else:
        rng = np.random.default_rng(5)
        starts = [np.array([rng.choice(a) for a in axes]) for _ in range(200)]
    opt = late.module("scipy.optimize")  # imported before the clock starts
    used = 0
    for start in starts:
        if used >= evaluations:
            break
        with np.errstate(all="ignore"):
            try:
                sol = opt.root(G, start, jac=J, method="hybr")
            except (ValueError, ZeroDivisionError, FloatingPointError, np.linalg.LinAlgError):
                used += 1
                continue
        # each start's Newton steps: the evaluations of g and of its Jacobian it used
        used += int(getattr(sol, "nfev", 1)) + int(getattr(sol, "njev", 0))
        if np.all(np.isfinite(sol.x)):
            candidates.append(sol.x)
    found: list[np.ndarray] = []
    for x in candidates:
        # merging costs a comparison with each root kept: counted with the evaluations, so a system whose
        # conditions vanish along a whole curve (thousands of roots) ends its merge where its search would
        used += len(found)
        if used >= 2 * evaluations:
            break
        y = wrap(x, periodic)
        # checked after wrapping: an iterate far out (theta = 1e6) has a residual large in absolute terms
        if any(y[i] < -1e-12 for i in nonnegative) or not _is_root(G, y, rows_at(y)):
            continue
        if not any(same_point(y, z, periodic) for z in found):
            found.append(y)
    return sorted(found, key=lambda x: tuple(x)), periodic
