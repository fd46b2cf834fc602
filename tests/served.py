"""What a test passes where an app would give its services: gates of its own (a script's: every run in line,
compiled first) and this process's scenes (``PROCESS_SCENES``, the one copy of the chapter's systems)."""

from typing import Any

from app.service.chapter.derivations import PROCESS_SCENES
from app.service.runtime.gates import Gates
from app.service.simulations import simulation


def scene_run(scene_id: str, asked: Any, gates: Gates | None = None) -> dict[str, Any]:
    """A scene's simulation through ``gates`` (new ones unless given) on this process's scenes."""
    return simulation.simulate_scene(scene_id, asked, gates or Gates(), PROCESS_SCENES)


def derivation_run(d: Any, asked: Any, **options: Any) -> dict[str, Any]:
    """A derivation's simulation (``simulate_derivation``), by default through new gates on this process's systems."""
    return simulation.simulate_derivation(
        d, asked, **{"gates": Gates(), "compiled": PROCESS_SCENES.compiled, **options}
    )
