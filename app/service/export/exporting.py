"""Exports of scenes and of user systems, fed by the same derivations, caches and limits as the API.

A scene's export reuses its cached derivation and document and is cached per
(scene, format).  A user system's export is a job in the worker pool
(``app.service.users.user_jobs.export_job``), under the derivation's time limit,
so an export can never do more than a derivation could.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from app.engine.derivation.derive import Derivation
from app.engine.document.model import Document
from app.limits import DEFAULT_T_END
from app.service.chapter import derivations
from app.service.export import filename, render
from app.service.export.source import FORMATS, scene_source, system_source
from app.service.runtime.cache import Recent
from app.service.simulations.simulate_request import initial_state


@dataclass(frozen=True)
class Exported:
    content: bytes
    filename: str
    media_type: str


def _check_format(fmt: str) -> str:
    if fmt not in FORMATS:
        raise ValueError(f"unknown export format {fmt[:20]!r}; choose one of {', '.join(FORMATS)}")
    return fmt


CACHED_EXPORTS = 64  # the size of the app's ``Recent`` of exports (app/service/answers.py)


def scene_export(
    scene_id: str, fmt: str, printed: Callable[[str], Document], remembered: Recent | None = None
) -> Exported:
    """A scene's derivation as a file (run in a thread: the first call may derive), through ``remembered``
    (the app's recent exports) when given.

    An export prints the derivation's printed document (its LaTeX, its steps) again in another format;
    ``printed`` gives a scene's document (the app's ``Scenes.document``)."""
    _check_format(fmt)

    def make() -> Exported:
        scene = derivations.scene(scene_id)
        d = derivations.derivation(scene_id)
        y0 = initial_state(d, {}, scene.initial)
        source = scene_source(scene, d, printed(scene_id), tuple(y0.tolist()))
        return Exported(render(source, fmt).encode(), filename(source, fmt), FORMATS[fmt][0])

    return make() if remembered is None else remembered.get((scene_id, fmt), make)


def system_export(
    d: Derivation, document: Document, fmt: str, initial: Mapping[str, float], t_end: float | None
) -> dict[str, str]:
    """A user system's derivation (and its JSON document) as a file, made in a worker.

    A bad initial state raises SimulationError; a name or function that cannot be written, ExportError."""
    _check_format(fmt)
    y0 = initial_state(d, initial, {})
    source = system_source(d, document, tuple(y0.tolist()), DEFAULT_T_END if t_end is None else t_end)
    return {"content": render(source, fmt), "filename": filename(source, fmt), "media_type": FORMATS[fmt][0]}
