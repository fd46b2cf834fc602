"""HTML pages: the chapter's table of contents and one page per scene.

Pages are rendered on the server from the derivation JSON (cached by the
service layer) through the page model of ``app.viz.page_model``; the model of
each scene is built once per app (its ``PageCache``, app/web/rendering/page_cache.py), so a
warm request only renders the template.  Routes are plain ``def``: a first, uncached derivation runs in the
thread pool, never on the event loop.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, RedirectResponse

from app.engine.document.contract import scene_json
from app.engine.document.model import Document
from app.errors import UnknownScene
from app.numerics.methods import CHOICES
from app.service.answers import Answers
from app.service.chapter import derivations
from app.service.chapter.derivations import Scenes
from app.service.simulations import lyapunov
from app.viz.chapter import table_of_contents
from app.viz.diagrams import diagram
from app.viz.page_model import scene_page
from app.web.api.deps import AnswersDep, ChapterDep, PagesDep, SettingsDep
from app.web.api.errors import problem
from app.web.http.compression import negotiate
from app.web.rendering.page_cache import PageCache
from app.web.rendering.templating import templates

router = APIRouter(tags=["pages"], include_in_schema=False)


def scene_info(scene_id: str, doc: Document) -> dict[str, Any]:
    """Title, section, statement, figure, panels, initial state, t_end, events and family of a scene."""
    return {**scene_json(derivations.scene(scene_id)), **(doc.scene.model_dump() if doc.scene else {})}


def page_model(
    scene_id: str, pages: PageCache | None, chapter: Scenes, answers: Answers | None = None
) -> dict[str, Any]:
    """The scene's page model, through the app's ``pages`` (rebuilt there only if its derivation document changed;
    None: built anew); the document from the app's ``chapter``, what was measured from the app's ``answers``
    (by default the disk's caches)."""
    doc = chapter.document(scene_id)

    def build() -> dict[str, Any]:
        s = derivations.scene(scene_id)
        particles = [(p.label, p.position) for p in s.system.particles]
        info = scene_info(scene_id, doc)
        if s.lyapunov_seconds:  # a chaotic scene's measured exponent opens its run note
            info["run_note"] = lyapunov.run_note(scene_id, answers.lyapunov if answers else None, chapter)
        return scene_page(doc, info, particles, CHOICES, s.system.nonnegative)

    return build() if pages is None else pages.model(scene_id, doc, build)


def _card_diagram(s: Any) -> str:
    defaults = {p.name: p.default for p in s.system.parameters}
    particles = [(p.label, p.position) for p in s.system.particles]
    drawn = (s.family, s.title, s.figure, defaults, dict(s.initial), s.system.coordinates, particles)
    return diagram(*drawn, ident=f"card-{s.id}", marks=s.marks)


@router.get("/", response_class=HTMLResponse)
def index(
    request: Request, pages: PagesDep, chapter: ChapterDep, answers: AnswersDep, config: SettingsDep
) -> HTMLResponse:
    # the panels each page shows (app/viz/panels.py) tell the contents where a section is illustrated
    scenes = [
        {
            **scene_json(s),
            "panels": page_model(s.id, pages, chapter, answers)["panels"],
            "diagram": pages.card(s.id, lambda s=s: _card_diagram(s)),
            "url": f"/scenes/{s.id}",
        }
        for s in derivations.SCENES.values()
    ]
    context = {"toc": table_of_contents(scenes), "scenes": scenes, "notes": config.source_notes}
    return templates.TemplateResponse(request, "index.html", context)


@router.get("/scenes", response_class=RedirectResponse)
def scenes_index() -> RedirectResponse:
    return RedirectResponse("/", status_code=307)


def unknown_scene(request: Request, exc: UnknownScene, prefix: str) -> HTMLResponse:
    """The 404 page of a scene id that does not exist, listing the scenes there are as ``prefix`` + id."""
    known = [{"id": s.id, "title": s.title, "url": f"{prefix}{s.id}"} for s in derivations.SCENES.values()]
    return templates.TemplateResponse(
        request, "404.html", {"missing": exc.scene_id[:60], "known": known}, status_code=problem(exc).status
    )


@router.get("/scenes/{scene_id}", response_class=HTMLResponse)
def scene_page_route(
    request: Request, scene_id: str, pages: PagesDep, chapter: ChapterDep, answers: AnswersDep, config: SettingsDep
) -> HTMLResponse:
    try:
        model = page_model(scene_id, pages, chapter, answers)
    except UnknownScene as exc:
        return unknown_scene(request, exc, "/scenes/")
    # A scene page depends only on its model and whether it names the source notes: render (and compress) it
    # once per both, then serve the bytes.
    notes = config.source_notes
    context = {"m": model, "scene": model["info"], "notes": notes}
    plain, compressed = pages.page(
        scene_id, model, lambda: bytes(templates.TemplateResponse(request, "scene.html", context).body), notes
    )
    if negotiate(request.headers.get("accept-encoding", ""), offered=("gzip",)):
        return HTMLResponse(compressed, headers={"Content-Encoding": "gzip", "Vary": "Accept-Encoding"})
    return HTMLResponse(plain, headers={"Vary": "Accept-Encoding"})
