"""Exact solutions, for checking errors: the pendulum (Jacobi elliptic functions), constant acceleration,
and linear systems with constant coefficients (their normal modes, through the matrix exponential).

Which solution applies is found by probing the generated right-hand side, not
by trusting a scene's name: a one-coordinate system whose acceleration is
-w0^2 sin(q) for some constant w0^2 > 0 (checked at many random states and
times) is a pendulum; a system whose accelerations are the same everywhere
moves with constant acceleration.

Pendulum, with k^2 = sin^2(q0/2) + q_dot0^2 / (4 w0^2) (the energy level):

* libration (k < 1): sin(q/2) = k sn(u, m), cos(q/2) = dn(u, m), q_dot = 2 k w0 cn(u, m),
  u = w0 t + u0, m = k^2, so q = 2 atan2(k sn, dn) (accurate up to the top);
* rotation (k > 1): q/2 = am(w, m'), q_dot = 2 k w0 dn(w, m') (signed), w = k w0 t + w0',
  m' = 1 / k^2.

Linear with constant coefficients (coupled oscillators, two masses on a spring): the state y = (q, q̇)
obeys ẏ = A y + c with A and c constant, probed the same way (the right-hand side is affine in y at
every probed time).  With z = (y, 1), ż = B z and B = [[A, c], [0, 0]], so z(t) = exp(B t) z(0): the
superposition of the normal modes e^{st} (s = ±iω for each oscillation, and a drift t for a zero ω),
including the free drift, whose Jordan block has no basis of modes of its own.

``scipy.special.ellipj`` loses all accuracy when m is within ~1e-12 of 1 (near
the separatrix), so everything is evaluated in mpmath at 40 digits, with
1 - m computed from the float inputs in that precision.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import mpmath
import numpy as np

from app import late
from app.numerics.system import NumericSystem

Solution = Callable[[np.ndarray], np.ndarray]  # t -> array of shape (len(t), 2n): (q, q_dot)
DIGITS = 40


def pendulum(w0_squared: float, q0: float, v0: float) -> Solution:
    """The exact pendulum motion q'' = -w0^2 sin q from (q0, v0) at t = 0."""
    with mpmath.workdps(DIGITS):
        w0 = mpmath.sqrt(mpmath.mpf(w0_squared))
        turns = mpmath.floor((mpmath.mpf(q0) + mpmath.pi) / (2 * mpmath.pi))
        qr = mpmath.mpf(q0) - 2 * mpmath.pi * turns  # in [-pi, pi)
        vv = mpmath.mpf(v0)
        k2 = mpmath.sin(qr / 2) ** 2 + vv**2 / (4 * w0**2)
    if k2 < 1:
        return _libration(w0, qr, vv, k2, turns)
    return _rotation(w0, qr, vv, k2, turns)


def _libration(w0, qr, vv, k2, turns) -> Solution:
    with mpmath.workdps(DIGITS):
        k = mpmath.sqrt(k2)
        m = k2
        # sn(u0) = sin(q0/2)/k, cn(u0) = q_dot0 / (2 k w0)
        s0 = mpmath.sin(qr / 2) / k
        s0 = max(min(s0, mpmath.mpf(1)), mpmath.mpf(-1))
        u0 = mpmath.ellipf(mpmath.asin(s0), m)
        if vv < 0:
            u0 = 2 * mpmath.ellipk(m) - u0

    def solution(t: np.ndarray) -> np.ndarray:
        out = np.empty((len(t), 2))
        with mpmath.workdps(DIGITS):
            for i, ti in enumerate(t):
                u = w0 * mpmath.mpf(float(ti)) + u0
                sn, cn, dn = (mpmath.ellipfun(kind, u, m=m) for kind in ("sn", "cn", "dn"))
                out[i, 0] = float(2 * mpmath.atan2(k * sn, dn) + 2 * mpmath.pi * turns)
                out[i, 1] = float(2 * k * w0 * cn)
        return out

    return solution


def _rotation(w0, qr, vv, k2, turns) -> Solution:
    with mpmath.workdps(DIGITS):
        k = mpmath.sqrt(k2)
        mp_ = 1 / k2
        sign = 1 if vv >= 0 else -1
        K = mpmath.ellipk(mp_)
        # am(w0') = q0/2, and am(w + 2K) = am(w) + pi
        w_start = mpmath.ellipf(qr / 2, mp_)

    def solution(t: np.ndarray) -> np.ndarray:
        out = np.empty((len(t), 2))
        with mpmath.workdps(DIGITS):
            for i, ti in enumerate(t):
                w = w_start + sign * k * w0 * mpmath.mpf(float(ti))
                half_turns = mpmath.floor((w + K) / (2 * K))
                r = w - 2 * K * half_turns
                sn, cn, dn = (mpmath.ellipfun(kind, r, m=mp_) for kind in ("sn", "cn", "dn"))
                am = mpmath.atan2(sn, cn) + mpmath.pi * half_turns
                out[i, 0] = float(2 * am + 2 * mpmath.pi * turns)
                out[i, 1] = float(sign * 2 * k * w0 * dn)
        return out

    return solution


def constant_acceleration(a: np.ndarray, y0: np.ndarray) -> Solution:
    """q = q0 + v0 t + a t^2 / 2 for accelerations that are the same everywhere."""
    n = a.size
    q0, v0 = y0[:n], y0[n:]

    def solution(t: np.ndarray) -> np.ndarray:
        tt = np.asarray(t, dtype=float)[:, None]
        return np.hstack([q0 + v0 * tt + 0.5 * a * tt**2, v0 + a * tt])

    return solution


def _probe_states(system: NumericSystem, count: int = 12) -> list[tuple[float, np.ndarray]]:
    rng = np.random.default_rng(20261122)
    m = 2 * system.n
    return [(float(rng.uniform(0, 5)), rng.uniform(-2.5, 2.5, m)) for _ in range(count)]


def pendulum_frequency(system: NumericSystem, k: np.ndarray) -> float | None:
    """w0^2 when the system's acceleration is -w0^2 sin(q), w0^2 > 0 constant; else None."""
    if system.n != 1:
        return None
    ratios = []
    for t, y in _probe_states(system):
        if abs(math.sin(y[0])) < 0.1:
            continue
        try:
            a = system.f(t, y, k)[1]
        except (ArithmeticError, ValueError):
            return None
        ratios.append(-a / math.sin(y[0]))
    if not ratios or min(ratios) <= 0:
        return None
    w2 = float(np.median(ratios))
    return w2 if max(abs(r - w2) for r in ratios) <= 1e-12 * w2 else None


def constant_accelerations(system: NumericSystem, k: np.ndarray) -> np.ndarray | None:
    """The accelerations when they are the same at every state and time; else None."""
    values = []
    for t, y in _probe_states(system):
        try:
            values.append(system.f(t, y, k)[system.n :])
        except (ArithmeticError, ValueError):
            return None
    a = values[0]
    scale = max(float(np.max(np.abs(a))), 1e-300)
    return a if all(np.max(np.abs(v - a)) <= 1e-13 * scale for v in values) else None


def linear_motion(B: np.ndarray, y0: np.ndarray) -> Solution:
    """y(t) from ż = B z, z = (y, 1): z(t) = exp(B t) z(0), for each t (scaling and squaring)."""
    z0 = np.append(y0, 1.0)
    expm = late.module("scipy.linalg").expm  # imported with the first linear run, not with the app

    def solution(t: np.ndarray) -> np.ndarray:
        return np.array([(expm(B * float(ti)) @ z0)[:-1] for ti in np.asarray(t, dtype=float)])

    return solution


def linear_coefficients(system: NumericSystem, k: np.ndarray) -> np.ndarray | None:
    """B = [[A, c], [0, 0]] when ẏ = A y + c with A, c constant (checked at the probe states); else None."""
    m = 2 * system.n
    try:
        c = np.asarray(system.f(0.0, np.zeros(m), k), dtype=float)
        # an affine f: each column of A is f(e_j) − f(0) exactly (up to rounding), for any step
        A = np.column_stack([np.asarray(system.f(0.0, np.eye(m)[j], k), dtype=float) - c for j in range(m)])
        probes = [(t, y, np.asarray(system.f(t, y, k), dtype=float)) for t, y in _probe_states(system)]
    except (ArithmeticError, ValueError):
        return None
    if not (np.all(np.isfinite(A)) and np.all(np.isfinite(c))):
        return None
    for _, y, f in probes:
        scale = max(float(np.max(np.abs(f))), float(np.max(np.abs(A) @ np.abs(y))), float(np.max(np.abs(c))), 1e-300)
        if np.max(np.abs(f - (A @ y + c))) > 1e-11 * scale:
            return None
    B = np.zeros((m + 1, m + 1))
    B[:m, :m], B[:m, m] = A, c
    return B


def exact_solution(system: NumericSystem, k: np.ndarray, y0: np.ndarray) -> tuple[Solution, str] | None:
    """An exact solution for this system and start, with a sentence saying which; None when none is known."""
    w2 = pendulum_frequency(system, k)
    if w2 is not None:
        return pendulum(w2, float(y0[0]), float(y0[1])), (
            f"exact pendulum solution (Jacobi elliptic functions in mpmath at {DIGITS} digits), ω0² = {w2:.6g}/s²"
        )
    a = constant_accelerations(system, k)
    if a is not None:
        return constant_acceleration(a, y0), "exact constant-acceleration motion q = q0 + q̇0 t + a t²/2"
    B = linear_coefficients(system, k)
    if B is not None:
        return linear_motion(B, np.asarray(y0, dtype=float)), (
            "exact solution of the linear equations (constant coefficients): the superposition of the normal "
            "modes, y(t) = exp(Bt) y(0)"
        )
    return None
