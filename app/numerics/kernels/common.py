"""Types, status codes and small helpers shared by the compiled kernels."""

from __future__ import annotations

import numpy as np
from numba import njit, types
from numba.core import cgutils
from numba.extending import intrinsic

from app.numerics.paths import configure_numba

configure_numba()

F64 = types.float64
I64 = types.int64
VEC = types.float64[::1]
MAT = types.float64[:, ::1]

P64 = types.CPointer(types.float64)

# rhs(t, y, k, out): out = dy/dt at (t, y) for the parameter vector k, each vector as the address of
# its first element.  Raw addresses, not arrays: an array crosses a first-class call as a structure
# of seven fields, and with them the kernels' step loops were slow or fast by accidents of the
# compiler (the same Vern8 loop took 1.6 or 2.4 ms for bench_cyrk's pendulum after edits that added
# no work); with addresses the call is four machine words, as CyRK's and scipy's C callbacks are.
RHS_SIG = types.void(F64, P64, P64, P64)
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


@intrinsic
def address(typingctx, array):
    """The address of a float64 array's first element, to hand to a right-hand side (``RHS_SIG``).

    Nothing keeps the array alive through the address: pass an argument of the kernel, or an array
    (or a view of one) that the kernel uses again after the call, as numba frees an array after its
    last use."""
    if not (isinstance(array, types.Array) and array.dtype == types.float64 and array.layout == "C"):
        return None
    signature = P64(array)

    def codegen(context, builder, sig, args):
        return context.make_array(sig.args[0])(context, builder, args[0]).data

    return signature, codegen


@intrinsic
def rhs_at(typingctx, address):
    """The generated function at ``address`` (an integer, ``Bound.address``) as the kernels' ``RHS``.

    What numba builds when a ``Bound`` is passed in, without its work at every call from Python: there
    the argument is typed and unboxed in Python (numba's ``typeof``, then two look-ups of the address
    that read back its signature), 5-20 us per kernel call; an integer crosses in C.  The value holds
    the same C entry (``c_addr``) and no Python object nor numba entry (``py_addr``, ``jit_addr``), as a
    ``Bound``'s does, so a call through it runs the same code."""
    if not isinstance(address, types.Integer):
        return None

    def codegen(context, builder, sig, args):
        value = cgutils.create_struct_proxy(RHS)(context, builder)
        value.c_addr = builder.inttoptr(args[0], context.get_value_type(types.voidptr))
        return value._getvalue()

    return RHS(address), codegen


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


@njit(F64(VEC, VEC), **JIT)
def _rms(x, scale):
    # ||x / scale|| / sqrt(n)
    s = 0.0
    for i in range(x.size):
        s += (x[i] / scale[i]) ** 2
    return np.sqrt(s / x.size)


@njit(F64(RHS, F64, VEC, VEC, VEC, F64, F64, VEC, F64), **JIT)
def initial_step(f, t0, y0, f0, k, t_end, rtol, atol, order):
    """scipy's ``select_initial_step``: h from |y|, |f| and a trial Euler step."""
    n = y0.size
    scale = np.empty(n)
    for i in range(n):
        scale[i] = atol[i] + abs(y0[i]) * rtol
    d0 = _rms(y0, scale)
    d1 = _rms(f0, scale)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, t_end - t0)
    # y1 and f1 share one buffer: f1 is used after the call, which keeps y1 alive through it (see address)
    trial = np.empty((2, n))
    y1, f1 = trial[0], trial[1]
    for i in range(n):
        y1[i] = y0[i] + h0 * f0[i]
    f(t0 + h0, address(y1), address(k), address(f1))
    for i in range(n):
        f1[i] -= f0[i]
    d2 = _rms(f1, scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / (order + 1.0))
    return min(100.0 * h0, h1, t_end - t0)
