"""Normal modes measured: predicted against measured frequencies from small-amplitude simulations.

For each equilibrium at rest with an oscillating mode (``app.viz.panels.oscillating_equilibria``
of the derivation document) and each of its modes with omega^2 > 0, the system starts at the
equilibrium displaced by a small amplitude along the mode's shape, at rest; it then moves in that
mode alone (to first order in the amplitude), and the period of the largest component, measured
over CYCLES cycles, gives the measured omega.  Numbers are at the default parameters, like the
engine's.  A scene's result is computed once (memory and disk cache); a user system's runs in the
worker pool (``app.service.user_systems``).

    [{"equilibrium": {q: x}, "kind": str,
      "modes": [{"omega_squared", "predicted", "measured", "relative_difference", "amplitude"}]}]
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from app.engine.derive import Derivation
from app.errors import OverCapacity
from app.numerics import limits
from app.numerics.frequency import measured_omega
from app.numerics.simulate import simulate
from app.service.cache import JsonCache, source_fingerprint
from app.service.simulation import COMPILED, GATES, Gates, parameter_vector
from app.viz.panels import oscillating_equilibria

AMPLITUDE = 1e-4  # of the largest component, in the coordinate's own unit
CYCLES = 20  # of the mode measured
SAMPLES_PER_CYCLE = 200

_cache = JsonCache("modes-measured", source_fingerprint("engine", "scenes", "numerics", "viz", "service"))


def measure(
    d: Derivation,
    doc: Mapping[str, Any],
    key: str | None = None,
    forces: Sequence[dict[str, Any]] = (),
    gates: Gates = GATES,
) -> list[dict[str, Any]]:
    """Predicted and measured omega of every oscillating mode at every equilibrium at rest."""
    names = list(d.table.names)
    n = len(names)
    k = parameter_vector(d, {})
    system, _ = COMPILED.get(key, d, forces)
    out = []
    for e in oscillating_equilibria(dict(doc)):
        modes = []
        for m in e["modes"]:
            w2 = m["omega_squared"]
            entry: dict[str, Any] = {"omega_squared": w2, "predicted": math.sqrt(w2) if w2 > 0 else None}
            entry.update(measured=None, relative_difference=None, amplitude=AMPLITUDE)
            if w2 > 0:
                y0 = np.zeros(2 * n)
                for i, q in enumerate(names):
                    y0[i] = e["equilibrium"].get(q, 0.0) + AMPLITUDE * m["shape"].get(q, 0.0)
                omega = math.sqrt(w2)
                t_end = CYCLES * 2 * math.pi / omega
                if not gates.slots.acquire(timeout=limits.WALL_SECONDS):
                    raise OverCapacity("too many simulations are running at once; try again in a few seconds", 2)
                try:
                    run = simulate(
                        system, k, y0, t_end, CYCLES * SAMPLES_PER_CYCLE, "DOP853-compiled",
                        rtol=1e-11, atol=1e-14, estimate=False,
                    )  # fmt: skip
                finally:
                    gates.slots.release()
                # the largest component of the shape oscillates most clearly
                big = max(m["shape"], key=lambda q: abs(m["shape"][q]))
                i = names.index(big)
                x = run.trajectory.y[:, i] - e["equilibrium"].get(big, 0.0)
                measured = measured_omega(run.trajectory.t, x)
                if measured is not None:
                    entry["measured"] = float(measured)
                    entry["relative_difference"] = float(measured / omega - 1)
            modes.append(entry)
        out.append({"equilibrium": e["equilibrium"], "kind": e["kind"], "modes": modes})
    return out


def measure_scene(scene_id: str, gates: Gates = GATES) -> list[dict[str, Any]]:
    """A scene's measured modes (computed once, then from the cache)."""
    from app.service.derivations import derivation, derivation_document

    doc = derivation_document(scene_id)
    return _cache.get(
        scene_id, lambda: measure(derivation(scene_id), doc, scene_id, doc.get("constraint_forces") or [], gates)
    )


def warm_all() -> None:
    """Measure every scene that has an equilibrium with an oscillating mode (run at set-up, see app.service.warm)."""
    from app.service.derivations import SCENES, derivation_document

    for scene_id in SCENES:
        if oscillating_equilibria(derivation_document(scene_id)):
            measure_scene(scene_id)
