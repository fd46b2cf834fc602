"""Normal modes measured: predicted against measured frequencies from small-amplitude simulations.

For each equilibrium at rest with an oscillating mode (``at_rest``, read from the derivation's
typed ``normal_modes`` member) and each of its modes with omega^2 > 0, the system starts at the
equilibrium displaced by a small amplitude along the mode's shape, at rest; it then moves in that
mode alone (to first order in the amplitude), and the period of the largest component, measured
over CYCLES cycles, gives the measured omega.  A scene's result at the default parameters is
computed once (memory and disk cache); a user system's runs in the worker pool
(``app.service.users.user_systems``) at its declared values.

A scene's modes also follow the page's sliders (``modes_at``): the engine's ``normal_modes``
gives every equilibrium at rest in closed form, its position and its M and K as expressions of
the parameters; these are turned into numeric functions once per scene, so that a new set of
parameter values costs an evaluation and a small eigenproblem, (K - omega^2 M) a = 0, then the
measurement above.  An equilibrium found only numerically (at the defaults) cannot follow; it is
reported with ``"at_defaults": true``.

    [{"equilibrium": {q: x}, "kind": str, "parameters": {name: value},
      "modes": [{"omega_squared", "shape", "predicted", "measured", "relative_difference", "amplitude"}]}]
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
import sympy as sp

from app import late
from app.engine.algebra.budget import Skipped
from app.engine.derivation.derive import Derivation
from app.engine.document.contract import held_momenta
from app.engine.equilibria.modes import NormalModes
from app.errors import OverCapacity
from app.numerics import limits
from app.numerics.frequency import measured_omega
from app.numerics.simulate import simulate
from app.service.chapter.compiled import Compiled
from app.service.chapter.derivations import Scenes
from app.service.runtime.cache import JsonCache, Recent, source_fingerprint
from app.service.runtime.gates import Gates
from app.service.simulations.simulate_request import parameter_vector

AMPLITUDE = 1e-4  # of the largest component, in the coordinate's own unit
CYCLES = 20  # of the mode measured
SAMPLES_PER_CYCLE = 200


def measured_cache(folder: Path | None = None) -> JsonCache:
    """The measured modes' cache (memory, then disk): the app's services hold one (app/service/answers.py)."""
    return JsonCache("modes-measured", source_fingerprint("engine", "scenes", "numerics", "viz", "service"), folder)


@dataclass(frozen=True)
class AtRest:
    """An equilibrium at rest with its modes, as measured: position, kind, (omega^2, shape) per mode."""

    equilibrium: dict[str, float]
    kind: str
    modes: tuple[tuple[float, dict[str, float]], ...]
    at_defaults: bool = False  # found numerically at the declared values only


def at_rest(nm: NormalModes | Skipped) -> list[AtRest]:
    """The engine's equilibria at rest (not steady motions of a reduction) with at least one oscillating mode."""
    if isinstance(nm, Skipped):
        return []
    return [
        AtRest(dict(e.position), e.kind, tuple((m.omega_squared, dict(zip(e.coordinates, m.shape, strict=True)))
                                                for m in e.modes))
        for e in nm.equilibria
        if e.stable and not e.momenta and any(m.omega_squared > 0 for m in e.modes)
    ]  # fmt: skip


def measure(
    d: Derivation,
    *,
    gates: Gates,
    compiled: Compiled,
    key: str | None = None,
    parameters: Mapping[str, float] | None = None,
) -> list[dict[str, Any]]:
    """``measured`` of a derivation's own normal modes (a user system's, in a worker): no momentum is held, as
    its document's are printed (the same member, computed once per derivation)."""
    return measured(d, at_rest(d.normal_modes({})), gates=gates, compiled=compiled, key=key, parameters=parameters)


def measured(
    d: Derivation,
    equilibria: Sequence[AtRest],
    *,
    gates: Gates,
    compiled: Compiled,
    key: str | None = None,
    parameters: Mapping[str, float] | None = None,
) -> list[dict[str, Any]]:
    """Predicted and measured omega of every oscillating mode at every equilibrium at rest.

    ``equilibria`` are at ``parameters`` (default: the declared values); ``compiled``: where the numeric
    system is kept (the app's scenes', or a worker's)."""
    names = list(d.table.names)
    n = len(names)
    k = parameter_vector(d, parameters or {})
    used = dict(zip((p.name for p in d.system.parameters), map(float, k), strict=True))
    system, _ = compiled.get(key, d)
    out = []
    for e in equilibria:
        modes = []
        for w2, shape in e.modes:
            entry: dict[str, Any] = {"omega_squared": w2, "shape": dict(shape)}
            entry["predicted"] = math.sqrt(w2) if w2 > 0 else None
            entry.update(measured=None, relative_difference=None, amplitude=AMPLITUDE)
            if w2 > 0:
                y0 = np.zeros(2 * n)
                for i, q in enumerate(names):
                    y0[i] = e.equilibrium.get(q, 0.0) + AMPLITUDE * shape.get(q, 0.0)
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
                big = max(shape, key=lambda q: abs(shape[q]))
                i = names.index(big)
                x = run.trajectory.y[:, i] - e.equilibrium.get(big, 0.0)
                found_omega = measured_omega(run.trajectory.t, x)
                if found_omega is not None:
                    entry["measured"] = float(found_omega)
                    entry["relative_difference"] = float(found_omega / omega - 1)
            modes.append(entry)
        found: dict[str, Any] = {"equilibrium": e.equilibrium, "kind": e.kind, "parameters": used, "modes": modes}
        if e.at_defaults:
            found["at_defaults"] = True
        out.append(found)
    return out


def scene_modes(scene_id: str) -> NormalModes | Skipped:
    """A scene's normal modes as its document shows them (its conserved momenta held at the initial state)."""
    from app.service.chapter.derivations import derivation, scene

    d = derivation(scene_id)
    return d.normal_modes(held_momenta(d, scene(scene_id)))


# omega^2 within this fraction of the largest |omega^2| counts as zero (the engine's classification)
ZERO = 1e-9


def _kind(omega_squared: Sequence[float]) -> str:
    scale = max([abs(w) for w in omega_squared] + [1e-300])
    if any(w < -ZERO * scale for w in omega_squared):
        return "unstable"
    if any(abs(w) <= ZERO * scale for w in omega_squared):
        return "neutral"
    return "stable"


def _eigen(M: np.ndarray, K: np.ndarray) -> list[dict[str, Any]] | None:
    """(K - omega^2 M) a = 0: omega^2 ascending, each shape scaled so its largest component is 1."""
    if not (np.all(np.isfinite(M)) and np.all(np.isfinite(K))) or abs(np.linalg.det(M)) < 1e-12:
        return None
    w2, vectors = late.module("scipy.linalg").eig(K, M)
    order = np.argsort(w2.real)
    out = []
    for i in order:
        a = vectors[:, i].real
        a = a / a[np.argmax(np.abs(a))]
        out.append(
            {"omega_squared": float(w2[i].real), "shape": [float(x) + 0.0 for x in np.where(abs(a) < 1e-12, 0, a)]}
        )
    return out


@lru_cache(maxsize=64)
def _parametric(scene_id: str) -> tuple[tuple[str, ...], list[tuple[Callable[..., Any] | None, Any, Any, dict]]]:
    """Each equilibrium at rest of a scene as numeric functions of the parameters: (position, M, K, at defaults).

    Built once per scene from the engine's closed forms (the scene is fixed, so this SymPy work
    does not depend on what a user sends)."""
    from app.service.chapter.derivations import derivation

    d = derivation(scene_id)
    params = list(d.table.params)
    names = tuple(d.table.names)
    out: list[tuple[Callable[..., Any] | None, Any, Any, dict]] = []
    nm = scene_modes(scene_id)
    for e in nm.equilibria if not isinstance(nm, Skipped) else ():
        if e.momenta or tuple(e.coordinates) != names:
            continue  # a relative equilibrium of a reduction: not a state at rest
        if e.exact is None or e.mass.free_symbols - set(params) or e.stiffness.free_symbols - set(params):
            out.append((None, None, None, dict(e.position)))  # numeric only, at the default values
            continue
        position = sp.lambdify(params, [sp.sympify(e.exact.get(n, 0)) for n in names], "numpy", dummify=True)
        M = sp.lambdify(params, e.mass, "numpy", dummify=True)
        K = sp.lambdify(params, e.stiffness, "numpy", dummify=True)
        out.append((position, M, K, dict(e.position)))
    return names, out


def predicted_at(scene_id: str, d: Derivation, k: np.ndarray) -> list[AtRest]:
    """The scene's oscillating equilibria at rest with their modes at the parameter vector ``k``."""
    names, equilibria = _parametric(scene_id)
    defaults = np.array([p.default for p in d.system.parameters], dtype=float)
    out: list[AtRest] = []
    oscillating = at_rest(scene_modes(scene_id))
    for position, M, K, at_defaults in equilibria:
        if position is None:
            if not np.allclose(k, defaults):
                continue  # found numerically at the defaults: it says nothing about these values
            same = [e for e in oscillating if e.equilibrium == at_defaults]
            out.extend(AtRest(e.equilibrium, e.kind, e.modes, at_defaults=True) for e in same)
            continue
        with np.errstate(all="ignore"):
            x = np.asarray(position(*k), dtype=complex)
            if np.any(abs(x.imag) > 1e-12 * np.maximum(1, abs(x.real))) or not np.all(np.isfinite(x.real)):
                continue  # this root is not real at these values
            modes = _eigen(np.asarray(M(*k), dtype=float), np.asarray(K(*k), dtype=float))
        if modes is None:
            continue  # M singular there: a coordinate singularity, no modes
        kind = _kind([m["omega_squared"] for m in modes])
        if kind == "unstable" or not any(m["omega_squared"] > 0 for m in modes):
            continue  # no mode oscillates about it
        out.append(
            AtRest(
                dict(zip(names, map(float, x.real), strict=True)), kind,
                tuple((m["omega_squared"], dict(zip(names, m["shape"], strict=True))) for m in modes),
            )
        )  # fmt: skip
    return out


AT_CACHE_SIZE = 256  # the size of the app's ``Recent`` of modes at given values (app/service/answers.py)


def modes_at(
    scene_id: str,
    parameters: Mapping[str, float],
    gates: Gates,
    remembered: Recent | None,
    chapter: Scenes,
) -> list[dict[str, Any]]:
    """A scene's modes, predicted and measured, at the given parameter values (the rest at their defaults),
    through ``remembered`` (the app's recent answers) when given; ``chapter``: the app's scenes."""
    d = chapter.derivation(scene_id)
    k = parameter_vector(d, parameters)  # refuses unknown names and values out of range

    def compute() -> list[dict[str, Any]]:
        given = dict(zip((p.name for p in d.system.parameters), map(float, k), strict=True))
        equilibria = predicted_at(scene_id, d, k)
        return measured(d, equilibria, gates=gates, compiled=chapter.compiled, key=scene_id, parameters=given)

    return compute() if remembered is None else remembered.get((scene_id, tuple(map(float, k))), compute)


def measure_scene(scene_id: str, gates: Gates, cache: JsonCache | None, chapter: Scenes) -> list[dict[str, Any]]:
    """A scene's measured modes (computed once, then from ``cache``, by default the disk's); ``chapter``: the
    app's scenes (the process's at image build)."""

    def compute() -> list[dict[str, Any]]:
        d = chapter.derivation(scene_id)
        return measured(d, at_rest(scene_modes(scene_id)), gates=gates, compiled=chapter.compiled, key=scene_id)

    return (cache or measured_cache()).get(scene_id, compute)


def warm_all() -> None:
    """Measure every scene that has an equilibrium with an oscillating mode (run at set-up, see app.service.warm)."""
    from app.service.chapter.derivations import PROCESS_SCENES, SCENES

    cache, gates = measured_cache(), Gates()  # a script's: in line, compiled first
    for scene_id in SCENES:
        if at_rest(scene_modes(scene_id)):
            measure_scene(scene_id, gates, cache, PROCESS_SCENES)
            _parametric(scene_id)  # the closed forms the sliders' modes are evaluated from
