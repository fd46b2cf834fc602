"""A chaotic scene's largest Lyapunov exponent at its default start: measured once, cached, and said in words.

A scene that declares ``lyapunov_seconds`` gets its exponent measured (``app.numerics.lyapunov``) at its
default parameters and start, over that many seconds; the result is computed once per version of the
source (memory, then the disk that set-up filled) and its sentence opens the scene's run note.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from app.engine.display.names import unicode
from app.limits import LYAPUNOV_SECONDS
from app.numerics.errors import TooMuchWork
from app.numerics.lyapunov import largest_exponent
from app.service.chapter.derivations import Scenes, scene
from app.service.runtime.cache import JsonCache, source_fingerprint
from app.service.simulations.simulate_request import parameter_vector
from app.viz.page_model import power_of_ten
from app.viz.units import coordinate_units


def lyapunov_cache(folder: Path | None = None) -> JsonCache:
    """The measured exponents' cache (memory, then disk): the app's services hold one (app/service/answers.py)."""
    return JsonCache("lyapunov", source_fingerprint("engine", "scenes", "numerics"), folder)


def measure_scene(scene_id: str, cache: JsonCache | None, chapter: Scenes) -> dict[str, Any]:
    """The largest Lyapunov exponent of a scene's default start, with how it was measured (computed once, then
    from ``cache``, by default the disk's; ``chapter``: the app's scenes, the process's at image build):
    {"value" (1/s), "t_end", "gap", "every", "settle", "method", "coordinate"}."""
    s = scene(scene_id)

    def compute() -> dict[str, Any]:
        d = chapter.derivation(scene_id)
        system, _ = chapter.system(scene_id)
        q = system.coordinates
        y0 = np.array([s.initial.get(n, 0.0) for n in q] + [s.initial.get(f"{n}_dot", 0.0) for n in q])
        found = largest_exponent(system, parameter_vector(d, {}), y0, s.lyapunov_seconds, LYAPUNOV_SECONDS)
        return {
            "value": found.value, "t_end": found.t_end, "gap": found.gap, "every": found.every,
            "settle": found.settle, "method": found.method, "coordinate": q[0],
        }  # fmt: skip

    return (cache or lyapunov_cache()).get(scene_id, compute)


_SUPERSCRIPT = str.maketrans("-.0123456789", "⁻·⁰¹²³⁴⁵⁶⁷⁸⁹")


def sentence(measured: dict[str, Any], unit: str) -> str:
    """The exponent as the run note says it; ``unit``: the unit of the coordinate the second start moves."""
    rate = f"{measured['value']:.2g}"
    gap = power_of_ten(f"1e{round(math.log10(measured['gap']))}")
    how = (
        f"(Measured at the default parameters by following a second run started with "
        f"{unicode(measured['coordinate'])} larger by {gap} "
        f"{unit}, putting it back at that distance every {measured['every']:g} s and averaging the logarithm of "
        f"the gap's growth over {measured['t_end']:g} s, once the gap has had {measured['settle']:g} s to turn "
        "the way it grows fastest.)"
    )
    if float(rate) <= 0:
        return f"The largest Lyapunov exponent of this start is about {rate} s⁻¹: nearby starts do not part. {how}"
    # the gap grows by e^λ each second
    growth = f"{math.exp(float(rate)):.2g}"
    return (
        f"This start is chaotic: its largest Lyapunov exponent is about {rate} s⁻¹, so the gap between two runs "
        f"whose starts differ in the last digits grows about {growth}-fold each second "
        f"(e{rate.translate(_SUPERSCRIPT)} ≈ {growth}). {how}"
    )


def run_note(scene_id: str, cache: JsonCache | None, chapter: Scenes) -> str:
    """The scene's run note, opened by its measured exponent when the scene asks for one."""
    s = scene(scene_id)
    if not s.lyapunov_seconds:
        return s.run_note
    units = coordinate_units(chapter.document(scene_id), scene=True)["units"]
    unit = units[s.system.coordinates[0]]
    try:
        measured = measure_scene(scene_id, cache, chapter)
    except TooMuchWork:
        # not measured yet and the machine too busy to measure it now: the note without it (nothing is cached,
        # so the next reader's page tries again), never a page that fails
        return s.run_note
    return (sentence(measured, unit) + " " + s.run_note).strip()


def warm_all() -> None:
    """Measure every scene that asks for its exponent (run at set-up, see app.service.warm)."""
    from app.service.chapter.derivations import PROCESS_SCENES, SCENES

    cache = lyapunov_cache()
    for scene_id, s in SCENES.items():
        if s.lyapunov_seconds:
            measure_scene(scene_id, cache, PROCESS_SCENES)
