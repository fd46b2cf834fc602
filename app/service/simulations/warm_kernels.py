"""The warm-up: every kernel and every scene's numeric system compiled (or loaded) in the background."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from app.limits import GIVE_WAY_SECONDS
from app.numerics.methods import METHODS, NONSTIFF
from app.numerics.methods.scipy_ivp import scipy_integrate
from app.scenes import SCENES
from app.service.runtime.gates import Gates

if TYPE_CHECKING:
    from app.service.chapter.derivations import Scenes


def warm_all(scenes: Scenes, give_way: Callable[[], object] = lambda: None) -> dict[str, float]:
    """Compile (or load from numba's disk cache) every kernel and every scene's right-hand sides.

    Run in the background at start-up and at image build (``python -m app.service.simulations.simulation``).
    Order: scipy.integrate (the fallback); then scene by scene (in the chapter's order), its
    derivation and numeric system, then ``auto``'s compiled default (``NONSTIFF``: what it picks most
    often, and the error reference) on it; then the other compiled kernels.  A method is used the
    moment it is ready.  ``give_way`` runs between steps (the server's: wait while requests are being
    served).  ``scenes``: whose systems (the app's, or the process's at image build).  Returns the seconds
    spent per item."""
    spent: dict[str, float] = {}
    # scipy first: it answers while the kernels load, and once imported here (under its lock) no kernel
    # module that reads scipy's tables can be importing it half-way beside a request's fallback
    start = time.perf_counter()
    scipy_integrate()
    spent["scipy.integrate"] = time.perf_counter() - start
    first = METHODS[NONSTIFF]
    systems = []
    for scene_id in SCENES:
        give_way()
        start = time.perf_counter()
        system = scenes.system(scene_id)[0]
        systems.append(system)
        spent["numeric systems"] = spent.get("numeric systems", 0.0) + time.perf_counter() - start
        give_way()
        start = time.perf_counter()
        if first.applicable(system) is None:
            first.prepare(system)
        spent[first.name] = spent.get(first.name, 0.0) + time.perf_counter() - start
    for method in (m for m in METHODS.values() if m.compiled and m is not first):
        start = time.perf_counter()
        for system in systems:
            give_way()
            if method.applicable(system) is None:
                method.prepare(system)
        spent[method.name] = time.perf_counter() - start
    return spent


def start_warming(scenes: Scenes, gates: Gates) -> threading.Thread:
    """The server's start: answer at once (scipy while compiling), load and compile ``scenes``' systems in
    the background.

    The thread gives way to the requests being served (``gates.in_flight``) between its steps, so that a
    first request shares the processor with at most one step of it (one scene's system or one kernel);
    the app's ``Gates`` answer from scipy meanwhile (``answer_while_compiling``, app/service/services.py)."""
    thread = threading.Thread(
        target=warm_all,
        args=(scenes, lambda: gates.in_flight.wait_quiet(GIVE_WAY_SECONDS)),
        name="warm-up",
        daemon=True,
    )
    thread.start()
    return thread
