"""A compiled generated function handed to the kernels by its address, found once (numba's side of ``jit``).

Kept apart from ``app.numerics.jit`` so that importing the app does not import numba (about
0.5 s of a server's start): this module loads with the first compiled run."""

from __future__ import annotations

import numpy as np
from numba import njit
from numba.core import types
from numba.core.types.function_type import WrapperAddressProtocol
from numba.experimental.function_type import _get_wrapper_address
from numba.extending import typeof_impl

from app.numerics.kernels.common import F64, I64, JIT, VEC, address, rhs_at


class Bound(WrapperAddressProtocol):
    """A compiled generated function as a first-class function argument of the kernels, resolved once.

    Handing numba a dispatcher makes it look up the function's wrapper address at
    every Python-to-kernel call (hundreds of microseconds); this object hands over the
    address found once, per system and function."""

    def __init__(self, dispatcher, signature):
        self.dispatcher = dispatcher  # keeps the compiled code alive
        self.sig = signature
        self.address = _get_wrapper_address(dispatcher, signature)
        self.numba_type = types.FunctionType(signature)  # what numba's typeof would build at every call

    def __call__(self, t: float, y: np.ndarray, k: np.ndarray, out: np.ndarray) -> None:
        """The function called from Python: out = f(t, y, k), for contiguous float64 arrays (checked).

        Through a compiled trampoline, whose signature checks the arrays: the C entry through ctypes
        took 40-70 us right after other work (the ctypes objects of three addresses and the checks
        in Python), the trampoline 10-20 us, for the same machine code and the same numbers."""
        try:
            _call(self.address, float(t), y, k, out)
        except TypeError:
            for a in (y, k, out):
                if not (isinstance(a, np.ndarray) and a.dtype == np.float64 and a.flags.c_contiguous):
                    raise TypeError("a compiled generated function takes contiguous float64 arrays") from None
            # read-only arguments, which the trampoline's signature does not take: their copies
            _call(self.address, float(t), y.copy(), k.copy(), out)

    def __wrapper_address__(self) -> int:
        return self.address

    def signature(self):
        return self.sig


@njit(types.void(I64, F64, VEC, VEC, VEC), **JIT)
def _call(at, t, y, k, out):
    # the function by its address, an integer (see kernels.common.rhs_at)
    rhs_at(at)(t, address(y), address(k), address(out))


@typeof_impl.register(Bound)
def _typeof_bound(value: Bound, context) -> types.FunctionType:
    # the type found once: numba otherwise rebuilds the function type from the signature at every
    # Python-to-kernel call (13 us of a 38 us call measured)
    return value.numba_type
