"""Verner's 8(7) pair with its 7th-order continuous extension, as a compiled loop.

Tableau: app.numerics.kernels.vern8_tableau.  Per accepted step from t to t + h:

    K_s = f(t + c_s h, y + h sum_{j<s} a_sj K_j),   s = 1..12   (K_0 = f(t, y), kept from the last step)
    y_new = y + h sum_j b_j K_j                                 (8th order)
    err = h || sum_j (b_j - bhat_j) K_j / (atol + rtol max(|y|, |y_new|)) ||_rms
    h_next = h min(10, max(0.2, 0.9 err^(-1/8)))               (after a rejection: at most h)

K_13 = f(t + h, y_new) is the next step's K_0, so an accepted step costs 13
evaluations.  Only a step with a sample inside it evaluates the three stages of
the continuous extension.  Each stage sums only the tableau's nonzero entries.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types

from app.numerics.kernels import vern8_tableau as tab
from app.numerics.kernels.common import (
    BOUND,
    DONE,
    F64,
    I64,
    JIT,
    MAT,
    NONFINITE,
    RHS,
    RUNNING,
    STEP_TOO_SMALL,
    STIFF,
    VEC,
    initial_step,
    outside,
)


def _sparse(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per row, the columns of its nonzero entries, their values and how many there are."""
    count = np.array([np.count_nonzero(r) for r in rows], dtype=np.int64)
    width = max(1, int(count.max()))
    cols = np.zeros((rows.shape[0], width), dtype=np.int64)
    vals = np.zeros((rows.shape[0], width))
    for i, r in enumerate(rows):
        nz = np.flatnonzero(r)
        cols[i, : nz.size] = nz
        vals[i, : nz.size] = r[nz]
    return cols, vals, count


A_COLS, A_VALS, A_COUNT = _sparse(tab.A)
(B_COLS,), (B_VALS,), (B_COUNT,) = _sparse(tab.B[None, :])
(E_COLS,), (E_VALS,), (E_COUNT,) = _sparse(tab.E[None, :])
C = np.ascontiguousarray(tab.C)
NODES = np.ascontiguousarray(tab.NODES)
NODE_VALUES = np.ascontiguousarray(tab.NODE_VALUES)
N_STEP, N_ALL, DEGREE = tab.N_STEP, tab.N_ALL, tab.DEGREE
ERROR_EXPONENT = -1.0 / 8.0  # -1 / (embedded order 7 + 1)
SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0

# Stiffness test (Hairer's, as in DOP853): stage 12 and K_13 are both at t + h, so
# rho = |K_13 - K_12| / |y_new - Y_12| estimates the local Lipschitz constant, and h rho held near the
# stability boundary of the method on the negative real axis (|R(-x)| = 1 at x = 5.864 for this pair,
# from R(z) = 1 + z b^T (I - z A)^-1 1, checked by the tests) for STIFF_STEPS steps in a row means the step
# size is limited by stability, not accuracy.  The same 0.955 of the boundary as DOP853's 6.1 of 6.39.
STIFF_LIMIT = 5.6
STIFF_STEPS, CALM_STEPS = 15.0, 6.0

# Slots of the state vector ``st`` carried between calls.
T, H, STEPS, REJECTED, NFEV, NEXT_OUT, STARTED, STIFF_RUN, CALM_RUN, STIFF_SEEN = range(10)
STATE_SIZE = 10


@njit(types.void(F64, VEC), **JIT)
def interpolant_weights(theta, out):
    """out_j = b_j(theta), the interpolant's weights, from their values at the nodes theta_m.

    b_j is the polynomial of degree 8 with b_j(0) = 0 through b_j(theta_m), m = 1..8 (Lagrange's form):
        b_j(theta) = sum_m l_m(theta) b_j(theta_m),   l_m(theta) = (theta / theta_m) prod_{r != m} (theta - theta_r) / (theta_m - theta_r)
    The l_m stay below 2 on [0, 1] and the node values below 60, so no large terms cancel."""
    for j in range(N_ALL):
        out[j] = 0.0
    for m in range(DEGREE):
        ell = theta / NODES[m]
        for r in range(DEGREE):
            if r != m:
                ell *= (theta - NODES[r]) / (NODES[m] - NODES[r])
        for j in range(N_ALL):
            out[j] += ell * NODE_VALUES[m, j]


@njit(inline="always")
def _stage(f, K, y, h, t, k, s, ys):
    # K_s = f(t + c_s h, y + h sum_j a_sj K_j), over the nonzero a_sj
    n = y.size
    for i in range(n):
        acc = 0.0
        for m in range(A_COUNT[s]):
            acc += A_VALS[s, m] * K[A_COLS[s, m], i]
        ys[i] = y[i] + h * acc
    f(t + C[s] * h, ys, k, K[s])


@njit(I64(RHS, VEC, VEC, F64, VEC, VEC, I64, I64, VEC, VEC, VEC, MAT), **JIT)
def run(f, k, t_out, rtol, atol, bound, stop_on_stiff, chunk, y, fy, st, Y):
    """Advance at most ``chunk`` steps; fill Y[i] = y(t_out[i]) as the samples are passed."""
    n = y.size
    n_out = t_out.size
    t_end = t_out[n_out - 1]
    K = np.zeros((N_ALL, n))
    y_new = np.empty(n)
    ys = np.empty(n)
    weights = np.empty(N_ALL)
    if st[STARTED] == 0.0:
        st[T] = t_out[0]
        f(st[T], y, k, fy)
        st[H] = initial_step(f, st[T], y, fy, k, t_end, rtol, atol, 8.0)
        st[NFEV] += 2
        st[STARTED] = 1.0
    t = st[T]
    h_abs = st[H]
    j_out = int(st[NEXT_OUT])
    while j_out < n_out and t_out[j_out] <= t:
        Y[j_out, :] = y
        j_out += 1
    done_here = 0
    status = RUNNING
    while True:
        if j_out >= n_out or t >= t_end:
            status = DONE
            break
        if done_here >= chunk:
            break
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        rejected = False
        while True:
            if h_abs < min_step:
                status = STEP_TOO_SMALL
                break
            t_new = t + h_abs
            if t_new > t_end:
                t_new = t_end
            h = t_new - t
            K[0, :] = fy
            for s in range(1, N_STEP):
                _stage(f, K, y, h, t, k, s, ys)
            st[NFEV] += N_STEP - 1
            err = 0.0
            for i in range(n):
                acc = 0.0
                for m in range(B_COUNT):
                    acc += B_VALS[m] * K[B_COLS[m], i]
                y_new[i] = y[i] + h * acc
                e = 0.0
                for m in range(E_COUNT):
                    e += E_VALS[m] * K[E_COLS[m], i]
                scale = atol[i] + max(abs(y[i]), abs(y_new[i])) * rtol
                err += (e / scale) ** 2
            err = h * np.sqrt(err / n)
            if not np.isfinite(err):
                h_abs *= MIN_FACTOR
                rejected = True
                st[REJECTED] += 1
                continue
            if err < 1.0:
                factor = MAX_FACTOR if err == 0.0 else min(MAX_FACTOR, SAFETY * err**ERROR_EXPONENT)
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                break
            h_abs *= max(MIN_FACTOR, SAFETY * err**ERROR_EXPONENT)
            rejected = True
            st[REJECTED] += 1
        if status == STEP_TOO_SMALL:
            break
        # K_13 = f(t + h, y_new): the continuous extension's last node and the next step's K_0
        f(t_new, y_new, k, K[N_STEP])
        st[NFEV] += 1
        # ys still holds stage 12's state (c = 1): the stiffness test above
        num = 0.0
        den = 0.0
        for i in range(n):
            num += (K[N_STEP, i] - K[N_STEP - 1, i]) ** 2
            den += (y_new[i] - ys[i]) ** 2
        if den > 0.0 and h * np.sqrt(num / den) > STIFF_LIMIT:
            st[CALM_RUN] = 0.0
            st[STIFF_RUN] += 1.0
            if st[STIFF_RUN] >= STIFF_STEPS:
                st[STIFF_SEEN] = 1.0
        else:
            st[CALM_RUN] += 1.0
            if st[CALM_RUN] >= CALM_STEPS:
                st[STIFF_RUN] = 0.0
        if j_out < n_out and t_out[j_out] < t_new:
            for s in range(N_STEP + 1, N_ALL):
                _stage(f, K, y, h, t, k, s, ys)
            st[NFEV] += N_ALL - N_STEP - 1
            while j_out < n_out and t_out[j_out] < t_new:
                interpolant_weights((t_out[j_out] - t) / h, weights)
                for i in range(n):
                    acc = 0.0
                    for j in range(N_ALL):
                        acc += weights[j] * K[j, i]
                    Y[j_out, i] = y[i] + h * acc
                j_out += 1
        while j_out < n_out and t_out[j_out] <= t_new:
            Y[j_out, :] = y_new
            j_out += 1
        y[:] = y_new
        fy[:] = K[N_STEP]
        t = t_new
        st[STEPS] += 1
        done_here += 1
        finite = True
        for i in range(n):
            if not np.isfinite(y[i]):
                finite = False
        if not finite:
            status = NONFINITE
            break
        if outside(y, bound):
            status = BOUND
            break
        if stop_on_stiff != 0 and st[STIFF_SEEN] != 0.0:
            status = STIFF
            break
    st[T] = t
    st[H] = h_abs
    st[NEXT_OUT] = j_out
    return status
