"""Gauss-Legendre implicit Runge-Kutta on z = (q, p), compiled: symplectic for any Hamiltonian.

With s stages (order 2s) and the Butcher tableau (A, b, c) of the Gauss
collocation nodes, one step of size h solves

    Z_i = z + h sum_j a_ij F(t + c_i h, Z_j),   i = 1..s
    z_new = z + h sum_i b_i F(t + c_i h, Z_i)

by fixed-point iteration on the stage slopes K_i = F(Z_i).  The first guess
extrapolates the previous step's collocation polynomial: K_i ~ sum_j E_ij K_j^old
with E_ij = l_j(1 + c_i), the Lagrange basis on the nodes.  Iteration stops at
round-off (the correction no longer shrinks) or after 50 sweeps (then the
kernel reports no convergence: the step is too large for the problem's
stiffness).  The step is fixed, ``substeps`` per interval between samples, and
the update uses compensated summation.  Samples are (q, q_dot) with q_dot the
first half of F.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types

from app.numerics.kernels.common import (
    BOUND,
    DONE,
    F64,
    I64,
    JIT,
    MAT,
    NO_CONVERGENCE,
    NONFINITE,
    RHS,
    RUNNING,
    VEC,
    address,
    all_finite,
    compensated_add,
    outside,
)

MAX_SWEEPS = 50
INTERVAL, SUBSTEP, STEPS, NFEV, STARTED, HAVE_PREV, SWEEPS, MAX_SWEEPS_SEEN = range(8)
STATE_SIZE = 8


@njit(types.boolean(RHS, VEC, F64, F64, MAT, VEC, VEC, MAT, VEC, VEC, VEC, MAT, MAT, VEC), **JIT)
def gl_step(f, k, t, h, A, b, c, E, scale_floor, z, comp, K, Kprev, st):
    """One Gauss-Legendre step of size h in place on z; False when the stage iteration fails."""
    m = z.size
    s = b.size
    Knew = np.empty((s, m))
    Z = np.empty(m)
    # first guess of the stage slopes
    if st[HAVE_PREV] != 0.0:
        for i in range(s):
            for col in range(m):
                acc = 0.0
                for jj in range(s):
                    acc += E[i, jj] * Kprev[jj, col]
                K[i, col] = acc
    else:
        f(t, address(z), address(k), address(Z))
        st[NFEV] += 1
        for i in range(s):
            K[i, :] = Z
    previous = np.inf
    for sweep in range(MAX_SWEEPS):
        # K_i <- F(t + c_i h, z + h sum_j a_ij K_j)
        for i in range(s):
            for col in range(m):
                acc = 0.0
                for jj in range(s):
                    acc += A[i, jj] * K[jj, col]
                Z[col] = z[col] + h * acc
            f(t + c[i] * h, address(Z), address(k), address(Knew[i]))
        st[NFEV] += s
        st[SWEEPS] += 1
        change = 0.0
        for i in range(s):
            for col in range(m):
                d = abs(h * (Knew[i, col] - K[i, col])) / (abs(z[col]) + scale_floor[col])
                if not d <= change:
                    change = d
        K[:, :] = Knew
        if sweep + 1 > st[MAX_SWEEPS_SEEN]:
            st[MAX_SWEEPS_SEEN] = sweep + 1
        converged = change <= 1e-15 or (sweep >= 2 and change >= previous and change <= 1e-10)
        if converged:
            # z_new = z + h sum_i b_i K_i
            for col in range(m):
                acc = 0.0
                for i in range(s):
                    acc += b[i] * K[i, col]
                compensated_add(z, comp, col, h * acc)
            Kprev[:, :] = K
            st[HAVE_PREV] = 1.0
            return True
        if not np.isfinite(change):
            return False
        previous = change
    return False


@njit(types.void(RHS, VEC, MAT, VEC, VEC, MAT, VEC, MAT, F64, VEC, F64, F64, VEC), **JIT)
def local_errors(f, k, A, b, c, E, times, states, h, atol, rtol, order, out):
    """Scaled local error of one step from each state z = (q, p), by step doubling."""
    m = states.shape[1]
    s = b.size
    st = np.zeros(STATE_SIZE)
    K = np.empty((s, m))
    Kprev = np.zeros((s, m))
    for r in range(states.shape[0]):
        t = times[r]
        one = states[r].copy()
        two = states[r].copy()
        st[HAVE_PREV] = 0.0
        ok = gl_step(f, k, t, h, A, b, c, E, atol, one, np.zeros(m), K, Kprev, st)
        st[HAVE_PREV] = 0.0
        comp = np.zeros(m)
        ok = ok and gl_step(f, k, t, 0.5 * h, A, b, c, E, atol, two, comp, K, Kprev, st)
        ok = ok and gl_step(f, k, t + 0.5 * h, 0.5 * h, A, b, c, E, atol, two, comp, K, Kprev, st)
        total = 0.0
        for i in range(m):
            scale = atol[i] + rtol * max(abs(states[r, i]), abs(two[i]))
            total += ((one[i] - two[i]) / (1.0 - 2.0**-order) / scale) ** 2
        err = np.sqrt(total / m)
        out[r] = err if ok and np.isfinite(err) else np.inf


@njit(I64(RHS, VEC, VEC, MAT, VEC, VEC, MAT, I64, VEC, VEC, I64, VEC, VEC, MAT, VEC, MAT), **JIT)
def run(f, k, t_out, A, b, c, E, substeps, bound, scale_floor, chunk, z, comp, Kprev, st, Y):
    m = z.size
    n = m // 2
    s = b.size
    n_out = t_out.size
    K = np.empty((s, m))
    work = np.empty(m)
    if st[STARTED] == 0.0:
        f(t_out[0], address(z), address(k), address(work))
        Y[0, :n] = z[:n]
        Y[0, n:] = work[:n]
        st[NFEV] += 1
        st[STARTED] = 1.0
    j = int(st[INTERVAL])
    sub = int(st[SUBSTEP])
    done_here = 0
    while j < n_out - 1:
        h = (t_out[j + 1] - t_out[j]) / substeps
        while sub < substeps:
            if done_here >= chunk:
                st[INTERVAL] = j
                st[SUBSTEP] = sub
                return RUNNING
            if not gl_step(f, k, t_out[j] + sub * h, h, A, b, c, E, scale_floor, z, comp, K, Kprev, st):
                st[INTERVAL] = j
                st[SUBSTEP] = sub
                return NO_CONVERGENCE
            st[STEPS] += 1
            sub += 1
            done_here += 1
        sub = 0
        j += 1
        f(t_out[j], address(z), address(k), address(work))
        st[NFEV] += 1
        Y[j, :n] = z[:n]
        Y[j, n:] = work[:n]
        st[INTERVAL] = j
        st[SUBSTEP] = 0
        if not all_finite(z) or not all_finite(work):
            return NONFINITE
        if outside(Y[j], bound):
            return BOUND
    return DONE
