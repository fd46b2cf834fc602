"""Poincaré sections of scenes and user systems: checked options in, the documented JSON out.

``section_of_derivation`` is the entry point the pages (and a later API route)
call with a derivation; ``section_of_scene`` looks the scene up.  The result:

    {"coordinate": q_i, "value": c, "direction": +1 | -1, "energy": E,
     "axes": {"q": q_j, "q_dot": q_j + "_dot", "p": "p_" + q_j},
     "orbits": [{"initial": {...}, "t": [...], "q": [...], "q_dot": [...], "p": [...],
                 "energy_drift": number, "complete": bool}],
     "stats": {"wall_time_s": number, "crossings": int}}

(q_j is the first coordinate other than q_i: the plane's points are (q_j, p_j).)
"""

from __future__ import annotations

import json
import time
from collections.abc import Mapping
from typing import Any

from app.engine.derivation.derive import Derivation
from app.errors import OverCapacity
from app.limits import POINCARE_T_END as DEFAULT_T_END
from app.numerics import limits
from app.numerics.errors import SimulationError
from app.numerics.poincare import hamiltonian, section
from app.service.chapter.compiled import Compiled
from app.service.chapter.derivations import Scenes
from app.service.runtime.cache import Recent
from app.service.runtime.gates import Gates
from app.service.simulations.simulate_request import check_number, initial_state, parameter_vector, setting

COUNT_MAX = 12  # orbits per section
T_END_MAX = 2_000.0  # seconds of simulated time per orbit
DEFAULT_COUNT = 6


def section_of_derivation(
    d: Derivation,
    *,
    parameters: Mapping[str, float] | None = None,
    energy: float | None = None,
    initial: Mapping[str, float] | None = None,
    coordinate: str | None = None,
    value: float = 0.0,
    direction: int = 1,
    count: int = DEFAULT_COUNT,
    t_end: float = DEFAULT_T_END,
    key: str | None = None,
    defaults: Mapping[str, float] | None = None,
    gates: Gates,
    compiled: Compiled,
) -> dict[str, Any]:
    """The section q_coordinate = value of orbits with h = energy (or h at ``initial``); refusals raise SimulationError.

    ``gates``: how many run at once; ``compiled``: where the numeric system is kept (the app's scenes', or a
    worker's)."""
    names = list(d.table.names)
    if len(names) < 2:
        raise SimulationError("a Poincaré section needs at least two coordinates; this system has one", "coordinate")
    coordinate = names[1] if coordinate is None else coordinate
    if coordinate not in names:
        raise SimulationError(f"unknown coordinate {coordinate[:40]!r}; choose one of {', '.join(names)}", "coordinate")
    if direction not in (1, -1):
        raise SimulationError("direction must be 1 (crossing upward) or -1 (downward)", "direction")
    value = check_number(value, "value")
    count = int(setting(count, DEFAULT_COUNT, limits.Range(1, COUNT_MAX), "count"))
    t_end = setting(t_end, DEFAULT_T_END, limits.Range(1e-6, T_END_MAX), "t_end")
    k = parameter_vector(d, parameters or {})
    system, observables = compiled.get(key, d)
    if energy is None:
        y0 = initial_state(d, initial or {}, defaults or {})
        energy = float(hamiltonian(observables, y0, k)[0])
    energy = check_number(energy, "energy")
    if not gates.slots.acquire(timeout=limits.WALL_SECONDS):
        raise OverCapacity("too many simulations are running at once; try again in a few seconds", 2)
    start = time.perf_counter()
    try:
        cut = section(
            system, observables, k, energy, names.index(coordinate), value, direction, count, t_end, limits.WALL_SECONDS
        )
    finally:
        gates.slots.release()
    other = next(n for n in names if n != coordinate)
    j = names.index(other)
    n = len(names)
    return {
        "coordinate": coordinate,
        "value": value,
        "direction": direction,
        "energy": energy,
        "axes": {"q": other, "q_dot": f"{other}_dot", "p": f"p_{other}"},
        "orbits": [
            {
                "initial": {
                    **{q: float(o.start[i]) for i, q in enumerate(names)},
                    **{f"{q}_dot": float(o.start[n + i]) for i, q in enumerate(names)},
                },
                "t": o.t.tolist(),
                "q": o.states[:, j].tolist(),
                "q_dot": o.states[:, n + j].tolist(),
                "p": o.momenta[:, j].tolist(),
                "energy_drift": o.energy_drift,
                "complete": o.complete,
            }
            for o in cut.orbits
        ],
        "stats": {
            "wall_time_s": time.perf_counter() - start,
            "crossings": int(sum(o.t.size for o in cut.orbits)),
        },
    }


def section_of_scene(scene_id: str, gates: Gates, chapter: Scenes, **options: Any) -> dict[str, Any]:
    """A scene's Poincaré section; the energy defaults to h at the scene's initial state.  ``chapter``: the
    app's scenes."""
    from app.service.chapter.derivations import scene

    s = scene(scene_id)
    d = chapter.derivation(scene_id)
    return section_of_derivation(d, key=scene_id, defaults=s.initial, gates=gates, compiled=chapter.compiled, **options)


CACHED_SECTIONS = 32  # the size of the app's ``Recent`` of sections (app/service/answers.py)


def cached_section_of_scene(
    scene_id: str, gates: Gates, remembered: Recent, chapter: Scenes, **options: Any
) -> dict[str, Any]:
    """``section_of_scene`` through ``remembered``, the app's last CACHED_SECTIONS answers (a page asks again
    after each run)."""
    key = json.dumps([scene_id, options], sort_keys=True, default=str)
    return remembered.get(key, lambda: section_of_scene(scene_id, gates, chapter, **options))
