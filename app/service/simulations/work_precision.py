"""Error against run time for a scene: several methods over a tolerance sweep, cached per scene.

For each method and rtol (atol = rtol / 1000) the scene's default motion is
integrated to t_end.  The error is max_k |q_k(t_end) - q_k,ref(t_end)|, with the
reference an exact solution where one is known (the pendulum's Jacobi-elliptic
solution, constant-acceleration motion) or else the compiled DOP853 at rtol =
1e-13, whose own error is checked against Gauss-Legendre (order 6) at a step
fine enough for round-off level: the two agree to within the stated amount.
Time is the minimum over several runs after a warm-up run (one run when a
single run takes longer than ``REPEAT_BELOW`` seconds).
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import numpy as np

from app.limits import RUN_SECONDS
from app.numerics.errors import TooMuchWork
from app.numerics.exact import exact_solution
from app.numerics.methods import METHODS, NONSTIFF, STIFF, Problem, symplectic_for
from app.service.chapter.derivations import PROCESS_SCENES, derivation, scene
from app.service.runtime.cache import JsonCache, source_fingerprint

SWEEP = [10.0**-e for e in range(3, 13)]
SCIPY_METHODS = ["DOP853", "RK45", "Radau", "LSODA"]
REPEATS = 3
REPEAT_BELOW = 0.25  # seconds
BOUND = 1.0e8


def report_cache(folder: Path | None = None) -> JsonCache:
    """The reports' cache (memory, then disk): the app's services hold one (app/service/answers.py)."""
    return JsonCache("work-precision", source_fingerprint("engine", "scenes", "numerics"), folder)


def _problem(system, k, y0, t_end, rtol, seconds) -> Problem:
    m = y0.size
    return Problem(
        system,
        k,
        y0,
        np.array([0.0, t_end]),
        rtol,
        np.full(m, rtol * 1e-3),
        np.full(m, BOUND),
        time.perf_counter() + seconds,
        50_000_000,
    )


def _reference(system, k, y0, t_end) -> tuple[np.ndarray, str]:
    exact = exact_solution(system, k, y0)
    if exact is not None:
        solution, label = exact
        return solution(np.array([t_end]))[0], label
    n = system.n
    dop = METHODS["DOP853-compiled"].integrate(_problem(system, k, y0, t_end, 1e-13, 30.0))
    gl_problem = _problem(system, k, y0, t_end, 1e-12, 30.0)
    gl = METHODS["Gauss-Legendre"].integrate(gl_problem)
    check = float(np.max(np.abs(dop.y[-1, :n] - gl.y[-1, :n])))
    label = (
        f"no exact solution is known here: reference = compiled DOP853 at rtol = 1e-13; checked against "
        f"Gauss-Legendre (order 6, h = {gl.step_size:.3g} s), the two final states differ by {check:.2g}, "
        "so errors below about that size are not resolved"
    )
    return dop.y[-1], label


def methods_for(system) -> list[str]:
    # the compiled Radau IIA beside scipy's (the same scheme): what compiling the step loop buys
    symplectic = symplectic_for(system)
    return [NONSTIFF, *([symplectic.name] if symplectic is not None else []), STIFF, *SCIPY_METHODS]


def compute(scene_id: str, sweep: list[float] | None = None, methods: list[str] | None = None) -> dict[str, Any]:
    s = scene(scene_id)
    d = derivation(scene_id)
    system, _ = PROCESS_SCENES.compiled.get(scene_id, d)
    system.compiled()
    k = np.array([p.default for p in s.system.parameters], dtype=float)
    names = list(system.coordinates)
    y0 = np.array([s.initial.get(q, 0.0) for q in names] + [s.initial.get(f"{q}_dot", 0.0) for q in names])
    t_end = s.t_end
    ref, label = _reference(system, k, y0, t_end)
    n = system.n
    runs = []
    for name in methods or methods_for(system):
        method = METHODS[name]
        method.prepare(system)  # compiling (or loading from the disk cache) is not the method's run time
        skipping = False
        for rtol in sweep or SWEEP:
            if skipping:
                runs.append(_skipped(name, rtol, "skipped: a looser tolerance already exceeded the time budget"))
                continue
            try:
                first = method.integrate(_problem(system, k, y0, t_end, rtol, RUN_SECONDS))
            except TooMuchWork:
                runs.append(_skipped(name, rtol, f"over the {RUN_SECONDS:g} s budget for one run"))
                skipping = True
                continue
            times = [first.wall_time_s]
            if first.wall_time_s < REPEAT_BELOW:
                for _ in range(REPEATS):
                    try:
                        times.append(method.integrate(_problem(system, k, y0, t_end, rtol, RUN_SECONDS)).wall_time_s)
                    except TooMuchWork:  # a busy moment of the machine (e.g. compiling beside it): keep what ran
                        break
                times = times[1:] or times  # the first run was the warm-up
            error = float(np.max(np.abs(first.y[-1, :n] - ref[:n]))) if first.complete else None
            runs.append(
                {
                    "method": name,
                    "rtol": rtol,
                    "error": error,
                    "wall_time_s": min(times),
                    "rhs_evaluations": first.rhs_evaluations,
                    "steps": first.steps,
                    "timed_runs": len(times),
                }
            )
            if first.wall_time_s > RUN_SECONDS / 2:
                skipping = True
    return {
        "scene": scene_id,
        "t_end": t_end,
        "reference": label,
        "error_measure": "max over coordinates of |q(t_end) - q_ref(t_end)|",
        "timing": f"minimum of {REPEATS} runs after a warm-up run (one run when it takes over {REPEAT_BELOW} s)",
        "runs": runs,
    }


def _skipped(name: str, rtol: float, note: str) -> dict[str, Any]:
    return {"method": name, "rtol": rtol, "error": None, "wall_time_s": None, "rhs_evaluations": None, "note": note}


def for_scene(scene_id: str, cache: JsonCache | None = None) -> dict[str, Any]:
    """The scene's work-precision data through ``cache`` (memory and disk, by default the disk's: computed once
    per engine/numerics version)."""
    scene(scene_id)
    return (cache or report_cache()).get(scene_id, lambda: compute(scene_id))


def warm_all() -> None:
    from app.scenes import SCENES

    cache = report_cache()
    for scene_id in SCENES:
        for_scene(scene_id, cache)


if __name__ == "__main__":
    warm_all()
