"""The long-lived objects leave the garbage collector's sight once the server has loaded them.

CPython's cyclic collector scans every tracked object in a full (oldest-generation) collection.
A web process holding the chapter (SymPy's modules, the derivations, the compiled systems) tracks
about 170,000 objects, and one full collection of them took 0.1 s on this machine: a pause of the
event loop, the /healthz probe included, whenever a flood of requests allocates enough to trigger
one.  ``gc.freeze`` moves every object alive into a permanent generation that collections skip,
so later ones scan only what requests created.  A frozen object that becomes garbage is not
reclaimed by the cycle collector (reference counting still frees it), so freezing waits for the
warm-up to finish and collects first.
"""

from __future__ import annotations

import gc
import threading


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
