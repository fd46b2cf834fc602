"""The simulation document: the series along a trajectory, their drifts, the run's stats and its trust."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from app.numerics.observables import Observables, summarize
from app.numerics.system import NumericSystem
from app.service.simulations.rounding import as_series
from app.service.simulations.sentences import as_sentence
from app.service.simulations.trust import judge


@dataclass
class Observed:
    """What a document carries of a finished trajectory besides its stats: the series (rounded as asked),
    their drifts (``summarize``'s figures and warnings) and whether every series is finite."""

    series: dict[str, Any]
    summary: dict[str, Any]
    finite: bool


def observe(
    system: NumericSystem, observables: Observables, trajectory, k: np.ndarray, rtol: float, precision: str
) -> Observed:
    """The state, energy, h, conserved quantities and constraint forces along a trajectory, and their drifts."""
    tr = trajectory
    n = system.n
    values = observables.evaluate(tr.t, tr.y, k)
    state: dict[str, np.ndarray] = {}
    for i, q in enumerate(system.coordinates):
        state[q] = as_series(tr.y[:, i], precision)
        state[f"{q}_dot"] = as_series(tr.y[:, n + i], precision)
    # quantities whose change since t = 0 is plotted keep every digit (rounded, the change is a staircase)
    conserved = {c: as_series(values[f"conserved:{c}"]) for c in system.conserved}
    forces = {f.constraint.name: as_series(values[f"force:{i}"], precision) for i, f in enumerate(observables.forces)}
    series = {
        "t": as_series(tr.t),
        "state": state,
        "energy": as_series(values["energy"]),
        "hamiltonian": as_series(values["hamiltonian"]),
        "conserved": conserved,
        "constraint_forces": forces,
    }
    finite = all(np.isfinite(one).all() for one in (*state.values(), *conserved.values()))
    return Observed(series, summarize(observables, tr.t, values, rtol), finite)


def document(
    system: NumericSystem,
    observables: Observables,
    outcome,
    k: np.ndarray,
    rtol: float,
    precision: str = "full",
    observed: Observed | None = None,
) -> dict[str, Any]:
    """The result document; ``precision="display"`` rounds the state and forces (never ``stats``, E, h or the
    conserved momenta, whose changes are plotted) to DISPLAY_DIGITS.  ``observed``: the series already made
    of the outcome's trajectory (while the reference ran, see simulate_derivation); else they are made here."""
    tr = outcome.trajectory
    if observed is None:
        observed = observe(system, observables, tr, k, rtol, precision)
    summary = dict(observed.summary)
    warnings = [*outcome.warnings, *summary.pop("warnings")]
    est = outcome.estimate
    stats = {
        "method": outcome.method,
        "reason": outcome.reason,
        "path": outcome.path,
        "steps": tr.steps,
        "rhs_evaluations": tr.rhs_evaluations,
        "wall_time_s": tr.wall_time_s,
        "error_estimate": est.value if est and math.isfinite(est.value) else None,
        "error_estimate_by_coordinate": est.by_coordinate if est else {},
        "error_reference": est.reference if est else None,
        **summary,
        "complete": tr.complete,
        "t_end_reached": tr.t_reached,
        "step_size": tr.step_size,
        "stiffness": outcome.analysis.as_dict(),
        "compile_time_s": outcome.compile_seconds,
        "notes": tr.notes,
        "warnings": warnings,
        # the terminal event that ended the run (its name, time and what it means), or null
        "event": outcome.event.as_json() if outcome.event is not None else None,
    }
    if not observed.finite:
        warnings.append("some values are not finite (the motion reached a singular point); they are null")
    # each warning is served as a sentence a reader can take on its own
    stats["warnings"] = [as_sentence(w) for w in warnings]
    return {
        **observed.series,
        "stats": _finite(stats),
        "trust": _finite(
            judge(stats["error_estimate"], stats["error_estimate_by_coordinate"], system.coordinates, tr.y)
        ),
        # the same right-hand side as JavaScript: the page integrates a preview while an input moves
        "preview": {
            "rhs": system.browser,
            "coordinates": list(system.coordinates),
            "parameters": list(system.parameter_names),
        },
    }


def _finite(value: Any) -> Any:
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_finite(v) for v in value]
    return value
