"""A compiled generated function handed to the kernels by its address, found once (numba's side of ``jit``).

Kept apart from ``app.numerics.jit`` so that importing the app does not import numba (about
0.5 s of a server's start): this module loads with the first compiled run."""

from __future__ import annotations

from numba.core import types
from numba.core.types.function_type import WrapperAddressProtocol
from numba.experimental.function_type import _get_wrapper_address
from numba.extending import typeof_impl


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

    def __wrapper_address__(self) -> int:
        return self.address

    def signature(self):
        return self.sig


@typeof_impl.register(Bound)
def _typeof_bound(value: Bound, context) -> types.FunctionType:
    # the type found once: numba otherwise rebuilds the function type from the signature at every
    # Python-to-kernel call (13 us of a 38 us call measured)
    return value.numba_type
