"""Simulations of scenes and of user systems: one entry point from the request to the JSON result.

``simulate_derivation`` is the one entry point: the scene route calls it with
a scene's derivation, the user-system worker with a user's.  It checks the
request against the system's declared ranges (``simulate_request``), takes
(once per system and process) the numeric functions (``compiled``), waits for
a slot (``gates``), runs the plan where it belongs (``simulation_run``) and
returns the documented JSON:

    {"t", "state": {q, q_dot}, "energy", "hamiltonian", "conserved": {name: [...]},
     "constraint_forces": {name: [...]}, "stats": {...}}
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from contextlib import ExitStack
from typing import TYPE_CHECKING, Any

import numpy as np

from app.engine.derivation.derive import Derivation
from app.engine.equations.constraints import ConstraintForce
from app.limits import DEFAULT_T_END
from app.numerics import limits, methods
from app.numerics.errors import SimulationError
from app.numerics.methods import AUTO
from app.numerics.plan import Plan, plan
from app.numerics.simulate import Outcome
from app.numerics.start import why_not_at_start
from app.scenes import SCENES, Scene
from app.service.chapter.compiled import Compiled
from app.service.runtime.cores import CORES
from app.service.runtime.gates import SLOTS, Gates
from app.service.simulations.scene_jobs import load_scenes, run_scene_plan
from app.service.simulations.simulate_request import (
    SimulationInput,
    initial_state,
    parameter_vector,
    setting,
)
from app.service.simulations.simulation_result import document, observe
from app.service.simulations.simulation_run import run_served, steps_in_python
from app.service.simulations.warm_kernels import start_warming, warm_all
from app.settings import settings

if TYPE_CHECKING:
    from app.service.chapter.derivations import Scenes

# Where the pieces live (simulation.py was split by idea): the request's checks (simulate_request), display
# rounding (rounding), the gates and the in-flight count (gates), the compiled systems (compiled), the result
# document (simulation_result), the warm-up (warm_kernels) and the scenes' worker jobs (scene_jobs). The app's
# start, its services and the worker pool name these through this module:
__all__ = [
    "SLOTS", "Gates", "load_scenes", "simulate_derivation", "simulate_scene", "start_warming", "warm_all",
]  # fmt: skip

HEAVY_SPAN = 10  # times the scene's t_end (or the default 10 s)
HEAVY_RTOL = 1e-9


def simulate_derivation(
    derivation: Derivation,
    request: SimulationInput,
    *,
    gates: Gates,
    compiled: Compiled,
    constraint_forces: Sequence[ConstraintForce] | None = None,
    scene_id: str | None = None,
) -> dict[str, Any]:
    """Simulate a derived system as the request asks; a refusal raises SimulationError, a full server OverCapacity.

    ``gates``: how many run at once (the app's, or a worker's own); ``compiled``: where its numeric system is
    kept (the app's scenes', or the worker's); ``constraint_forces``: the forces observed along the run (by
    default the derivation's own)."""
    scene: Scene | None = SCENES.get(scene_id) if scene_id else None
    k = parameter_vector(derivation, request.parameters or {})
    y0 = initial_state(derivation, request.initial or {}, scene.initial if scene else {})
    # the ranges the API's schema documents (limits.RANGES): a caller without the schema is held to them too
    ranges = limits.RANGES
    t_end = setting(request.t_end, scene.t_end if scene else DEFAULT_T_END, ranges["t_end"], "t_end")
    rtol = setting(request.rtol, limits.RTOL_DEFAULT, ranges["rtol"], "rtol")
    atol = setting(request.atol, limits.ATOL_DEFAULT, ranges["atol"], "atol")
    samples = int(setting(request.samples, limits.SAMPLES_DEFAULT, ranges["samples"], "samples"))
    method = request.method or AUTO
    precision = getattr(request, "precision", None) or "full"
    if method != AUTO:
        methods.method(method)  # an unknown name is refused before any work

    system, observables = compiled.get(scene_id, derivation, constraint_forces)
    try:
        start = system.f(0.0, y0, k)
    except (ArithmeticError, ValueError):
        start = np.array([math.nan])
    if not np.all(np.isfinite(start)):
        raise SimulationError(why_not_at_start(derivation, y0, k), "initial")  # the cause, named
    # the plan resolves auto (and the fallback while compiling) first, so the throttle sees what will run
    planned = plan(
        system, k, y0, t_end, samples, method, rtol, atol,
        wait_for_compile=not gates.answer_while_compiling, ready=gates.compiled,
    )  # fmt: skip
    # a run far beyond the scene's span or near the tolerance floor is heavy: those take at most half
    # of the slots, so a flood of them leaves the others to the light runs students send
    heavy = t_end > HEAVY_SPAN * (scene.t_end if scene else DEFAULT_T_END) or rtol < HEAVY_RTOL
    elsewhere = None
    if scene_id is not None and gates.offload is not None:
        offload = gates.offload

        def elsewhere(python_plan: Plan, wall_seconds: float) -> Outcome:
            # a Python step loop holds the GIL of the process it runs in: in the scenes' worker, not
            # beside the event loop; the worker may first start and load the scene (from the disk
            # caches), hence the margin
            return offload(
                run_scene_plan, scene_id, python_plan.portable(), wall_seconds,
                timeout=wall_seconds + settings().simulate_seconds,
            )  # fmt: skip

    with ExitStack() as held:
        if steps_in_python(planned):
            held.enter_context(gates.python_loop())
        elif heavy:
            held.enter_context(gates.heavy_run())
        held.enter_context(gates.any())
        outcome, observed = run_served(
            planned, gates.wall_seconds, compiled.events(scene, system), CORES, throttle=gates.python_loop,
            elsewhere=elsewhere,
            # the series while the error estimate's reference run finishes beside
            alongside=lambda trajectory: observe(system, observables, trajectory, k, rtol, precision),
        )  # fmt: skip
    return document(system, observables, outcome, k, rtol, precision, observed)


def simulate_scene(scene_id: str, request: SimulationInput, gates: Gates, scenes: Scenes) -> dict[str, Any]:
    """Simulate a chapter scene; ``scenes``: where its derivation and system are kept (the app's)."""
    from app.service.chapter.derivations import scene

    scene(scene_id)
    with gates.in_flight.serving():  # the warm-up thread waits meanwhile
        return simulate_derivation(
            scenes.derivation(scene_id), request, scene_id=scene_id, gates=gates, compiled=scenes.compiled
        )


if __name__ == "__main__":  # at image build: python -m app.service.simulations.simulation
    from app.service.chapter.derivations import PROCESS_SCENES

    for name, seconds in warm_all(PROCESS_SCENES).items():
        print(f"{name}: {seconds:.2f} s")
