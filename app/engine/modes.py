"""Equilibria and normal modes, for any number of coordinates.

Write L = 1/2 q_dot . M(q) q_dot + b(q) . q_dot + L0(q).  A system at rest at q0
stays there when nothing pushes it:

    dV/dq (q0) = Q(q0, 0),   with V = -L0 = U - T0

(T0, the velocity-free part of T, is a moving constraint's centrifugal term).
Put q = q0 + eps and keep first order: M(q0) eps_ddot + C eps_dot + K eps = 0 with

    K = d/dq (dV/dq - Q(q, 0)) at q0     (the Hessian of V when Q = 0),
    C = gyroscopic and damping terms, set aside for the frequencies.

Trying eps = a cos(omega t) gives (K - omega^2 M) a = 0: omega^2 are the
eigenvalues of K relative to M and a the mode shapes.  omega^2 > 0 oscillates,
omega^2 < 0 grows like exp(sqrt(-omega^2) t), omega^2 = 0 drifts freely (a
neutral direction, like a free translation).

Equilibria are solved symbolically within a time budget, otherwise found
numerically at the parameters' default values.  When every coordinate but one
is cyclic, the one-coordinate reduction adds its relative equilibria (a
circular or conical orbit): U_eff'(r0) = 0 at given values of the conserved
momenta, omega^2 = U_eff''(r0) / m_eff(r0).
"""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from app import late
from app.engine.budget import within_budget
from app.engine.derive import Derivation, positive_names
from app.engine.kinks import away_from_kinks

SOLVE_SECONDS = 1.5  # symbolic equilibria
EIGEN_SECONDS = 1.0  # symbolic omega^2
SEARCH_SECONDS = 1.5  # numeric equilibria
MAX_SOLVE_OPS = 400  # larger conditions go straight to the numeric search
MAX_EXACT_OPS = 80  # closed forms of omega^2 longer than this are given as numbers only
MAX_EQUILIBRIA = 8  # equilibria linearized (a polynomial condition can have many roots)
MAX_SYMBOLIC_SIZE = 3  # coordinates up to which M and K are kept symbolic at an exact equilibrium
ZERO = 1e-9  # relative size below which an omega^2 counts as zero

STABLE, NEUTRAL, UNSTABLE = "stable", "neutral", "unstable"


@dataclass(frozen=True)
class Mode:
    omega_squared: float
    shape: tuple[float, ...]  # largest component 1
    exact: sp.Expr | None = None


@dataclass(frozen=True)
class Equilibrium:
    position: dict[str, float]
    exact: dict[str, sp.Expr] | None  # the symbolic position, when solved
    kind: str  # stable, neutral or unstable
    mass: sp.Matrix  # M at the equilibrium (symbolic when the position is)
    stiffness: sp.Matrix  # K at the equilibrium
    modes: tuple[Mode, ...]
    coordinates: tuple[str, ...]  # the coordinates the modes are written in
    momenta: dict[str, float] = field(default_factory=dict)  # conserved momenta held fixed (reduction)

    @property
    def stable(self) -> bool:
        """No direction grows exponentially (neutral directions drift, but do not run away)."""
        return self.kind != UNSTABLE


@dataclass(frozen=True)
class NormalModes:
    potential: sp.Expr  # V = U - T0
    condition: tuple[sp.Expr, ...]  # dV/dq - Q(q, 0), zero at an equilibrium
    solved: bool  # equilibria found in closed form (else numerically at the defaults)
    equilibria: tuple[Equilibrium, ...]
    singular: tuple[dict[str, float], ...]  # equilibria where M is singular (a coordinate singularity)
    damped: bool  # velocity terms (damping, gyroscopic) present at some equilibrium
    note: str = ""  # why there is nothing, when there is nothing
    kinks: tuple[dict[str, float], ...] = ()  # equilibria at a kink of a piecewise-smooth U (|x|): no linearization


def defaults(d: Derivation) -> dict[sp.Symbol, float]:
    return {s: float(p.default) for s, p in zip(d.table.params, d.system.parameters, strict=True)}


def _numeric(expr: sp.Expr, values: Mapping[sp.Symbol, float]) -> complex:
    return complex(sp.N(sp.sympify(expr).xreplace(dict(values))))


def _function(exprs: list[sp.Expr], args: list[sp.Symbol]) -> Callable[..., np.ndarray]:
    # dummify: user names never reach the generated source
    # (a piecewise-smooth U, with Abs, has Dirac deltas in its Hessian: 0 off the kinks)
    exprs = [[away_from_kinks(x) for x in row] if isinstance(row, list) else away_from_kinks(row) for row in exprs]
    f = sp.lambdify(args, exprs, modules=["numpy"], dummify=True)
    return lambda *x: np.asarray(f(*x), dtype=float)


def _vanishes(
    g_exprs: list[sp.Expr], J: sp.Matrix, at: Mapping[sp.Symbol, float], values: Mapping[sp.Symbol, float]
) -> bool:
    """The equilibrium condition holds at a point (relative to the size of K there)."""
    point = {**values, **at}
    try:
        residual = max(abs(_numeric(e, point)) for e in g_exprs)
        scale = max([abs(_numeric(x, point)) for x in J] + [1.0])
    except (TypeError, ValueError):
        return False
    return math.isfinite(residual) and residual <= 1e-9 * scale


def _cheap(expr: sp.Expr) -> sp.Expr:
    """A quick normal form for entries of M and K at an equilibrium (no full simplification)."""
    return within_budget(lambda: sp.factor_terms(sp.cancel(expr)), expr, 0.2)


def _classify(omega_squared: list[float]) -> str:
    scale = max([abs(w) for w in omega_squared] + [1e-300])
    if any(w < -ZERO * scale for w in omega_squared):
        return UNSTABLE
    if any(abs(w) <= ZERO * scale for w in omega_squared):
        return NEUTRAL
    return STABLE


def _shape(vector: np.ndarray) -> tuple[float, ...]:
    """Scaled so that the largest component is +1."""
    v = np.real_if_close(vector).astype(float)
    big = v[int(np.argmax(np.abs(v)))]
    return tuple(float(x) for x in v / big) if big != 0 else tuple(float(x) for x in v)


def _exact_eigenvalues(M: sp.Matrix, K: sp.Matrix, assume: Mapping[sp.Symbol, sp.Symbol]) -> list[sp.Expr]:
    """Closed forms of the roots of det(K - lambda M) = 0 (under the declared signs), when small."""
    back = {v: k for k, v in assume.items()}
    M, K = M.xreplace(dict(assume)), K.xreplace(dict(assume))
    return [r.xreplace(back) for r in _roots(M, K)]


def _neat(expr: sp.Expr) -> sp.Expr:
    if any(not e.exp.is_integer for e in expr.atoms(sp.Pow)):
        return sp.factor_terms(expr)
    return sp.factor(expr)


def _roots(M: sp.Matrix, K: sp.Matrix) -> list[sp.Expr]:
    n = M.shape[0]
    if M.is_diagonal() and K.is_diagonal():
        return [sp.cancel(K[i, i] / M[i, i]) for i in range(n)]
    if n == 2:
        # det(K - l M) = a l^2 + b l + c = 0
        a = M.det()
        b = -(K[0, 0] * M[1, 1] + K[1, 1] * M[0, 0] - K[0, 1] * M[1, 0] - K[1, 0] * M[0, 1])
        c = K.det()
        root = sp.sqrt(sp.factor(sp.expand(b**2 - 4 * a * c)))
        # a rational result (the square root came out) is put over one factored denominator
        return [_neat((-b - root) / (2 * a)), _neat((-b + root) / (2 * a))]
    lam = sp.Dummy("lambda")
    poly = sp.Poly(sp.expand((K - lam * M).det(method="berkowitz")), lam)
    roots = sp.roots(poly, multiple=True)
    if len(roots) != M.shape[0]:
        return []
    return [sp.factor_terms(r) for r in roots]


def _modes(
    M: sp.Matrix,
    K: sp.Matrix,
    values: Mapping[sp.Symbol, float],
    exact: bool,
    assume: Mapping[sp.Symbol, sp.Symbol] | None = None,
) -> tuple[Mode, ...] | None:
    """Mode frequencies and shapes at the defaults; None when M is singular there."""
    Mn = np.array([[_numeric(x, values).real for x in row] for row in M.tolist()], dtype=float)
    Kn = np.array([[_numeric(x, values).real for x in row] for row in K.tolist()], dtype=float)
    if not np.all(np.isfinite(Mn)) or not np.all(np.isfinite(Kn)):
        return None
    sizes = np.abs(np.linalg.eigvalsh((Mn + Mn.T) / 2))
    if sizes.min() <= 1e-12 * max(sizes.max(), 1e-300):
        return None
    if np.allclose(Kn, Kn.T, rtol=1e-10, atol=1e-12 * max(np.abs(Kn).max(), 1e-300)):
        # symmetric K, positive M: real omega^2 and M-orthogonal shapes
        w2, vectors = late.module("scipy.linalg").eigh((Kn + Kn.T) / 2, (Mn + Mn.T) / 2)
    else:
        w2c, vectors = late.module("scipy.linalg").eig(Kn, Mn)
        order = np.argsort(w2c.real)
        w2, vectors = w2c.real[order], vectors[:, order]
    closed: list[sp.Expr] = []
    if exact:
        found = within_budget(lambda: _exact_eigenvalues(M, K, assume or {}), [], EIGEN_SECONDS)  # type: ignore[var-annotated]
        closed = [c for c in found if sp.count_ops(c) <= MAX_EXACT_OPS]
    modes = []
    for i, w in enumerate(w2):
        match = None
        for c in closed:
            value = _numeric(c, values)
            if abs(value.imag) <= 1e-9 * max(1.0, abs(value)) and abs(value.real - w) <= 1e-8 * max(1.0, abs(w)):
                match = c
                closed.remove(c)
                break
        modes.append(Mode(float(w), _shape(vectors[:, i]), match))
    return tuple(modes)


def _positive(d: Derivation) -> dict[sp.Symbol, sp.Symbol]:
    """Stand-ins carrying the declared signs (positive parameters, nonnegative distances)."""
    names = positive_names(d.system)
    table = d.table
    nonnegative = {p.name for p in d.system.parameters if p.min is not None and p.min == 0}
    out = {s: sp.Symbol(s.name, nonnegative=True) for s in table.params if s.name in nonnegative}
    out.update({s: sp.Symbol(s.name, positive=True) for s in table.params if s.name in names})
    out.update({s: sp.Symbol(s.name, nonnegative=True) for s in table.q if s.name in names})
    return out


def _periodic(g: Callable[..., np.ndarray], n: int, k: list[float]) -> list[bool]:
    """Coordinates in which the equilibrium condition repeats after 2 pi (angles)."""
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
            if not np.allclose(a, b, rtol=1e-9, atol=1e-12):
                same = False
                break
        out.append(same)
    return out


def _wrap(x: np.ndarray, periodic: list[bool]) -> np.ndarray:
    """Angles into (-pi, pi]."""
    y = x.copy()
    for i, p in enumerate(periodic):
        if p:
            y[i] = math.pi - (math.pi - y[i]) % (2 * math.pi)
    return y


def _search(
    g_exprs: list[sp.Expr], J: sp.Matrix, q: list[sp.Symbol], d: Derivation, nonnegative: set[int]
) -> list[np.ndarray]:
    """Roots of g(q) = 0 at the defaults, from a grid of starting points (within SEARCH_SECONDS)."""
    params = list(d.table.params)
    k = [float(p.default) for p in d.system.parameters]
    g = _function(g_exprs, [*q, *params])
    jac = _function(J.tolist(), [*q, *params])
    n = len(q)
    periodic = _periodic(g, n, k)
    per_axis = {1: 13, 2: 9, 3: 5}.get(n, 3)
    axes = [
        np.linspace(0.05, 3.0, per_axis) if i in nonnegative else np.linspace(-3.0, 3.0, per_axis) for i in range(n)
    ]
    starts = itertools.product(*axes) if n <= 4 else (np.random.default_rng(5).uniform(-3, 3, n) for _ in range(120))
    found: list[np.ndarray] = []
    deadline = time.monotonic() + SEARCH_SECONDS
    for start in starts:
        if time.monotonic() > deadline:
            break
        with np.errstate(all="ignore"):
            try:
                sol = late.module("scipy.optimize").root(
                    lambda x: g(*x, *k).ravel(), np.array(start, dtype=float), jac=lambda x: jac(*x, *k), method="hybr"
                )
            except (ValueError, ZeroDivisionError, FloatingPointError):
                continue
            if not np.all(np.isfinite(sol.x)):
                continue
            residual = np.abs(g(*sol.x, *k)).max()
        scale = max(1.0, float(np.abs(jac(*sol.x, *k)).max()) if np.all(np.isfinite(jac(*sol.x, *k))) else 1.0)
        if residual > 1e-9 * scale or any(sol.x[i] < -1e-12 for i in nonnegative):
            continue
        x = _wrap(sol.x, periodic)
        x[np.abs(x) < 1e-12] = 0.0
        if all(np.abs(x - y).max() > 1e-6 for y in found):
            found.append(x)
    return sorted(found, key=lambda x: tuple(x))


def _solve(g_exprs: list[sp.Expr], q: list[sp.Symbol], d: Derivation) -> list[dict[sp.Symbol, sp.Expr]] | None:
    """Closed-form equilibria (free coordinates set to 0), or None if SymPy cannot tell in time."""
    if all(e == 0 for e in g_exprs):
        return [{}]
    if sp.count_ops(g_exprs) > MAX_SOLVE_OPS:
        return None
    assume = _positive(d)
    back = {v: k for k, v in assume.items()}
    unknowns = [assume.get(s, s) for s in q]
    found = within_budget(
        # unchecked and unsimplified (much faster); each root is checked numerically by the caller
        lambda: sp.solve(
            [e.xreplace(assume) for e in g_exprs if e != 0], unknowns, dict=True, check=False, simplify=False
        ),
        None,
        SOLVE_SECONDS,
    )
    if found is None:
        return None
    return [{k.xreplace(back): v.xreplace(back) for k, v in sol.items()} for sol in found]


def normal_modes(d: Derivation, momenta: Mapping[str, float] | None = None) -> NormalModes:
    """Equilibria, their classification and normal modes, with numbers at the default parameters.

    ``momenta`` gives values of the conserved momenta for the reduction's relative
    equilibria (1 each when not given).
    """
    table, eqs, mech = d.table, d.equations, d.mechanics
    q = list(table.q)
    zero_v = dict.fromkeys(table.qd, sp.Integer(0))
    # V = -L(q, q_dot = 0) = U - T0
    V = -mech.L.xreplace(zero_v)
    Q0 = [f.xreplace(zero_v) for f in mech.Q]
    # the equilibrium condition dV/dq - Q(q, 0) = 0
    g_exprs = [sp.diff(V, s) - f for s, f in zip(q, Q0, strict=True)]
    M = eqs.mass_matrix
    if any(e.has(table.t) for e in (*g_exprs, *M)):
        return NormalModes(
            V, tuple(g_exprs), False, (), (), False, "The forces depend on time explicitly: no state stays at rest."
        )
    # K = d(dV/dq - Q)/dq
    J = sp.Matrix([[sp.diff(e, s) for s in q] for e in g_exprs])
    # C = -d f / d q_dot at rest (damping and gyroscopic terms)
    C = sp.Matrix([[sp.diff(f, v) for v in table.qd] for f in eqs.forcing]).xreplace(zero_v)
    values = defaults(d)
    nonnegative = {i for i, name in enumerate(table.names) if name in d.system.nonnegative}

    solutions = _solve(g_exprs, q, d)
    solved = solutions is not None
    points: list[tuple[dict[sp.Symbol, sp.Expr] | None, np.ndarray]] = []
    if solutions is not None:
        for sol in solutions:
            exact = {s: sol.get(s, sp.Integer(0)).xreplace({t: 0 for t in q if t not in sol}) for s in q}
            try:
                x = np.array([_numeric(exact[s], values) for s in q])
            except (TypeError, ValueError):
                continue
            if np.any(np.abs(x.imag) > 1e-12 * np.maximum(1, np.abs(x.real))) or not np.all(np.isfinite(x.real)):
                continue
            if any(x[i].real < -1e-12 for i in nonnegative):
                continue
            if not _vanishes(g_exprs, J, dict(zip(q, x.real, strict=True)), values):
                continue
            points.append((exact, x.real))
    if not points and any(e.has(*q) for e in g_exprs):
        # nothing in closed form (SymPy gave up, or found no root of a transcendental condition): search
        points = [(None, x) for x in _search(g_exprs, J, q, d, nonnegative)]
        solved = solved and not points

    equilibria: list[Equilibrium] = []
    singular: list[dict[str, float]] = []
    kinks: list[dict[str, float]] = []
    damped = False
    for exact, x in points[:MAX_EQUILIBRIA]:  # type: ignore[assignment]
        at = {s: (exact[s] if exact is not None else sp.Float(float(v))) for s, v in zip(q, x, strict=True)}
        if exact is not None and len(q) <= MAX_SYMBOLIC_SIZE:
            M0, K0 = M.xreplace(at).applyfunc(_cheap), J.xreplace(at).applyfunc(_cheap)
        else:
            # found numerically at the defaults: M and K as numbers there
            M0, K0 = M.xreplace(at).xreplace(values).evalf(), J.xreplace(at).xreplace(values).evalf()
        position = {name: float(v) for name, v in zip(table.names, x, strict=True)}
        if K0.has(sp.DiracDelta) or M0.has(sp.DiracDelta):
            # U = |x| at x = 0: the force jumps there, so no quadratic approximation (and no omega) exists
            kinks.append(position)
            continue
        modes = _modes(M0, K0, values, exact is not None and len(q) <= MAX_SYMBOLIC_SIZE, _positive(d))
        if modes is None:
            singular.append(position)
            continue
        damped = damped or any(abs(_numeric(c, values)) > 0 for c in C.xreplace(at))
        equilibria.append(
            Equilibrium(
                position,
                {s.name: v for s, v in exact.items()} if exact is not None else None,
                _classify([m.omega_squared for m in modes]),
                M0,
                K0,
                modes,
                tuple(table.names),
            )
        )
    equilibria.extend(_relative(d, momenta or {}))
    note = (
        "" if equilibria or singular or kinks else "No configuration makes every generalized force vanish: no equilibrium."
    )
    return NormalModes(V, tuple(g_exprs), solved, tuple(equilibria), tuple(singular), damped, note, tuple(kinks))


def _relative(d: Derivation, momenta: Mapping[str, float]) -> list[Equilibrium]:
    """Relative equilibria of the one-coordinate reduction: U_eff'(r0) = 0 at the given conserved momenta."""
    red = d.reduction
    if red is None or not red.momenta:
        return []
    table = d.table
    r = table.q[table.names.index(red.coordinate)]
    values = defaults(d)
    values.update({P: float(momenta.get(P.name, 1.0)) for P in red.momenta})
    held = {P.name: values[P] for P in red.momenta}
    dU = red.equilibrium_condition
    roots: list[tuple[sp.Expr | None, float]] = []
    for e in red.equilibria:
        v = _numeric(e.position, values)
        if abs(v.imag) <= 1e-12 * max(1.0, abs(v)) and math.isfinite(v.real):
            roots.append((e.position, v.real))
    if not roots and dU.has(r):
        roots = [(None, x) for x in _roots_1d(dU, r, values, red.coordinate in d.system.nonnegative)]
    out = []
    for exact, x0 in roots[:MAX_EQUILIBRIA]:
        at = {r: exact if exact is not None else sp.Float(x0)}
        m0 = red.effective_mass.xreplace(at)
        k0 = sp.diff(red.effective_potential, r, 2).xreplace(at)
        if exact is not None:
            m0, k0 = _cheap(m0), _cheap(k0)
        else:
            m0, k0 = m0.xreplace(values).evalf(), k0.xreplace(values).evalf()
        modes = _modes(sp.Matrix([[m0]]), sp.Matrix([[k0]]), values, exact is not None, _positive(d))
        if modes is None:
            continue
        out.append(
            Equilibrium(
                {red.coordinate: float(x0)},
                {red.coordinate: exact} if exact is not None else None,
                _classify([m.omega_squared for m in modes]),
                sp.Matrix([[m0]]),
                sp.Matrix([[k0]]),
                modes,
                (red.coordinate,),
                held,
            )
        )
    return out


def _roots_1d(dU: sp.Expr, r: sp.Symbol, values: Mapping[sp.Symbol, float], nonnegative: bool) -> list[float]:
    """Roots of U_eff'(r) at the given values: sign changes on a grid, refined by bisection."""
    f = _function([dU.xreplace(dict(values))], [r])
    periodic = _periodic(lambda x: f(x), 1, [])[0]
    # an even U_eff (U_eff'(-r) = -U_eff'(r)) mirrors each root: keep r >= 0
    even = nonnegative or _odd(f)
    lo, hi = (0.0, 2 * math.pi) if periodic else (-10.0, 10.0)
    if even:
        lo = 0.0
        hi = math.pi if periodic else hi
    grid = np.linspace(lo, hi, 2001)[1:-1]
    with np.errstate(all="ignore"):
        y = np.array([f(x)[0] for x in grid])
    roots: list[float] = []
    for a, b, ya, yb in zip(grid[:-1], grid[1:], y[:-1], y[1:], strict=True):
        if not (np.isfinite(ya) and np.isfinite(yb)) or ya * yb > 0:
            continue
        x0 = a if ya == 0 else late.module("scipy.optimize").brentq(lambda x: f(x)[0], a, b, xtol=1e-14)
        scale = max(abs(ya), abs(yb), 1.0)
        # a sign change across a pole is not a root
        if abs(f(x0)[0]) <= 1e-8 * scale and all(abs(x0 - z) > 1e-9 for z in roots):
            roots.append(float(x0))
    return roots


def _odd(f: Callable[..., np.ndarray]) -> bool:
    with np.errstate(all="ignore"):
        xs = np.array([0.37, 0.81, 1.23])
        a = np.array([f(x)[0] for x in xs])
        b = np.array([f(-x)[0] for x in xs])
    return bool(np.all(np.isfinite(a)) and np.allclose(a, -b, rtol=1e-9, atol=1e-12))
