"""The action of scenes and user systems: checked options in, the documented JSON out.

    {"epsilons": [ε…], "action": [S(ε)…], "true": S(0), "first_variation": dS/dε at 0,
     "second_variation": d²S/dε² at 0, "kind": "minimum" | "saddle" | "maximum",
     "conjugate_time": t* | null, "varied_conjugate_time": the varied coordinate's own focus | null,
     "error_estimate": absolute error of each S,
     "coordinate", "shape", "k", "t_end", "eigenvalues": the second variation on η_1 … η_K,
     "path": {"t", "q", "L"} (the true path's chosen coordinate and L, SHOWN samples),
     "preview": {"lagrangian", "rhs", "coordinates", "parameters"} (L and the equations as browser JavaScript), "warnings": [...]}

The numbers come from ``app.numerics.action`` (no SymPy on a warm system); a refusal is a
SimulationError naming the field, as for a simulation.  A user system's job runs in the worker pool.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from app.engine.derivation.derive import Derivation
from app.limits import DEFAULT_T_END
from app.numerics.action import K_SHAPES, SHAPES, SHOWN, action_of, action_terms
from app.numerics.action_relax import find_path
from app.numerics.errors import SimulationError
from app.numerics.simulate import simulate
from app.service.chapter.compiled import Compiled
from app.service.chapter.derivations import Scenes
from app.service.runtime.cache import Recent
from app.service.runtime.gates import Gates, slot
from app.service.simulations.sentences import as_sentence
from app.service.simulations.simulate_request import check_number, initial_state, parameter_vector

EPSILONS_MAX = 101  # varied paths per request
K_MAX = 50  # the highest sine shape k offered
T_SPAN = 10  # t_end may reach this many times the scene's own run (DEFAULT_T_END for a user system)


def _shown(values: np.ndarray) -> list[float]:
    index = np.linspace(0, values.size - 1, SHOWN).round().astype(int)
    return [float(x) if math.isfinite(x) else math.nan for x in values[index]]


def action_of_derivation(
    d: Derivation,
    *,
    t_end: float,
    epsilons: Sequence[float] = (),
    parameters: Mapping[str, float] | None = None,
    initial: Mapping[str, float] | None = None,
    coordinate: str | None = None,
    shape: str = "sine",
    k: int = 1,
    key: str | None = None,
    defaults: Mapping[str, float] | None = None,
    span: float = DEFAULT_T_END,
    gates: Gates,
    compiled: Compiled,
) -> dict[str, Any]:
    """S(ε) of the varied paths of one coordinate, and what the second variation says; refusals raise SimulationError.

    ``gates``: how many run at once; ``compiled``: where the numeric system is kept (the app's scenes', or a
    worker's)."""
    names = list(d.table.names)
    coordinate = names[0] if coordinate is None else coordinate
    if coordinate not in names:
        raise SimulationError(f"unknown coordinate {coordinate[:40]!r}; choose one of {', '.join(names)}", "coordinate")
    if shape not in SHAPES:
        raise SimulationError(
            f"shape {str(shape)[:40]!r} is not offered; the shapes are {', '.join(SHAPES)} (η = sin(kπt/T))", "shape"
        )
    if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= K_MAX:
        raise SimulationError(f"k must be a whole number from 1 to {K_MAX}", "k")
    limit = T_SPAN * span
    T = check_number(t_end, "t_end")
    if T <= 0:
        raise SimulationError(f"t_end must be positive (the path runs from 0 to t_end); got {T:g}", "t_end")
    if T > limit:
        raise SimulationError(
            f"t_end = {T:g} s is beyond this system's limit for the action, {limit:g} s ({T_SPAN} times its run)",
            "t_end",
        )
    if len(epsilons) > EPSILONS_MAX:
        raise SimulationError(f"too many epsilons ({len(epsilons)}); at most {EPSILONS_MAX} per request", "epsilons")
    eps = [check_number(e, f"epsilons.{i}") for i, e in enumerate(epsilons)]
    kv = parameter_vector(d, parameters or {})
    y0 = initial_state(d, initial or {}, defaults or {})
    system, _ = compiled.get(key, d)
    with slot(gates.slots, "too many simulations are running at once; try again in a few seconds"):
        result = action_of(
            system, kv, y0, T, names.index(coordinate), k, eps, wait_for_compile=not gates.answer_while_compiling
        )
    c = names.index(coordinate)
    terms = action_terms(system)
    return {
        "epsilons": result.epsilons,
        "action": result.action,
        "true": result.true,
        "first_variation": result.first_variation,
        "second_variation": result.second_variation,
        "kind": result.kind,
        "conjugate_time": result.conjugate_time,
        "varied_conjugate_time": result.varied_conjugate_time,
        "error_estimate": result.error_estimate,
        "coordinate": coordinate,
        "shape": shape,
        "k": k,
        "t_end": T,
        "shapes_checked": K_SHAPES,
        "eigenvalues": result.hessian_eigenvalues,
        "path": {
            "t": _shown(result.path.t),
            "q": _shown(result.path.y[:, c]),
            "L": _shown(result.L),
            "method": result.path.method,
        },
        "preview": {
            "lagrangian": terms.browser,
            "rhs": system.browser,
            "coordinates": names,
            "parameters": list(system.parameter_names),
        },
        "warnings": [as_sentence(w) for w in result.warnings],
    }


STEPS_DEFAULT = 200  # steps of a relaxed path (and twice as many for its extrapolation)
STEPS_MAX = 1000
FRAMES = 12  # iterates of the relaxation returned for the page's animation


def _ends(d: Derivation, given: Mapping[str, float] | None, fallback: np.ndarray, where: str) -> np.ndarray:
    names = list(d.table.names)
    given = given or {}
    unknown = sorted(set(given) - set(names))
    if unknown:
        raise SimulationError(
            f"unknown coordinate {unknown[0][:40]!r} in {where}; choose among {', '.join(names)}", where
        )
    return np.array([check_number(given.get(q, fallback[i]), f"{where}.{q}") for i, q in enumerate(names)])


def relax_of_derivation(
    d: Derivation,
    *,
    t_end: float,
    parameters: Mapping[str, float] | None = None,
    initial: Mapping[str, float] | None = None,
    start: Mapping[str, float] | None = None,
    end: Mapping[str, float] | None = None,
    trial: Mapping[str, Sequence[float]] | None = None,
    steps: int = STEPS_DEFAULT,
    key: str | None = None,
    defaults: Mapping[str, float] | None = None,
    span: float = DEFAULT_T_END,
    gates: Gates,
    compiled: Compiled,
) -> dict[str, Any]:
    """The path between two fixed ends that makes the discrete action stationary, beside the shooting solution.

    The ends default to those of the true path from ``initial``; the trial path to the straight line."""
    names = list(d.table.names)
    T = check_number(t_end, "t_end")
    if not 0 < T <= T_SPAN * span:
        raise SimulationError(f"t_end must be in (0, {T_SPAN * span:g}] s; got {T:g}", "t_end")
    if isinstance(steps, bool) or not isinstance(steps, int) or not 4 <= steps <= STEPS_MAX:
        raise SimulationError(f"steps must be a whole number from 4 to {STEPS_MAX}", "steps")
    kv = parameter_vector(d, parameters or {})
    system, _ = compiled.get(key, d)
    terms = action_terms(system)
    n = system.n
    with slot(gates.slots, "too many simulations are running at once; try again in a few seconds"):
        y0 = initial_state(d, initial or {}, defaults or {})
        if start is None or end is None:
            run = simulate(system, kv, y0, T, 2, rtol=1e-12, atol=1e-14, estimate=False).trajectory
            if not run.complete:
                raise SimulationError("the true path from this start does not reach t_end; give start and end", "t_end")
            ends = run.y[0, :n], run.y[-1, :n]
        else:
            ends = (np.zeros(n), np.zeros(n))
        q0 = _ends(d, start, ends[0], "start")
        q1 = _ends(d, end, ends[1], "end")
        path = np.linspace(q0, q1, steps + 1).T
        for q, values in (trial or {}).items():
            if q not in names:
                raise SimulationError(
                    f"unknown coordinate {q[:40]!r} in trial; choose among {', '.join(names)}", "trial"
                )
            if len(values) != steps + 1:
                raise SimulationError(
                    f"trial.{q} must hold steps + 1 = {steps + 1} values (even times 0 … t_end)", "trial"
                )
            path[names.index(q)] = [check_number(v, f"trial.{q}") for v in values]
        # shooting may also start from the true path's q̇(0) (the panel's ends are near the true path's)
        found = find_path(system, terms, kv, q0, q1, T, path, velocities=(np.asarray(y0[n:], dtype=float),))
    frames = found.coarse.iterations
    chosen = sorted({round(i) for i in np.linspace(0, len(frames) - 1, min(FRAMES, len(frames)))})

    def by_name(Q: np.ndarray) -> dict[str, list[float]]:
        return {q: Q[i].tolist() for i, q in enumerate(names)}

    shooting = None
    if found.shot is not None and found.velocity is not None:
        shooting = {
            "velocity": {f"{q}_dot": float(found.velocity[i]) for i, q in enumerate(names)},
            "q": by_name(found.shot),
        }
    return {
        "found": found.found,
        "reasons": found.reasons,
        "advice": advice(found.reasons, shooting is not None),
        "t": found.coarse.t.tolist(),
        "q": by_name(found.q),
        "iterations": [by_name(frames[i]) for i in chosen],
        "kind": found.fine.kind,
        "negative_directions": found.fine.negative,
        "converged": found.coarse.converged and found.fine.converged,
        "residual": max(found.coarse.gradient, found.fine.gradient),
        "error_estimate": found.error_estimate,
        "action": found.fine.action,
        "shooting": shooting,
        "difference": found.difference,
        "steps": steps,
    }


def advice(reasons: Sequence[str], shot: bool) -> list[str]:
    """What to try when the relaxed path is not the true one, as codes the page words:

    "closer-trial" (a trial path nearer the true one: a smaller ε), "shorter-t" (a shorter T: fewer stationary
    paths, a Newton start nearer one), "from-shooting" (relax from the shooting solution, when there is one)."""
    if not reasons:
        return []
    tips = ["shorter-t"] if reasons == ["no-shooting"] or reasons == ["too-coarse"] else ["closer-trial", "shorter-t"]
    return tips + (["from-shooting"] if shot else [])


def _of_scene(
    compute: Callable[..., dict[str, Any]],
    scene_id: str,
    gates: Gates,
    options: dict[str, Any],
    chapter: Scenes,
):
    """``compute`` (the action, or a relaxed path) on a chapter scene: its derivation, defaults and run length,
    from ``chapter`` (the app's scenes)."""
    from app.service.chapter.derivations import scene

    s = scene(scene_id)
    d = chapter.derivation(scene_id)
    return compute(d, key=scene_id, defaults=s.initial, span=s.t_end, gates=gates, compiled=chapter.compiled, **options)


def relax_of_scene(scene_id: str, gates: Gates, chapter: Scenes, **options: Any) -> dict[str, Any]:
    return _of_scene(relax_of_derivation, scene_id, gates, options, chapter)


def action_of_scene(scene_id: str, gates: Gates, chapter: Scenes, **options: Any) -> dict[str, Any]:
    return _of_scene(action_of_derivation, scene_id, gates, options, chapter)


CACHED_ANSWERS = 64  # the size of the app's ``Recent`` of actions (app/service/answers.py)


def cached_action_of_scene(
    scene_id: str, gates: Gates, remembered: Recent, chapter: Scenes, **options: Any
) -> dict[str, Any]:
    """``action_of_scene`` through ``remembered``, the app's last CACHED_ANSWERS answers (a panel asks again
    for the same T)."""
    key = json.dumps([scene_id, options], sort_keys=True, default=str)
    return remembered.get(key, lambda: action_of_scene(scene_id, gates, chapter, **options))
