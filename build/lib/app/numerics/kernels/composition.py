"""Störmer-Verlet and its compositions (Yoshida's 4th order), compiled, for separable Hamiltonians.

For H = 1/2 v.M.v + U(q) with a constant mass matrix, q_ddot = a(q) depends on
the coordinates only.  One kick-drift-kick Verlet step of size w h:

    v_half = v + (w h / 2) a(q)
    q_new  = q + w h v_half
    v_new  = v_half + (w h / 2) a(q_new)

is symplectic and time-symmetric (order 2).  Yoshida's triple jump composes
three of them with w = (x1, x0, x1), x1 = 1 / (2 - 2^(1/3)), x0 = 1 - 2 x1, and
reaches order 4 while staying symplectic.  The step is fixed: ``substeps``
steps per interval between samples, so every sample is hit exactly.  Updates
use compensated summation, so round-off does not add a random walk to the
energy over very long runs.
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
    NONFINITE,
    RHS,
    RUNNING,
    VEC,
    address,
    all_finite,
    compensated_add,
    outside,
)

# Slots of the state vector ``st``.
INTERVAL, SUBSTEP, STEPS, NFEV, STARTED = range(5)
STATE_SIZE = 5


@njit(types.void(RHS, VEC, F64, F64, VEC, VEC, VEC, VEC, VEC), **JIT)
def composed_step(f, k, t, h, weights, y, acc, comp, work):
    """One composed step of size h: a kick-drift-kick Verlet step of size w h for each weight w."""
    n = y.size // 2
    for w in weights:
        hw = w * h
        for i in range(n):
            compensated_add(y, comp, n + i, 0.5 * hw * acc[i])
        for i in range(n):
            compensated_add(y, comp, i, hw * y[n + i])
        f(t, address(y), address(k), address(work))
        acc[:] = work[n:]
        for i in range(n):
            compensated_add(y, comp, n + i, 0.5 * hw * acc[i])


@njit(types.void(RHS, VEC, VEC, VEC, MAT, F64, VEC, F64, F64, VEC), **JIT)
def local_errors(f, k, weights, times, states, h, atol, rtol, order, out):
    """Scaled local error of one step from each state, by step doubling (see methods.symplectic)."""
    m = states.shape[1]
    n = m // 2
    work = np.empty(m)
    for s in range(states.shape[0]):
        t = times[s]
        one = states[s].copy()
        two = states[s].copy()
        acc1 = np.empty(n)
        f(t, address(one), address(k), address(work))
        acc1[:] = work[n:]
        acc2 = acc1.copy()
        composed_step(f, k, t, h, weights, one, acc1, np.zeros(m), work)
        comp = np.zeros(m)
        composed_step(f, k, t, 0.5 * h, weights, two, acc2, comp, work)
        composed_step(f, k, t + 0.5 * h, 0.5 * h, weights, two, acc2, comp, work)
        total = 0.0
        for i in range(m):
            scale = atol[i] + rtol * max(abs(states[s, i]), abs(two[i]))
            total += ((one[i] - two[i]) / (1.0 - 2.0**-order) / scale) ** 2
        err = np.sqrt(total / m)
        out[s] = err if np.isfinite(err) else np.inf


@njit(I64(RHS, VEC, VEC, VEC, I64, VEC, I64, VEC, VEC, VEC, VEC, MAT), **JIT)
def run(f, k, t_out, weights, substeps, bound, chunk, y, acc, comp, st, Y):
    """Advance at most ``chunk`` composed steps; y = (q, v), acc = a(q), comp = compensations."""
    m = y.size
    n = m // 2
    n_out = t_out.size
    work = np.empty(m)
    if st[STARTED] == 0.0:
        Y[0, :] = y
        f(t_out[0], address(y), address(k), address(work))
        acc[:] = work[n:]
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
            composed_step(f, k, t_out[j] + sub * h, h, weights, y, acc, comp, work)
            st[NFEV] += weights.size
            st[STEPS] += 1
            sub += 1
            done_here += 1
        sub = 0
        j += 1
        Y[j, :] = y
        st[INTERVAL] = j
        st[SUBSTEP] = 0
        if not all_finite(y):
            return NONFINITE
        if outside(y, bound):
            return BOUND
    return DONE
