"""Radau IIA of order 5 (Hairer and Wanner's RADAU5 scheme) as a compiled loop, for stiff problems.

One step from t to t + h solves the collocation equations for the stage increments
Z_i = Y_i - y at the nodes c = ((4 - sqrt 6)/10, (4 + sqrt 6)/10, 1):

    Z = h (A ⊗ I) F(t + c h, y + Z),        y_new = y + Z_3

A's inverse has one real eigenvalue mu_r and a complex pair mu_c, conj(mu_c); in the
basis W = T^-1 Z that diagonalises it, simplified Newton (J = dF/dy held fixed over the
step, often over many steps) splits into one real and one complex linear system of size m:

    (mu_r / h - J) dW_1 = (T^-1 F)_1 - (mu_r / h) W_1
    (mu_c / h - J) (dW_2 + i dW_3) = (T^-1 F)_2 + i (T^-1 F)_3 - (mu_c / h) (W_2 + i W_3)

each solved with an LU factorisation kept while h and J stay.  The iteration stops when
the contraction rate theta predicts the remaining correction theta/(1 - theta) |dW| below
``newton_tol``; it fails (h is halved, J refreshed first) when theta >= 1 or the
prediction says six iterations cannot get there.

Error estimate (order 3, as RADAU5): err = (mu_r / h - J)^-1 (f(t, y) + (e^T Z) / h), with e
chosen so that it is h gamma_0 f + e^T Z = y_new - y_hat of an embedded method; after a
rejection it is filtered once more through f(t, y + err) (Hairer and Wanner IV.8).  The step
size follows Gustafsson's predictive controller,

    h_new = h min(10, safety min(1, (h / h_prev) (err_prev / err)^(1/4)) err^(-1/4)),

with safety 0.9 (2 N + 1) / (2 N + iterations), N = 6, and h kept when the factor is between
1 and 1.2 (the factorisations then stay valid).  Dense output is the collocation polynomial
itself: u(t + x h) = y + sum_{j=1..3} Q_j x^j, the cubic through (0, 0) and (c_i, Z_i);
the next step starts Newton from it, extrapolated.

The Jacobian is the engine's, generated and compiled as the right-hand side is (``jac``,
same calling convention, out[i m + j] = dF_i/dy_j); for a system without one (``has_jac``
0), forward differences.  Coefficients as published by Hairer and Wanner (and in
scipy's ``Radau``, which runs the same scheme with a Python step loop); the tests check
them (``tests/numerics/test_radau.py``).
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
    STEP_TOO_SMALL,
    VEC,
    address,
    initial_step,
)

S6 = 6.0**0.5
C = np.array([(4.0 - S6) / 10.0, (4.0 + S6) / 10.0, 1.0])
# the error estimate's weights: (e^T Z) / h with e = (-13 - 7 sqrt 6, -13 + 7 sqrt 6, -1) / 3
E = np.array([-13.0 - 7.0 * S6, -13.0 + 7.0 * S6, -1.0]) / 3.0
# eigenvalues of A^-1: the real one and the complex pair
MU_REAL = 3.0 + 3.0 ** (2.0 / 3.0) - 3.0 ** (1.0 / 3.0)
MU_COMPLEX = 3.0 + 0.5 * (3.0 ** (1.0 / 3.0) - 3.0 ** (2.0 / 3.0)) - 0.5j * (3.0 ** (5.0 / 6.0) + 3.0 ** (7.0 / 6.0))
# A^-1 = T diag(mu_r, [[a, -b], [b, a]]) T^-1, with T's columns the real and the complex eigenvector's parts
T_MAT = np.array(
    [
        [0.09443876248897524, -0.14125529502095421, 0.03002919410514742],
        [0.25021312296533332, 0.20412935229379994, -0.38294211275726192],
        [1.0, 1.0, 0.0],
    ]
)
TI = np.array(
    [
        [4.17871859155190428, 0.32768282076106237, 0.52337644549944951],
        [-4.17871859155190428, -0.32768282076106237, 0.47662355450055044],
        [0.50287263494578682, -2.57192694985560522, 0.59603920482822492],
    ]
)
# the collocation polynomial: Q_j = sum_i P_ij Z_i, u(t + x h) = y + Q_1 x + Q_2 x^2 + Q_3 x^3
P = np.array(
    [
        [13.0 / 3.0 + 7.0 * S6 / 3.0, -23.0 / 3.0 - 22.0 * S6 / 3.0, 10.0 / 3.0 + 5.0 * S6],
        [13.0 / 3.0 - 7.0 * S6 / 3.0, -23.0 / 3.0 + 22.0 * S6 / 3.0, 10.0 / 3.0 - 5.0 * S6],
        [1.0 / 3.0, -8.0 / 3.0, 10.0 / 3.0],
    ]
)
NEWTON_MAXITER = 6
MIN_FACTOR, MAX_FACTOR = 0.2, 10.0
EPS = 2.220446049250313e-16
SQRT_EPS = 1.4901161193847656e-08

# Slots of the state vector ``st`` carried between calls.
(T, H, STEPS, REJECTED, NFEV, NEXT_OUT, STARTED, H_OLD, ERR_OLD, NJEV, NLU, HAVE_SOL, T_OLD, CURRENT_JAC) = range(14)
STATE_SIZE = 14


@njit(**JIT)
def _lu_factor(A, piv):
    """A = P L U in place (Doolittle, partial pivoting), real or complex; False when A is singular."""
    m = A.shape[0]
    for j in range(m):
        p = j
        big = abs(A[j, j])
        for i in range(j + 1, m):
            if abs(A[i, j]) > big:
                big = abs(A[i, j])
                p = i
        piv[j] = p
        if big == 0.0 or not np.isfinite(big):
            return False
        if p != j:
            for c in range(m):
                A[j, c], A[p, c] = A[p, c], A[j, c]
        inv = 1.0 / A[j, j]
        for i in range(j + 1, m):
            A[i, j] *= inv
            lij = A[i, j]
            for c in range(j + 1, m):
                A[i, c] -= lij * A[j, c]
    return True


@njit(**JIT)
def _lu_solve(LU, piv, b):
    """b <- A^-1 b from ``_lu_factor``'s output."""
    m = LU.shape[0]
    for j in range(m):
        p = piv[j]
        if p != j:
            b[j], b[p] = b[p], b[j]
    # L z = P b (unit lower triangle), then U x = z
    for i in range(m):
        acc = b[i]
        for c in range(i):
            acc -= LU[i, c] * b[c]
        b[i] = acc
    for i in range(m - 1, -1, -1):
        acc = b[i]
        for c in range(i + 1, m):
            acc -= LU[i, c] * b[c]
        b[i] = acc / LU[i, i]


@njit(**JIT)
def _jacobian(f, jac, has_jac, t, y, fy, k, J, ywork, fwork):
    """J = dF/dy at (t, y): the generated Jacobian, else forward differences (column j from a step
    sqrt(eps) max(|y_j|, 1e-5), error O(step)).  Returns the right-hand-side evaluations spent."""
    m = y.size
    if has_jac != 0:
        jac(t, address(y), address(k), address(J))
        return 0
    for i in range(m):
        ywork[i] = y[i]
    for j in range(m):
        step = SQRT_EPS * max(abs(y[j]), 1e-5)
        ywork[j] = y[j] + step
        step = ywork[j] - y[j]  # the step as represented
        f(t, address(ywork), address(k), address(fwork))
        for i in range(m):
            J[i, j] = (fwork[i] - fy[i]) / step
        ywork[j] = y[j]
    return m


@njit(**JIT)
def _factor(J, h, LUr, LUc, piv_r, piv_c):
    """LU of mu_r / h - J and mu_c / h - J; False when either is singular."""
    m = J.shape[0]
    a_r = MU_REAL / h
    a_c = MU_COMPLEX / h
    for i in range(m):
        for j in range(m):
            LUr[i, j] = -J[i, j]
            LUc[i, j] = -J[i, j]
        LUr[i, i] += a_r
        LUc[i, i] += a_c
    return _lu_factor(LUr, piv_r) and _lu_factor(LUc, piv_c)


@njit(**JIT)
def _newton(f, k, t, y, h, Z, W, F, dr, dc, ys, fs, scale, tol, LUr, LUc, piv_r, piv_c, out):
    """Simplified Newton on the collocation equations from the guess Z (3 x m), in the basis W = T^-1 Z.

    Returns True when converged (Z holds the solution); out[0] the iterations, out[1] the last rate,
    out[2] the evaluations spent."""
    m = y.size
    for s in range(3):
        for i in range(m):
            W[s, i] = TI[s, 0] * Z[0, i] + TI[s, 1] * Z[1, i] + TI[s, 2] * Z[2, i]
    a_r = MU_REAL / h
    a_c = MU_COMPLEX / h
    norm_old = -1.0
    rate = -1.0
    nfev = 0
    iterations = 0
    converged = False
    for it in range(NEWTON_MAXITER):
        iterations = it + 1
        finite = True
        for s in range(3):
            for i in range(m):
                ys[i] = y[i] + Z[s, i]
            f(t + C[s] * h, address(ys), address(k), address(fs))
            nfev += 1
            for i in range(m):
                F[s, i] = fs[i]
                if not np.isfinite(fs[i]):
                    finite = False
        if not finite:
            break
        # right-hand sides of the two systems: (T^-1 F) - (mu / h) W, the complex one from rows 2 and 3
        for i in range(m):
            dr[i] = TI[0, 0] * F[0, i] + TI[0, 1] * F[1, i] + TI[0, 2] * F[2, i] - a_r * W[0, i]
            w_c = W[1, i] + 1j * W[2, i]
            f_c = (TI[1, 0] * F[0, i] + TI[1, 1] * F[1, i] + TI[1, 2] * F[2, i]) + 1j * (
                TI[2, 0] * F[0, i] + TI[2, 1] * F[1, i] + TI[2, 2] * F[2, i]
            )
            dc[i] = f_c - a_c * w_c
        _lu_solve(LUr, piv_r, dr)
        _lu_solve(LUc, piv_c, dc)
        # |dW| in the scaled rms norm over all 3m components
        acc = 0.0
        for i in range(m):
            acc += (dr[i] / scale[i]) ** 2 + (dc[i].real / scale[i]) ** 2 + (dc[i].imag / scale[i]) ** 2
        norm = np.sqrt(acc / (3 * m))
        if norm_old >= 0.0:
            rate = norm / norm_old
        # diverging, or too slow to reach tol in the iterations left: theta^(N - it) / (1 - theta) |dW| > tol
        if rate >= 0.0 and (rate >= 1.0 or rate ** (NEWTON_MAXITER - it) / (1.0 - rate) * norm > tol):
            break
        for i in range(m):
            W[0, i] += dr[i]
            W[1, i] += dc[i].real
            W[2, i] += dc[i].imag
        for s in range(3):
            for i in range(m):
                Z[s, i] = T_MAT[s, 0] * W[0, i] + T_MAT[s, 1] * W[1, i] + T_MAT[s, 2] * W[2, i]
        # the remaining correction, theta / (1 - theta) |dW|, below tol
        if norm == 0.0 or (rate >= 0.0 and rate / (1.0 - rate) * norm < tol):
            converged = True
            break
        norm_old = norm
    out[0] = iterations
    out[1] = rate
    out[2] = nfev
    return converged


@njit(**JIT)
def _newton_start(have_sol, t, t_old, h, Q, y, Z):
    """Z = u(t + c_s h) - y at the three nodes, u the last step's collocation polynomial
    u(t_old + x h_prev) = Q_3 + x (Q_0 + x (Q_1 + x Q_2)) extrapolated; zero at the first step."""
    m = y.size
    if not have_sol:
        Z[:, :] = 0.0
        return
    h_prev = t - t_old
    for s in range(3):
        x = (t + C[s] * h - t_old) / h_prev
        for i in range(m):
            Z[s, i] = Q[3, i] + x * (Q[0, i] + x * (Q[1, i] + x * Q[2, i])) - y[i]


@njit(types.float64(F64, F64, F64, F64), **JIT)
def _predict_factor(h_abs, h_old, err, err_old):
    """Gustafsson's factor min(1, (h / h_prev) (err_prev / err)^(1/4)) err^(-1/4); the plain err^(-1/4) on the
    first step (h_old or err_old not positive)."""
    if err == 0.0:
        return MAX_FACTOR
    if h_old <= 0.0 or err_old <= 0.0:
        multiplier = 1.0
    else:
        multiplier = h_abs / h_old * (err_old / err) ** 0.25
    return min(1.0, multiplier) * err**-0.25


@njit(I64(RHS, RHS, I64, VEC, VEC, F64, VEC, VEC, I64, VEC, VEC, VEC, MAT, MAT, MAT), **JIT)
def run(f, jac, has_jac, k, t_out, rtol, atol, bound, chunk, y, fy, st, Y, J, Q):
    """Advance at most ``chunk`` accepted steps; fill Y[i] = y(t_out[i]) as the samples are passed.

    Carried between calls: ``st`` (the slots above), ``fy`` = F(t, y), ``J`` (m x m) and ``Q`` (4 x m: the
    last step's polynomial Q_1..Q_3 and the y it started from).  The factorisations are redone at each call."""
    m = y.size
    n_out = t_out.size
    t_end = t_out[n_out - 1]
    Z = np.zeros((3, m))
    W = np.empty((3, m))
    F = np.empty((3, m))
    dr = np.empty(m)
    dc = np.empty(m, dtype=np.complex128)
    ys = np.empty(m)
    fs = np.empty(m)
    y_new = np.empty(m)
    err = np.empty(m)
    scale = np.empty(m)
    LUr = np.empty((m, m))
    LUc = np.empty((m, m), dtype=np.complex128)
    piv_r = np.empty(m, dtype=np.int64)
    piv_c = np.empty(m, dtype=np.int64)
    info = np.empty(3)
    ywork = np.empty(m)
    fwork = np.empty(m)
    newton_tol = max(10.0 * EPS / rtol, min(0.03, rtol**0.5))
    nfev = 0
    njev = 0
    nlu = 0
    if st[STARTED] == 0.0:
        st[T] = t_out[0]
        f(st[T], address(y), address(k), address(fy))
        st[H] = initial_step(f, st[T], y, fy, k, t_end, rtol, atol, 3.0)
        nfev += 2
        nfev += _jacobian(f, jac, has_jac, st[T], y, fy, k, J, ywork, fwork)
        njev += 1
        st[CURRENT_JAC] = 1.0
        st[STARTED] = 1.0
    t = st[T]
    h_abs = st[H]
    h_old = st[H_OLD]
    err_old = st[ERR_OLD]
    have_sol = st[HAVE_SOL] != 0.0
    t_old = st[T_OLD]
    current_jac = st[CURRENT_JAC] != 0.0
    j_out = int(st[NEXT_OUT])
    while j_out < n_out and t_out[j_out] <= t:
        Y[j_out, :] = y
        j_out += 1
    factored = False  # the LU factors belong to the current h and J
    factored_h = 0.0
    accepted = 0
    rejected_total = 0
    status = RUNNING
    n_iter = 0
    rate = -1.0
    err_norm = 0.0
    safety = 0.9
    while True:
        if j_out >= n_out or t >= t_end:
            status = DONE
            break
        if accepted >= chunk:
            break
        smallest = 10.0 * EPS * max(abs(t), 1e-300)
        rejected = False
        step_ok = False
        while not step_ok:
            if h_abs <= smallest:
                status = STEP_TOO_SMALL
                break
            t_new = t + h_abs
            if t_new > t_end:
                t_new = t_end
            h = t_new - t
            h_abs = h
            # Newton's start: the last step's polynomial extrapolated to the new nodes, minus y
            _newton_start(have_sol, t, t_old, h, Q, y, Z)
            for i in range(m):
                scale[i] = atol[i] + abs(y[i]) * rtol
            converged = False
            while True:
                if not factored or factored_h != h:
                    nlu += 2
                    factored = _factor(J, h, LUr, LUc, piv_r, piv_c)
                    factored_h = h
                if factored:
                    converged = _newton(
                        f, k, t, y, h, Z, W, F, dr, dc, ys, fs, scale, newton_tol, LUr, LUc, piv_r, piv_c, info
                    )
                    n_iter = int(info[0])
                    rate = info[1]
                    nfev += int(info[2])
                if converged or current_jac:
                    break
                # not converged with an old Jacobian: refresh it and try again from the same guess
                nfev += _jacobian(f, jac, has_jac, t, y, fy, k, J, ywork, fwork)
                njev += 1
                current_jac = True
                factored = False
                _newton_start(have_sol, t, t_old, h, Q, y, Z)
            if not converged:
                h_abs *= 0.5
                factored = False
                rejected = True
                rejected_total += 1
                continue
            # the error estimate: (mu_r / h - J)^-1 (f + (e^T Z) / h), scaled by the larger of |y|, |y_new|
            for i in range(m):
                y_new[i] = y[i] + Z[2, i]
                err[i] = fy[i] + (E[0] * Z[0, i] + E[1] * Z[1, i] + E[2] * Z[2, i]) / h
            _lu_solve(LUr, piv_r, err)
            for i in range(m):
                scale[i] = atol[i] + max(abs(y[i]), abs(y_new[i])) * rtol
            acc = 0.0
            for i in range(m):
                acc += (err[i] / scale[i]) ** 2
            err_norm = np.sqrt(acc / m)
            safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + n_iter)
            if rejected and err_norm > 1.0:
                # after a rejection, filter once more: (mu_r / h - J)^-1 (f(t, y + err) + (e^T Z) / h)
                for i in range(m):
                    ys[i] = y[i] + err[i]
                f(t, address(ys), address(k), address(fs))
                nfev += 1
                for i in range(m):
                    err[i] = fs[i] + (E[0] * Z[0, i] + E[1] * Z[1, i] + E[2] * Z[2, i]) / h
                _lu_solve(LUr, piv_r, err)
                acc = 0.0
                for i in range(m):
                    acc += (err[i] / scale[i]) ** 2
                err_norm = np.sqrt(acc / m)
            if not np.isfinite(err_norm):
                h_abs *= MIN_FACTOR
                factored = False
                rejected = True
                rejected_total += 1
                continue
            if err_norm > 1.0:
                factor = _predict_factor(h_abs, h_old, err_norm, err_old)
                h_abs *= max(MIN_FACTOR, safety * factor)
                factored = False
                rejected = True
                rejected_total += 1
            else:
                step_ok = True
        if status == STEP_TOO_SMALL:
            break
        # accepted.  A slow Newton contraction asks for a fresh Jacobian at the new point.
        recompute_jac = n_iter > 2 and rate > 1e-3
        factor = min(MAX_FACTOR, safety * _predict_factor(h_abs, h_old, err_norm, err_old))
        if not recompute_jac and factor < 1.2:
            factor = 1.0  # keep h, so the factorisations stay
        h_old = h_abs
        err_old = err_norm
        # the collocation polynomial of this step, for the samples inside it and the next step's start
        for i in range(m):
            Q[3, i] = y[i]
            for c in range(3):
                Q[c, i] = P[0, c] * Z[0, i] + P[1, c] * Z[1, i] + P[2, c] * Z[2, i]
        while j_out < n_out and t_out[j_out] < t_new:
            x = (t_out[j_out] - t) / h
            for i in range(m):
                Y[j_out, i] = y[i] + x * (Q[0, i] + x * (Q[1, i] + x * Q[2, i]))
            j_out += 1
        while j_out < n_out and t_out[j_out] <= t_new:
            Y[j_out, :] = y_new
            j_out += 1
        outside_box = False
        for i in range(m):
            y[i] = y_new[i]
            if not abs(y[i]) <= bound[i]:
                outside_box = True
        t_old = t
        t = t_new
        have_sol = True
        accepted += 1
        h_abs = h_abs * factor
        if outside_box:
            status = BOUND
            for i in range(m):
                if not np.isfinite(y[i]):
                    status = NONFINITE
            break
        f(t, address(y), address(k), address(fy))
        nfev += 1
        if recompute_jac:
            nfev += _jacobian(f, jac, has_jac, t, y, fy, k, J, ywork, fwork)
            njev += 1
            current_jac = True
            factored = False
        else:
            current_jac = False
    st[T] = t
    st[H] = h_abs
    st[H_OLD] = h_old
    st[ERR_OLD] = err_old
    st[HAVE_SOL] = 1.0 if have_sol else 0.0
    st[T_OLD] = t_old
    st[CURRENT_JAC] = 1.0 if current_jac else 0.0
    st[NEXT_OUT] = j_out
    st[STEPS] += accepted
    st[REJECTED] += rejected_total
    st[NFEV] += nfev
    st[NJEV] += njev
    st[NLU] += nlu
    return status
