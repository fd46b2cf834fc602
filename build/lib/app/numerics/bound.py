"""A compiled generated function handed to the kernels by its address, found once (numba's side of ``jit``).

Kept apart from ``app.numerics.jit`` so that importing the app does not import numba (about
0.5 s of a server's start): this module loads with the first compiled run."""

from __future__ import annotations

import ctypes

import numpy as np
from numba.core import types
from numba.core.types.function_type import WrapperAddressProtocol
from numba.experimental.function_type import _get_wrapper_address
from numba.extending import typeof_impl

_C_RHS = ctypes.CFUNCTYPE(None, ctypes.c_double, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p)


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
        # the same machine code called from Python, through its C entry (the RHS_SIG convention: a
        # double and three addresses); kept here so that it lives as long as the address does
        self._c_function = _C_RHS(self.address)

    def __call__(self, t: float, y: np.ndarray, k: np.ndarray, out: np.ndarray) -> None:
        """The function called from Python: out = f(t, y, k), for contiguous float64 arrays (checked)."""
        for a in (y, k, out):
            if a.dtype != np.float64 or not a.flags.c_contiguous:
                raise TypeError("a compiled generated function takes contiguous float64 arrays")
        self._c_function(float(t), y.ctypes.data, k.ctypes.data, out.ctypes.data)

    def __wrapper_address__(self) -> int:
        return self.address

    def signature(self):
        return self.sig


@typeof_impl.register(Bound)
def _typeof_bound(value: Bound, context) -> types.FunctionType:
    # the type found once: numba otherwise rebuilds the function type from the signature at every
    # Python-to-kernel call (13 us of a 38 us call measured)
    return value.numba_type
