"""The action S = ∫ L dt along the true path and along its variations, and the second variation.

Everything is numeric: the engine's L and its first and second derivatives are printed once per
system (as the right-hand sides are, ``app.numerics.generate``) into one vectorised function, so a
request on a warm system runs no SymPy.  The true path q(t) on [0, T] is a simulation from the
initial state with tight tolerances, sampled densely (its dense output) on an even grid of M = 4N + 1
times, spacing h.

* S(ε) for the varied path q + ε η e_c (coordinate c alone), η(t) = sin(kπt/T): L on the grid, then
  composite Simpson with steps h and 2h and Richardson's extrapolation (Boole's rule).  The stated
  error is |Simpson(h) - Simpson(2h)| / 15 (the error of Simpson(h), which the extrapolated value
  improves on) plus the path's own: tolerance times ∫|L| dt.  When that exceeds 1e-9 of ∫|L| dt, the
  grid is made four times finer.
* dS/dε at 0 = ∫ (∂L/∂q_c η + ∂L/∂q̇_c η') dt, and d²S/dε² at 0 = ∫ (P η'² + 2 C η η' + R η²) dt with
  P = ∂²L/∂q̇_c², C = ∂²L/∂q_c∂q̇_c, R = ∂²L/∂q_c², exactly (no difference quotient).
* ``kind``: the second variation as a quadratic form on the span of η_1 … η_K (K sine shapes of the
  same coordinate), H_jl = ∫ (P η_j' η_l' + C (η_j η_l' + η_j' η_l) + R η_j η_l) dt; all its eigenvalues
  positive: a minimum, all negative: a maximum, otherwise a saddle (some direction lowers S).
* ``conjugate_time``: the Jacobi equation (the linearised Euler-Lagrange equations) for the n×n
  matrix J of Jacobi fields, J(0) = 0, J'(0) = 1, written with Π = P J' + Cᵀ J:
      J' = P⁻¹ (Π - Cᵀ J),   Π' = C J' + R J      (P, C, R now the full n×n matrices, C_ij = ∂²L/∂q_i∂q̇_j)
  integrated by RK4 with step 2h (its half-steps are grid times); t* is the first zero of det J after
  0: a sign change placed by bisection on the cubic Hermite interpolant of J between two steps, or a
  touch (a minimum of J's smallest singular value that reaches 0, several fields vanishing at once)
  confirmed by the second variation turning negative past it.
* ``varied_conjugate_time``: the same search for the variations of coordinate c alone (the other
  coordinates kept on the true path): the 1×1 Jacobi equation with P_cc, C_cc and R_cc.  Those variations
  are a subset of all, so their focus comes at t* or later, or never.
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from app.numerics import jit
from app.numerics.codegen import Block, BrowserPrinter, unpack
from app.numerics.errors import SimulationError
from app.numerics.generate import Names, observables_source
from app.numerics.simulate import simulate
from app.numerics.system import NumericSystem

K_SHAPES = 12  # sine shapes k = 1..K spanning the variations ``kind`` is judged on
SHAPES = ("sine",)  # the variation shapes offered
PATH_RTOL = 1e-11  # the true path's tolerances: its error enters S only through the end points
PATH_ATOL = 1e-13
GRID_STEPS = (1024, 4096)  # N: the grid has 4N + 1 samples; the finer one when the coarse one is not enough
TARGET = 1e-9  # relative quadrature error (of ∫|L| dt) below which the coarse grid is kept
SHOWN = 241  # samples of the true path and its L returned for a plot


@dataclass
class ActionTerms:
    """L, its gradient and its Hessian in (q, q̇), vectorised over samples; and L as browser JavaScript."""

    n: int
    function: Any  # (t, Q, V, k) -> [L, L_q (n), L_v (n), P (n²), C (n²), R (n²)]
    browser: str  # body of a JavaScript (t, y, k) returning L
    only_L: Any = None  # (t, Q, V, k) -> [L]: the varied paths need nothing else

    def evaluate(self, t: np.ndarray, Q: np.ndarray, V: np.ndarray, k: np.ndarray) -> list[np.ndarray]:
        with np.errstate(all="ignore"):
            return self.function(t, Q, V, k)

    def lagrangian(self, t: np.ndarray, Q: np.ndarray, V: np.ndarray, k: np.ndarray) -> np.ndarray:
        with np.errstate(all="ignore"):
            return (self.only_L or self.function)(t, Q, V, k)[0]

    def split(self, values: list[np.ndarray]) -> tuple[np.ndarray, ...]:
        n = self.n
        L = values[0]
        Lq = np.array(values[1 : 1 + n])
        Lv = np.array(values[1 + n : 1 + 2 * n])
        rest = 1 + 2 * n
        P, C, R = (np.array(values[rest + i * n * n : rest + (i + 1) * n * n]).reshape(n, n, -1) for i in range(3))
        return L, Lq, Lv, P, C, R


def terms_sources(system: NumericSystem) -> tuple[str, str, str]:
    """The Python source of the terms (``ActionTerms.function``), of L alone, and the JavaScript body of L."""
    d = system.derivation
    names = Names.of(d)
    table = d.table
    L = d.mechanics.L
    exprs: list[sp.Expr] = [L]
    exprs += [sp.diff(L, q) for q in table.q]
    exprs += [sp.diff(L, v) for v in table.qd]
    # P_ij = ∂²L/∂q̇_i∂q̇_j, C_ij = ∂²L/∂q_i∂q̇_j, R_ij = ∂²L/∂q_i∂q_j
    for first, second in ((table.qd, table.qd), (table.q, table.qd), (table.q, table.q)):
        exprs += [sp.diff(L, a, b) for a in first for b in second]
    python = observables_source(names, exprs)
    block = Block(javascript=True)
    n = len(names.q)
    block.raw(*(f"let {line};" for line in unpack("y", names.q)))
    block.raw(*(f"let {line};" for line in unpack("y", names.v, n)))
    block.raw(*(f"let {line};" for line in unpack("k", names.k)))
    block.assign(["_L"], [names(L)], BrowserPrinter(), "l_")
    block.raw("return _L;")
    return python, observables_source(names, [L]).replace("def observe(", "def lagrangian("), "\n".join(block.lines)


_TERMS: dict[str, ActionTerms] = {}
_TERMS_LOCK = threading.Lock()


def action_terms(system: NumericSystem) -> ActionTerms:
    """The system's generated terms, printed once per process (keyed by its generated source)."""
    with _TERMS_LOCK:
        found = _TERMS.get(system.key)
    if found is None:
        python, alone, browser = terms_sources(system)
        functions = jit.python_functions({"observe": python, "lagrangian": alone})
        found = ActionTerms(system.n, functions["observe"], browser, functions["lagrangian"])
        with _TERMS_LOCK:
            _TERMS[system.key] = found
    return found


@dataclass
class TruePath:
    t: np.ndarray  # 4N + 1 even samples on [0, T]
    y: np.ndarray  # (samples, 2n)
    method: str
    warnings: list[str] = field(default_factory=list)

    @property
    def h(self) -> float:
        return float(self.t[1] - self.t[0])


def true_path(
    system: NumericSystem, k: np.ndarray, y0: np.ndarray, t_end: float, steps: int, wait_for_compile: bool = True
) -> TruePath:
    outcome = simulate(
        system, k, y0, t_end, 4 * steps + 1, rtol=PATH_RTOL, atol=PATH_ATOL, estimate=False,
        wait_for_compile=wait_for_compile,
    )  # fmt: skip
    tr = outcome.trajectory
    if not tr.complete or tr.t.size != 4 * steps + 1 or not np.all(np.isfinite(tr.y)):
        raise SimulationError(
            f"the true path does not reach t = {t_end:g} s ({tr.stop_reason or 'it left the region where L is defined'}); "
            "choose a shorter t_end",
            "t_end",
        )
    return TruePath(tr.t, tr.y, outcome.method, list(outcome.warnings))


def simpson(values: np.ndarray, h: float) -> float:
    """Composite Simpson on an odd number of even samples: h/3 (f0 + 4 f1 + 2 f2 + … + 4 f_{m-1} + f_m)."""
    return float(h / 3 * (values[0] + values[-1] + 4 * values[1:-1:2].sum() + 2 * values[2:-1:2].sum()))


def integral(values: np.ndarray, h: float) -> tuple[float, float]:
    """∫ by Boole's rule (Richardson on Simpson with h and 2h), and |Simpson(h) - Simpson(2h)| / 15."""
    fine, coarse = simpson(values, h), simpson(values[::2], 2 * h)
    return fine + (fine - coarse) / 15, abs(fine - coarse) / 15


def shape(k: int, t: np.ndarray, T: float) -> tuple[np.ndarray, np.ndarray]:
    """η = sin(kπt/T) and η' = (kπ/T) cos(kπt/T)."""
    w = k * math.pi / T
    return np.sin(w * t), w * np.cos(w * t)


@dataclass
class ActionResult:
    epsilons: list[float]
    action: list[float | None]
    true: float
    first_variation: float
    second_variation: float
    kind: str
    conjugate_time: float | None
    varied_conjugate_time: float | None  # the focus of the varied coordinate alone (the others on the true path)
    error_estimate: float
    hessian_eigenvalues: list[float]
    path: TruePath
    L: np.ndarray
    warnings: list[str]


def _varied_L(terms: ActionTerms, path: TruePath, k: np.ndarray, c: int, eps: float, eta, deta) -> np.ndarray:
    n = terms.n
    Q = path.y[:, :n].T.copy()
    V = path.y[:, n:].T.copy()
    Q[c] += eps * eta
    V[c] += eps * deta
    return terms.lagrangian(path.t, Q, V, k)


def jacobi_determinant(t: np.ndarray, P: np.ndarray, C: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, list]:
    """det J at every other grid time, and (J, J') there, for J(0) = 0, J'(0) = 1 (RK4 with step 2h).

    The Jacobi equation is linear, z' = A(t) z for z = (J, Π), with
        A = [[-P⁻¹Cᵀ, P⁻¹], [R - C P⁻¹ Cᵀ, C P⁻¹]]
    so one RK4 step is a matrix Φ built from A at the step's start, middle and end; every Φ is built at
    once on the stacked samples, and only the products z_s+1 = Φ_s z_s run in order."""
    n = P.shape[0]
    Pt, Ct, Rt = (np.moveaxis(x, -1, 0) for x in (P, C, R))  # (samples, n, n)
    Pinv = np.linalg.inv(Pt)
    CT = np.swapaxes(Ct, 1, 2)
    A = np.empty((t.size, 2 * n, 2 * n))
    A[:, :n, :n] = -Pinv @ CT
    A[:, :n, n:] = Pinv
    A[:, n:, :n] = Rt - Ct @ Pinv @ CT
    A[:, n:, n:] = Ct @ Pinv
    H = 2 * (t[1] - t[0])
    identity = np.eye(2 * n)
    # RK4 on z' = A z: k1 = A_a z, k2 = A_m (z + H/2 k1), k3 = A_m (z + H/2 k2), k4 = A_b (z + H k3)
    k1 = A[0:-1:2]
    k2 = A[1::2] @ (identity + H / 2 * k1)
    k3 = A[1::2] @ (identity + H / 2 * k2)
    k4 = A[2::2] @ (identity + H * k3)
    step = identity + H / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    z = np.zeros((2 * n, n))
    z[n:] = Pt[0]  # J(0) = 0, J'(0) = 1: Π(0) = P(0)
    Z = [z]
    for s in range(step.shape[0]):
        z = step[s] @ z
        Z.append(z)
    stacked = np.array(Z)
    J = stacked[:, :n]
    dJ = (A[::2] @ stacked)[:, :n]
    return np.linalg.det(J), list(zip(J, dJ, strict=True))


def _zero_between(J0: np.ndarray, D0: np.ndarray, J1: np.ndarray, D1: np.ndarray, H: float) -> float:
    """Where in [0, 1] det J changes sign, J the cubic Hermite interpolant of (J, J') at a step's two ends."""

    def det_at(x: float) -> float:
        return float(np.linalg.det(_hermite(J0, D0, J1, D1, H, x)))

    low, high = 0.0, 1.0
    for _ in range(60):
        mid = (low + high) / 2
        if det_at(mid) > 0:
            low = mid
        else:
            high = mid
    return (low + high) / 2


FOCUS_DIP = 1e-5  # σ_min(J) below this fraction of the fields' size so far: a candidate zero where det J only touches 0
FOCUS_NEAR = 0.1  # a sampled minimum of σ_min(J) below this fraction is located between the samples first
FOCUS_MARGIN = 0.05  # the second variation is compared on [0, t*(1 - m)] and [0, t*(1 + m)]


def _hermite(J0: np.ndarray, D0: np.ndarray, J1: np.ndarray, D1: np.ndarray, H: float, x: float) -> np.ndarray:
    """J at the fraction x of a step, the cubic Hermite interpolant of (J, J') at the step's two ends."""
    h00, h10, h01, h11 = 2 * x**3 - 3 * x**2 + 1, x**3 - 2 * x**2 + x, -2 * x**3 + 3 * x**2, x**3 - x**2
    return h00 * J0 + h10 * H * D0 + h01 * J1 + h11 * H * D1


def _smallest_at(fields: list, H: float, s: int) -> float:
    """Where σ_min(J) is least between steps s - 1 and s + 1 (golden section on the Hermite interpolant), in steps."""

    def smallest(u: float) -> float:
        first = min(max(int(math.floor(u)), 0), len(fields) - 2)
        (J0, D0), (J1, D1) = fields[first], fields[first + 1]
        return float(np.linalg.svd(_hermite(J0, D0, J1, D1, H, u - first), compute_uv=False)[-1])

    golden = (math.sqrt(5) - 1) / 2
    low, high = float(s - 1), float(min(s + 1, len(fields) - 1))
    a, b = high - golden * (high - low), low + golden * (high - low)
    fa, fb = smallest(a), smallest(b)
    for _ in range(80):
        if fa <= fb:
            high, b, fb = b, a, fa
            a = high - golden * (high - low)
            fa = smallest(a)
        else:
            low, a, fa = a, b, fb
            b = low + golden * (high - low)
            fb = smallest(b)
    return (low + high) / 2


def second_variation_form(t: np.ndarray, P: np.ndarray, C: np.ndarray, R: np.ndarray, end: int) -> np.ndarray:
    """The second variation on [0, t_end] over every coordinate and the sine shapes k = 1 … K (Simpson, end even).

    For η = Σ a_ki sin(kπt/T) e_i, δ²S = ∫ (η'ᵀ P η' + 2 ηᵀ C η' + ηᵀ R η) dt, whose symmetric matrix has entries
        ∫ (η_a' η_b' P_ij + η_a η_b' C_ij + η_a' η_b C_ji + η_a η_b R_ij) dt."""
    tt = t[: end + 1]
    h = float(t[1] - t[0])
    weights = np.full(tt.size, 2.0)
    weights[1:-1:2] = 4.0
    weights[0] = weights[-1] = 1.0
    weights *= h / 3  # composite Simpson
    sines, slopes = zip(*(shape(k, tt, float(tt[-1])) for k in range(1, K_SHAPES + 1)), strict=True)
    S, D = np.array(sines) * weights, np.array(slopes)
    Pw, Cw, Rw = (x[:, :, : end + 1] for x in (P, C, R))
    form = np.einsum("am,bm,ijm->aibj", D * weights, D, Pw)
    form += np.einsum("am,bm,ijm->aibj", S, D, Cw)
    form += np.einsum("am,bm,jim->aibj", D * weights, np.array(sines), Cw)
    form += np.einsum("am,bm,ijm->aibj", S, np.array(sines), Rw)
    size = K_SHAPES * P.shape[0]
    return form.reshape(size, size)


def _focus_confirmed(t: np.ndarray, P: np.ndarray, C: np.ndarray, R: np.ndarray, t_star: float) -> bool:
    """A touching zero of det J is a focus when the second variation, positive on [0, t* - δ], has a negative
    direction on [0, t* + δ] (δ = 5 % of t*): the Jacobi field that vanishes at t* can then be lowered."""
    h = float(t[1] - t[0])
    before = 2 * math.floor(t_star * (1 - FOCUS_MARGIN) / h / 2)
    after = 2 * math.ceil(t_star * (1 + FOCUS_MARGIN) / h / 2)
    if before < 8 or after > t.size - 1:
        return False
    low, high = (np.linalg.eigvalsh(second_variation_form(t, P, C, R, end)) for end in (before, after))
    tol = 1e-9 * max(np.abs(low).max(), np.abs(high).max())
    return bool(low.min() > tol and high.min() < -tol)


def conjugate_time(t: np.ndarray, P: np.ndarray, C: np.ndarray, R: np.ndarray) -> float | None:
    """The first t* > 0 where det J = 0 (the first kinetic focus), or None before the grid's end.

    A zero is either a sign change of det J, or a touch: a local minimum of the smallest singular value of J
    below FOCUS_DIP of the fields' largest size so far (every field of a charge in a uniform magnetic field
    returns to 0 together, and det J = 2(1 - cos ω_c t)/ω_c² ≥ 0), kept when the second variation confirms it."""
    dets, fields = jacobi_determinant(t, P, C, R)
    H = 2 * (t[1] - t[0])
    Js = np.array([J for J, _ in fields])
    values = np.linalg.svd(Js, compute_uv=False)  # (steps, n), largest first
    size = np.maximum.accumulate(values[:, 0])
    smallest = values[:, -1]
    # det J ~ t^n > 0 just after 0: the first step at which it is no longer positive, or a dip to 0 before it
    for s in range(2, dets.size):
        if dets[s] <= 0:
            (J0, D0), (J1, D1) = fields[s - 1], fields[s]
            return float((s - 1 + _zero_between(J0, D0, J1, D1, H)) * H)
        last = s + 1 >= dets.size
        if (
            smallest[s] <= smallest[s - 1]
            and (last or smallest[s] <= smallest[s + 1])
            and (smallest[s] < FOCUS_NEAR * size[s])
        ):
            at = _smallest_at(fields, H, s)
            first = min(int(at), len(fields) - 2)
            (J0, D0), (J1, D1) = fields[first], fields[first + 1]
            least = np.linalg.svd(_hermite(J0, D0, J1, D1, H, at - first), compute_uv=False)[-1]
            if least < FOCUS_DIP * size[s] and _focus_confirmed(t, P, C, R, at * H):
                return float(at * H)
    return None


def classify(eigenvalues: np.ndarray, scale: float) -> str:
    """minimum: every direction raises S; maximum: every one lowers it; saddle: some lower it."""
    tol = 1e-9 * scale
    if eigenvalues.min() >= -tol:
        return "minimum"
    return "maximum" if eigenvalues.max() < -tol else "saddle"


def action_of(
    system: NumericSystem,
    k: np.ndarray,
    y0: np.ndarray,
    t_end: float,
    coordinate: int,
    shape_k: int,
    epsilons: list[float],
    wait_for_compile: bool = True,
) -> ActionResult:
    """S(ε) for the varied paths, the first and second variations at ε = 0, the kind and the conjugate time."""
    terms = action_terms(system)
    warnings: list[str] = []
    for steps in GRID_STEPS:
        path = true_path(system, k, y0, t_end, steps, wait_for_compile)
        n = system.n
        values = terms.evaluate(path.t, path.y[:, :n].T, path.y[:, n:].T, k)
        L, Lq, Lv, P, C, R = terms.split(values)
        if not np.all(np.isfinite(L)):
            raise SimulationError(
                "L cannot be evaluated along the true path (a singular point of the coordinates)", "initial"
            )
        h = path.h
        size, _ = integral(np.abs(L), h)
        true, quad_error = integral(L, h)
        if quad_error <= TARGET * max(size, 1e-300) or steps == GRID_STEPS[-1]:
            break
    error = quad_error + 10 * PATH_RTOL * size
    warnings += path.warnings
    if any(Q != 0 for Q in system.derivation.mechanics.Q):
        warnings.append(
            "this system has generalized forces Q not derived from a potential: its true path makes "
            "S + ∫ Q·δq dt stationary, not S alone, so dS/dε at 0 is not zero"
        )
    c = coordinate
    eta, deta = shape(shape_k, path.t, t_end)
    action: list[float | None] = []
    for eps in epsilons:
        if eps == 0:
            action.append(true)
            continue
        S, e = integral(_varied_L(terms, path, k, c, eps, eta, deta), h)
        error = max(error, e + 10 * PATH_RTOL * size)
        action.append(S if math.isfinite(S) else None)
    if any(S is None for S in action):
        warnings.append("some varied paths leave the region where L is defined; their S is null")
    first, _ = integral(Lq[c] * eta + Lv[c] * deta, h)
    Pc, Cc, Rc = P[c, c], C[c, c], R[c, c]
    second, _ = integral(Pc * deta**2 + 2 * Cc * eta * deta + Rc * eta**2, h)
    # the K×K form of the second variation on the span of η_1 … η_K
    shapes = [shape(j, path.t, t_end) for j in range(1, K_SHAPES + 1)]
    form = np.empty((K_SHAPES, K_SHAPES))
    for a, (ea, da) in enumerate(shapes):
        for b in range(a, K_SHAPES):
            eb, db = shapes[b]
            form[a, b] = form[b, a] = integral(Pc * da * db + Cc * (ea * db + da * eb) + Rc * ea * eb, h)[0]
    eigenvalues = np.linalg.eigvalsh(form)
    scale = float(np.abs(form).max()) or 1.0
    t_star = conjugate_time(path.t, P, C, R)
    # the variations of coordinate c alone: the Jacobi equation of the c-c blocks (with one coordinate, t* itself)
    alone = slice(c, c + 1)
    t_alone = t_star if n == 1 else conjugate_time(path.t, P[alone, alone], C[alone, alone], R[alone, alone])
    return ActionResult(
        epsilons=list(epsilons),
        action=action,
        true=true,
        first_variation=first,
        second_variation=second,
        kind=classify(eigenvalues, scale),
        conjugate_time=t_star,
        varied_conjugate_time=t_alone,
        error_estimate=error,
        hessian_eigenvalues=eigenvalues.tolist(),
        path=path,
        L=L,
        warnings=warnings,
    )
