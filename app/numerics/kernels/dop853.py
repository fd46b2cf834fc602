"""Dormand-Prince 8(5,3) with 7th-order dense output, as a compiled loop.

The tableau, error weights and dense-output coefficients are scipy's (from Hairer's DOP853),
held in ``dop853_tableau`` so that no private scipy module is imported, and the
step-size rules follow scipy's ``DOP853`` so results agree with it; the loop
itself runs in machine code.  Per accepted step from t to t + h:

    K_s = f(t + c_s h, y + h sum_{j<s} a_sj K_j),   s = 0..11
    y_new = y + h sum_j b_j K_j
    err = h |E5.K| / sqrt(|E5.K|^2 + 0.01 |E3.K|^2)     (norms scaled by atol + rtol |y|)
    h_next = h min(10, 0.9 err^(-1/8))                 (rejected: h max(0.2, 0.9 err^(-1/8)))

Stiffness is detected as in Hairer's code: h * |f(y_new) - f(y_12)| / |y_new - y_12|
above 6.1 (the edge of the stability region) on 15 accepted steps in a row.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types

from app.numerics.kernels import dop853_tableau as tab
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
    address,
    initial_step,
    outside,
    rhs_at,
)

A = np.ascontiguousarray(tab.A, dtype=np.float64)
B = np.ascontiguousarray(tab.B, dtype=np.float64)
C = np.ascontiguousarray(tab.C, dtype=np.float64)
E3 = np.ascontiguousarray(tab.E3, dtype=np.float64)
E5 = np.ascontiguousarray(tab.E5, dtype=np.float64)
D = np.ascontiguousarray(tab.D, dtype=np.float64)
N_STAGES = tab.N_STAGES  # 12
N_EXTENDED = tab.N_EXTENDED  # 16
SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0

# Slots of the state vector ``st`` carried between calls.
T, H, STEPS, REJECTED, NFEV, NEXT_OUT, STIFF_RUN, CALM_RUN, STIFF_SEEN, STARTED = range(10)
STATE_SIZE = 10


@njit(types.void(MAT, VEC, F64, types.intp, VEC), **JIT)
def _stage_state(K, y, h, s, out):
    # out = y + h sum_{j<s} a_sj K_j
    for i in range(y.size):
        acc = 0.0
        for j in range(s):
            acc += A[s, j] * K[j, i]
        out[i] = y[i] + h * acc


@njit(
    I64(RHS, VEC, VEC, F64, VEC, VEC, I64, I64, VEC, VEC, VEC, MAT),
    **JIT,
)
def run(f, k, t_out, rtol, atol, bound, stop_on_stiff, chunk, y, fy, st, Y):
    """Advance at most ``chunk`` steps; fill Y[i] = y(t_out[i]) as the samples are passed."""
    n = y.size
    n_out = t_out.size
    t_end = t_out[n_out - 1]
    K = np.zeros((N_EXTENDED, n))
    y_new = np.empty(n)
    ys = np.empty(n)
    y12 = np.empty(n)
    scale = np.empty(n)
    F = np.empty((7, n))
    if st[STARTED] == 0.0:
        st[T] = t_out[0]
        f(st[T], address(y), address(k), address(fy))
        st[H] = initial_step(f, st[T], y, fy, k, t_end, rtol, atol, 7.0)
        st[NFEV] += 2
        st[STARTED] = 1.0
    t = st[T]
    h_abs = st[H]
    j_out = int(st[NEXT_OUT])
    while j_out < n_out and t_out[j_out] <= t:
        Y[j_out, :] = y
        j_out += 1
    st[NEXT_OUT] = j_out
    done_here = 0
    while True:
        if j_out >= n_out or t >= t_end:
            return DONE
        if done_here >= chunk:
            return RUNNING
        # the smallest step: ten units in the last place of t, 10 eps |t| (a step of 0 at t = 0 fails too).  As
        # err^(-1/8) below as three square roots: with no call to nextafter or pow left in it, LLVM keeps
        # the step loop tight (measured: 1.88 against 2.45-2.6 ms for the pendulum of bench_cyrk; adding 1e-300
        # to this bound cost as much again, for reasons in the compiler: measure before changing these lines)
        smallest = 2.220446049250313e-15 * abs(t)
        rejected = False
        while True:
            if h_abs <= smallest:
                return STEP_TOO_SMALL
            t_new = t + h_abs
            if t_new > t_end:
                t_new = t_end
            h = t_new - t
            # the twelve stages
            K[0, :] = fy
            for s in range(1, N_STAGES):
                _stage_state(K, y, h, s, ys)
                if s == N_STAGES - 1:
                    y12[:] = ys
                f(t + C[s] * h, address(ys), address(k), address(K[s]))
            for i in range(n):
                acc = 0.0
                for j in range(N_STAGES):
                    acc += B[j] * K[j, i]
                y_new[i] = y[i] + h * acc
            f(t_new, address(y_new), address(k), address(K[N_STAGES]))
            st[NFEV] += N_STAGES
            # error norm: combined 5th- and 3rd-order estimates
            for i in range(n):
                scale[i] = atol[i] + max(abs(y[i]), abs(y_new[i])) * rtol
            e5 = 0.0
            e3 = 0.0
            for i in range(n):
                a5 = 0.0
                a3 = 0.0
                for j in range(N_STAGES + 1):
                    a5 += E5[j] * K[j, i]
                    a3 += E3[j] * K[j, i]
                e5 += (a5 / scale[i]) ** 2
                e3 += (a3 / scale[i]) ** 2
            if e5 == 0.0 and e3 == 0.0:
                err = 0.0
            else:
                err = h * e5 / np.sqrt((e5 + 0.01 * e3) * n)
            if not np.isfinite(err):
                h_abs *= MIN_FACTOR
                rejected = True
                st[REJECTED] += 1
                continue
            if err < 1.0:
                if err == 0.0:
                    factor = MAX_FACTOR
                else:
                    factor = min(MAX_FACTOR, SAFETY / np.sqrt(np.sqrt(np.sqrt(err))))
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                break
            h_abs *= max(MIN_FACTOR, SAFETY / np.sqrt(np.sqrt(np.sqrt(err))))
            rejected = True
            st[REJECTED] += 1
        # samples inside (t, t_new]: DOP853's 7th-order continuous extension
        if j_out < n_out and t_out[j_out] < t_new:
            for s in range(N_STAGES + 1, N_EXTENDED):
                _stage_state(K, y, h, s, ys)
                f(t + C[s] * h, address(ys), address(k), address(K[s]))
            st[NFEV] += N_EXTENDED - N_STAGES - 1
            for i in range(n):
                dy = y_new[i] - y[i]
                F[0, i] = dy
                F[1, i] = h * K[0, i] - dy
                F[2, i] = 2.0 * dy - h * (K[N_STAGES, i] + K[0, i])
                for r in range(4):
                    acc = 0.0
                    for j in range(N_EXTENDED):
                        acc += D[r, j] * K[j, i]
                    F[3 + r, i] = h * acc
            while j_out < n_out and t_out[j_out] < t_new:
                x = (t_out[j_out] - t) / h
                for i in range(n):
                    # Horner-like evaluation in x and 1 - x, as scipy's Dop853DenseOutput
                    v = 0.0
                    for r in range(7):
                        v += F[6 - r, i]
                        v *= x if r % 2 == 0 else 1.0 - x
                    Y[j_out, i] = y[i] + v
                j_out += 1
        while j_out < n_out and t_out[j_out] <= t_new:
            Y[j_out, :] = y_new
            j_out += 1
        # stiffness test: h times the local Lipschitz estimate between the last stage and y_new
        num = 0.0
        den = 0.0
        for i in range(n):
            num += (K[N_STAGES, i] - K[N_STAGES - 1, i]) ** 2
            den += (y_new[i] - y12[i]) ** 2
        if den > 0.0 and h * np.sqrt(num / den) > 6.1:
            st[CALM_RUN] = 0.0
            st[STIFF_RUN] += 1.0
            if st[STIFF_RUN] >= 15.0:
                st[STIFF_SEEN] = 1.0
        else:
            st[CALM_RUN] += 1.0
            if st[CALM_RUN] >= 6.0:
                st[STIFF_RUN] = 0.0
        y[:] = y_new
        fy[:] = K[N_STAGES]
        t = t_new
        st[T] = t
        st[H] = h_abs
        st[STEPS] += 1
        st[NEXT_OUT] = j_out
        done_here += 1
        for i in range(n):
            if not np.isfinite(y[i]):
                return NONFINITE
        if outside(y, bound):
            return BOUND
        if stop_on_stiff != 0 and st[STIFF_SEEN] != 0.0:
            return STIFF


@njit(I64(I64, VEC, VEC, F64, VEC, VEC, I64, I64, VEC, VEC, VEC, MAT), **JIT)
def run_at(at, k, t_out, rtol, atol, bound, stop_on_stiff, chunk, y, fy, st, Y):
    """``run`` with the right-hand side at the address ``at`` (``Bound.address``): the same loop, called
    from Python without the per-call work a first-class function argument costs (see common.rhs_at)."""
    return run(rhs_at(at), k, t_out, rtol, atol, bound, stop_on_stiff, chunk, y, fy, st, Y)
