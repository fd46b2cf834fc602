"""Finding the true path between two fixed ends by making the discretised action stationary.

The path is q_0 … q_N at t_j = j h (h = T/N) with q_0 and q_N fixed.  The discrete action uses the
midpoint rule for each step (a variational integrator's discrete Lagrangian):

    S_d = Σ_j h L(t_j+½, (q_j + q_j+1)/2, (q_j+1 - q_j)/h)

and the path that makes it stationary solves the discrete Euler-Lagrange equations ∂S_d/∂q_j = 0 at
every interior node, a second-order approximation of the true motion with the same ends.  Newton's
method solves them: the Hessian of S_d is block tridiagonal (each step couples two neighbouring
nodes), a band of width 2n - 1 in the order (node, coordinate), so each iteration costs O(N n³).
A step is halved until the gradient's norm falls (a damped Newton iteration); each iterate is kept
for the page's animation.  The number of negative eigenvalues of the Hessian at the end says what
the stationary path is: none, a minimum of S_d; some, a saddle (past the first kinetic focus).

``shoot`` finds the same path by shooting: the initial velocity whose run from q(0) ends at q(T),
by Newton's method on the end point with the Jacobi matrix ∂q(T)/∂q̇(0) from neighbouring runs.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from app import late
from app.numerics.action import ActionTerms
from app.numerics.choose import central_differences
from app.numerics.errors import SimulationError
from app.numerics.simulate import simulate
from app.numerics.system import NumericSystem

MAX_ITERATIONS = 40
GRADIENT_TOLERANCE = 1e-11  # relative to the scale of the gradient's terms


@dataclass
class Relaxed:
    t: np.ndarray
    q: np.ndarray  # (n, N + 1)
    action: float
    iterations: list[np.ndarray]  # the interior path after each Newton step (the first is the trial)
    negative: int  # negative eigenvalues of the discrete action's Hessian
    converged: bool
    gradient: float  # the discrete Euler-Lagrange residual at the end, relative to the scale of its terms

    @property
    def kind(self) -> str:
        return "minimum" if self.negative == 0 else "saddle"


def _blocks(terms: ActionTerms, k: np.ndarray, t: np.ndarray, Q: np.ndarray) -> tuple[float, np.ndarray, list, list]:
    """S_d, its gradient at every node (n, N + 1), and the Hessian's diagonal and upper blocks per node."""
    n, nodes = Q.shape
    h = t[1] - t[0]
    tm = (t[:-1] + t[1:]) / 2
    X = (Q[:, :-1] + Q[:, 1:]) / 2
    V = (Q[:, 1:] - Q[:, :-1]) / h
    L, Lq, Lv, P, C, R = terms.split(terms.evaluate(tm, X, V, k))
    S = float(h * L.sum())
    # ∂S_d/∂q_j: from step j (node j is its left end: x̄' = ½, v' = -1/h) and step j-1 (right end: ½, 1/h)
    grad = np.zeros((n, nodes))
    grad[:, :-1] += h * (0.5 * Lq - Lv / h)
    grad[:, 1:] += h * (0.5 * Lq + Lv / h)
    # the step's Hessian block for nodes a, b with (α, β) = ∂(x̄, v)/∂q:  h (α_a α_b R + α_a β_b C + β_a α_b Cᵀ + β_a β_b P)
    left, right = (0.5, -1.0 / h), (0.5, 1.0 / h)
    Pm, Cm, Rm = (np.moveaxis(x, -1, 0) for x in (P, C, R))  # (steps, n, n)
    Ct = np.swapaxes(Cm, 1, 2)

    def block(a: tuple[float, float], b: tuple[float, float]) -> np.ndarray:
        return h * (a[0] * b[0] * Rm + a[0] * b[1] * Cm + a[1] * b[0] * Ct + a[1] * b[1] * Pm)

    diagonal = np.zeros((nodes, n, n))
    diagonal[:-1] += block(left, left)
    diagonal[1:] += block(right, right)
    upper = block(left, right)  # (steps, n, n): rows node j, columns node j + 1
    return S, grad, list(diagonal), list(upper)


def _band(diagonal: list, upper: list, n: int) -> np.ndarray:
    """The interior nodes' Hessian as a symmetric lower band (``eig_banded``'s and, mirrored, ``solve_banded``'s)."""
    inner = len(diagonal) - 2
    m = inner * n
    width = 2 * n - 1
    band = np.zeros((width + 1, m))
    for j in range(inner):
        D = diagonal[j + 1]
        for i in range(n):
            for r in range(i, n):
                band[r - i, j * n + i] = D[r, i]
        if j + 1 < inner:
            U = upper[j + 1]  # rows node j + 1, columns node j + 2: lower part is its transpose
            for i in range(n):
                for r in range(n):
                    band[n + r - i, j * n + i] = U[i, r]
    return band


def _solve(band: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    width = band.shape[0] - 1
    m = band.shape[1]
    full = np.zeros((2 * width + 1, m))
    full[width:] = band
    for d in range(1, width + 1):
        full[width - d, d:] = band[d, : m - d]
    return late.module("scipy.linalg").solve_banded((width, width), full, rhs)


def relax(
    terms: ActionTerms, k: np.ndarray, start: np.ndarray, end: np.ndarray, T: float, trial: np.ndarray
) -> Relaxed:
    """Newton's method on the discrete Euler-Lagrange equations from a trial path (n, N + 1) with these ends."""
    n, nodes = trial.shape
    if nodes < 3:
        raise SimulationError("a discrete path needs at least 3 nodes", "steps")
    t = np.linspace(0.0, T, nodes)
    Q = np.array(trial, dtype=float)
    Q[:, 0], Q[:, -1] = start, end
    history = [Q.copy()]
    S, grad, diagonal, upper = _blocks(terms, k, t, Q)
    norm = float(np.abs(grad[:, 1:-1]).max())
    scale = max(float(np.abs(diagonal).max()) * max(float(np.abs(Q).max()), 1.0), 1e-300)
    converged = False
    for _ in range(MAX_ITERATIONS):
        if not np.isfinite(norm):
            raise SimulationError("the trial path leaves the region where L can be evaluated", "trial")
        if norm <= GRADIENT_TOLERANCE * scale:
            converged = True
            break
        step = _solve(_band(diagonal, upper, n), -grad[:, 1:-1].T.reshape(-1)).reshape(nodes - 2, n).T
        size = 1.0
        for _ in range(30):
            candidate = Q.copy()
            candidate[:, 1:-1] += size * step
            S_new, g_new, d_new, u_new = _blocks(terms, k, t, candidate)
            new_norm = float(np.abs(g_new[:, 1:-1]).max())
            if np.isfinite(new_norm) and new_norm < norm:
                break
            size /= 2
        else:
            break
        Q, S, grad, diagonal, upper, norm = candidate, S_new, g_new, d_new, u_new, new_norm
        history.append(Q.copy())
    # the directions that lower S_d: the Hessian's negative eigenvalues
    negative = late.module("scipy.linalg").eig_banded(
        _band(diagonal, upper, n), lower=True, eigvals_only=True, select="v", select_range=(-np.inf, 0.0)
    ).size
    return Relaxed(t, Q, S, history, negative, converged, norm / scale)


def shoot(
    system: NumericSystem, k: np.ndarray, start: np.ndarray, end: np.ndarray, T: float, v0: np.ndarray, samples: int
) -> tuple[np.ndarray, np.ndarray]:
    """The initial velocity whose run ends at ``end`` at T (Newton from v0), and that run's q at ``samples`` times."""
    n = system.n

    def run(v: np.ndarray) -> np.ndarray:
        y0 = np.concatenate([start, v])
        tr = simulate(system, k, y0, T, samples, rtol=1e-12, atol=1e-14, estimate=False).trajectory
        if not tr.complete:
            raise SimulationError("the shooting run did not reach T", "t_end")
        return tr.y[:, :n].T

    v = np.array(v0, dtype=float)
    for _ in range(30):
        q = run(v)
        miss = q[:, -1] - end
        if np.abs(miss).max() < 1e-12 * max(1.0, float(np.abs(end).max())):
            return v, q
        # the Jacobi matrix ∂q(T)/∂q̇(0) from neighbouring runs
        J = central_differences(lambda w: run(w)[:, -1], v, 1e-6)
        v = v - np.linalg.solve(J, miss)
    raise SimulationError("shooting did not converge onto the end point", "end")


# relative to the path's size: the relaxed and the shot path agree within this (or within the grid's error)
AGREEMENT = 1e-6
COARSE = 1e-2  # relative to the path's size: a grid whose halving moves the path by more is too coarse to judge


@dataclass
class Found:
    """The relaxed path on N steps, its Richardson extrapolation with 2N, and the shooting solution (if any)."""

    coarse: Relaxed
    fine: Relaxed
    q: np.ndarray  # (4 q_2N - q_N) / 3 at the N + 1 nodes: fourth order
    error_estimate: float  # max |q_2N - q_N| / 3: the error of q_2N, which the extrapolated path improves on
    velocity: np.ndarray | None  # q̇(0) of the shooting solution; None when no shooting run reached the end
    shot: np.ndarray | None  # the shooting run's q at the N + 1 nodes
    difference: float | None  # max |extrapolated - shot|
    reasons: list[str] = field(default_factory=list)  # why the relaxed path is not the true one (empty: it is)

    @property
    def found(self) -> bool:
        return not self.reasons


def _verdict(coarse: Relaxed, fine: Relaxed, q: np.ndarray, estimate: float, difference: float | None) -> list[str]:
    """Why the relaxed path is not the path of the true motion between these ends, as codes (none: it is).

    A stationary discrete path is the true one only if (1) Newton's method solved the discrete Euler-Lagrange
    equations on both grids, (2) the grid resolves it, and (3) a motion from q(0), shot to q(T), runs along it:
    Newton on S_d can stop short, or land on a stationary point of S_d that no motion follows."""
    scale = max(1.0, float(np.abs(q).max()))
    reasons = []
    if not (coarse.converged and fine.converged):
        reasons.append("not-stationary")
    elif not estimate <= COARSE * scale:
        reasons.append("too-coarse")
    if difference is None:
        reasons.append("no-shooting")
    elif not difference <= max(AGREEMENT * scale, estimate):
        reasons.append("disagrees")
    return reasons


def find_path(
    system: NumericSystem,
    terms: ActionTerms,
    k: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    T: float,
    trial: np.ndarray,
    velocities: tuple[np.ndarray, ...] = (),
) -> Found:
    """Relax a trial path (n, N + 1) on N steps and on 2N steps, extrapolate, and compare with shooting.

    Shooting starts from the extrapolated path's initial slope, then from each of ``velocities`` (e.g. the
    true path's q̇(0)), then from the chord (q(T) - q(0))/T, until one run reaches q(T)."""
    coarse = relax(terms, k, start, end, T, trial)
    nodes = trial.shape[1]
    t_fine = np.linspace(0.0, T, 2 * nodes - 1)
    finer = np.array([np.interp(t_fine, coarse.t, row) for row in coarse.q])
    fine = relax(terms, k, start, end, T, finer)
    # the midpoint rule's error is c h² + O(h⁴): eliminate c h² between h and h/2
    q = (4 * fine.q[:, ::2] - coarse.q) / 3
    estimate = float(np.abs(fine.q[:, ::2] - coarse.q).max() / 3)
    h = T / (nodes - 1)
    # a start for shooting: the one-sided slope of the extrapolated path, second order
    slope = (-3 * q[:, 0] + 4 * q[:, 1] - q[:, 2]) / (2 * h)
    velocity = shot = difference = None
    for v0 in (slope, *velocities, (end - start) / T):
        if not np.all(np.isfinite(v0)):
            continue
        try:
            velocity, shot = shoot(system, k, start, end, T, v0, nodes)
        except (SimulationError, np.linalg.LinAlgError):
            continue
        difference = float(np.abs(q - shot).max())
        break
    reasons = _verdict(coarse, fine, q, estimate, difference)
    return Found(coarse, fine, q, estimate, velocity, shot, difference, reasons)
