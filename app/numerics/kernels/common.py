"""Types, status codes and small helpers shared by the compiled kernels."""

from __future__ import annotations

import numpy as np
from numba import njit, types

from app.numerics.paths import configure_numba

configure_numba()

F64 = types.float64
I64 = types.int64
VEC = types.float64[::1]
MAT = types.float64[:, ::1]

# rhs(t, y, k, out): out = dy/dt at (t, y) for the parameter vector k
RHS_SIG = types.void(F64, VEC, VEC, VEC)
RHS = types.FunctionType(RHS_SIG)

JIT = {"cache": True, "nogil": True, "error_model": "numpy"}

# Kernel status codes (returned by every kernel call).
RUNNING = 0  # chunk used up, call again
DONE = 1
NONFINITE = 2
BOUND = 3  # a component left the allowed box: a runaway
STEP_TOO_SMALL = 4
STIFF = 5
NO_CONVERGENCE = 6

STATUS_NAMES = {
    RUNNING: "running",
    DONE: "done",
    NONFINITE: "non-finite state",
    BOUND: "state bound exceeded",
    STEP_TOO_SMALL: "step size underflow",
    STIFF: "stiffness detected",
    NO_CONVERGENCE: "implicit stage equations did not converge",
}


@njit(types.boolean(VEC, VEC), **JIT)
def outside(y, bound):
    """True when some |y_i| exceeds its bound (or is not a number)."""
    for i in range(y.size):
        if not abs(y[i]) <= bound[i]:
            return True
    return False


@njit(types.boolean(VEC), **JIT)
def all_finite(y):
    for i in range(y.size):
        if not np.isfinite(y[i]):
            return False
    return True


@njit(types.void(VEC, VEC, types.intp, F64), **JIT)
def compensated_add(x, c, i, delta):
    """x_i += delta with Kahan's running compensation c_i (keeps long runs free of round-off drift)."""
    inc = delta - c[i]
    new = x[i] + inc
    c[i] = (new - x[i]) - inc
    x[i] = new
