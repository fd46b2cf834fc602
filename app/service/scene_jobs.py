"""Worker-process jobs on the chapter's scenes: load their numeric systems, run a scene's plan."""

from __future__ import annotations

from typing import Any

from app.numerics.plan import Plan
from app.numerics.simulate import Outcome, run
from app.scenes import SCENES
from app.service.compiled import COMPILED, scene_events


def load_scenes() -> int:
    """A worker process's job at start-up: load every scene's numeric system (from the disk caches)."""
    from app.service.derivations import derivation

    for scene_id in SCENES:
        COMPILED.get(scene_id, derivation(scene_id))
    return len(SCENES)


def run_scene_plan(scene_id: str, portable: dict[str, Any], wall_seconds: float) -> Outcome:
    """A worker process's job: run a scene's plan (``Plan.portable``) on this process's copy of its system."""
    from app.service.derivations import derivation

    system, _ = COMPILED.get(scene_id, derivation(scene_id))
    return run(Plan.rebuilt(system, portable), wall_seconds, events=scene_events(SCENES[scene_id], system))
