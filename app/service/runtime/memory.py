"""The long-lived objects leave the garbage collector's sight once the server has loaded them.

CPython's cyclic collector scans every tracked object in a full (oldest-generation) collection.
A web process holding the chapter (SymPy's modules, the derivations, the compiled systems) tracks
about 170,000 objects, and one full collection of them took 0.1 s on this machine: a pause of the
event loop, the /healthz probe included, whenever a flood of requests allocates enough to trigger
one.  ``gc.freeze`` moves every object alive into a permanent generation that collections skip,
so later ones scan only what requests created.  A frozen object that becomes garbage is not
reclaimed by the cycle collector (reference counting still frees it), so the final freeze waits for
the warm-up to finish and collects first.

The warm-up itself allocates enough (derivations, numeric systems) to trigger full collections
while the first requests are served: with the imported modules unfrozen each took about 0.1 s
(160,000 objects), about 0.03 s with only what the warm-up loads (67,000).  So the server also
freezes what its imports left, as it starts (``freeze_imported``): modules, classes and functions
live as long as the process.
"""

from __future__ import annotations

import gc
import threading


def freeze_imported() -> None:
    """Freeze every object alive now (at the server's start: what its imports created)."""
    gc.collect()
    gc.freeze()


def freeze_when_done(*warming: threading.Thread) -> threading.Thread:
    """After the warm-up threads end: one full collection, then freeze what is left (a background thread)."""

    def settle() -> None:
        for thread in warming:
            thread.join()
        gc.collect()
        gc.freeze()

    thread = threading.Thread(target=settle, name="freeze-long-lived", daemon=True)
    thread.start()
    return thread
