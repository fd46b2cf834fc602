"""Worker-process jobs on the chapter's scenes: load their numeric systems, run a scene's plan.

A worker process has no app: its jobs are module-level functions pickled by reference, and they read
the process's ``Scenes`` (``app.service.chapter.derivations.PROCESS_SCENES``), which lives as long as the worker."""

from __future__ import annotations

from typing import Any

from app.numerics.plan import Plan
from app.numerics.simulate import Outcome
from app.scenes import SCENES
from app.service.runtime.cores import CORES
from app.service.simulations.simulation_run import run_served


def load_scenes() -> int:
    """A worker process's job at start-up: load every scene's numeric system (from the disk caches)."""
    from app.service.chapter.derivations import PROCESS_SCENES

    for scene_id in SCENES:
        PROCESS_SCENES.system(scene_id)
    return len(SCENES)


def run_scene_plan(scene_id: str, portable: dict[str, Any], wall_seconds: float) -> Outcome:
    """A worker process's job: run a scene's plan (``Plan.portable``) on this process's copy of its system."""
    from app.service.chapter.derivations import PROCESS_SCENES

    system, _ = PROCESS_SCENES.system(scene_id)
    events = PROCESS_SCENES.compiled.events(SCENES[scene_id], system)
    outcome, _ = run_served(Plan.rebuilt(system, portable), wall_seconds, events, CORES)
    return outcome
