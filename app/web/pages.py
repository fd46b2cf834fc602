"""HTML pages: the chapter's table of contents and one page per scene.

Pages are rendered on the server from the derivation JSON (cached by the
service layer) through the page model of ``app.viz.page_model``; the model of
each scene is built once per process, so a warm request only renders the
template.  Routes are plain ``def``: a first, uncached derivation runs in the
thread pool, never on the event loop.
"""

from __future__ import annotations

import gzip
import threading
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, RedirectResponse

from app.engine.contract import scene_json
from app.errors import UnknownScene
from app.numerics.methods import CHOICES
from app.service import derivations
from app.viz.chapter import table_of_contents
from app.viz.diagrams import diagram
from app.viz.page_model import scene_page
from app.web.compression import negotiate
from app.web.errors import problem
from app.web.templating import templates

router = APIRouter(tags=["pages"], include_in_schema=False)

_models: dict[str, tuple[int, dict[str, Any]]] = {}
_lock = threading.Lock()


def scene_info(scene_id: str, doc: dict[str, Any]) -> dict[str, Any]:
    """Title, section, statement, figure, panels, initial state, t_end, events and family of a scene."""
    return {**scene_json(derivations.scene(scene_id)), **(doc.get("scene") or {})}


def page_model(scene_id: str) -> dict[str, Any]:
    """The scene's page model, rebuilt only if its derivation document changed."""
    doc = derivations.derivation_document(scene_id)
    cached = _models.get(scene_id)
    if cached and cached[0] == id(doc):
        return cached[1]
    s = derivations.scene(scene_id)
    particles = [(p.label, p.position) for p in s.system.particles]
    model = scene_page(doc, scene_info(scene_id, doc), particles, CHOICES, s.system.nonnegative)
    with _lock:
        _models[scene_id] = (id(doc), model)
    return model


_cards: dict[str, str] = {}


def _card_diagram(s: Any) -> str:
    if s.id not in _cards:
        defaults = {p.name: p.default for p in s.system.parameters}
        particles = [(p.label, p.position) for p in s.system.particles]
        drawn = (s.family, s.title, s.figure, defaults, dict(s.initial), s.system.coordinates, particles)
        _cards[s.id] = diagram(*drawn, ident=f"card-{s.id}", marks=s.marks)
    return _cards[s.id]


@router.get("/", response_class=HTMLResponse)
def index(request: Request) -> HTMLResponse:
    # the panels each page shows (app/viz/panels.py) tell the contents where a section is illustrated
    scenes = [
        {
            **scene_json(s),
            "panels": page_model(s.id)["panels"],
            "diagram": _card_diagram(s),
            "url": f"/scenes/{s.id}",
        }
        for s in derivations.SCENES.values()
    ]
    return templates.TemplateResponse(request, "index.html", {"toc": table_of_contents(scenes), "scenes": scenes})


@router.get("/scenes", response_class=RedirectResponse)
def scenes_index() -> RedirectResponse:
    return RedirectResponse("/", status_code=307)


@router.get("/scenes/{scene_id}", response_class=HTMLResponse)
def scene_page_route(request: Request, scene_id: str) -> HTMLResponse:
    try:
        model = page_model(scene_id)
    except UnknownScene as exc:
        known = [{"id": s.id, "title": s.title, "url": f"/scenes/{s.id}"} for s in derivations.SCENES.values()]
        return templates.TemplateResponse(
            request, "404.html", {"missing": exc.scene_id[:60], "known": known}, status_code=problem(exc).status
        )
    # A scene page depends only on its model: render (and compress) it once per model, then serve the bytes.
    cached = _pages.get(scene_id)
    if cached is None or cached[0] is not model:
        body = bytes(templates.TemplateResponse(request, "scene.html", {"m": model, "scene": model["info"]}).body)
        cached = _pages[scene_id] = (model, body, gzip.compress(body, 9))
    if negotiate(request.headers.get("accept-encoding", ""), offered=("gzip",)):
        return HTMLResponse(cached[2], headers={"Content-Encoding": "gzip", "Vary": "Accept-Encoding"})
    return HTMLResponse(cached[1], headers={"Vary": "Accept-Encoding"})


_pages: dict[str, tuple[dict[str, Any], bytes, bytes]] = {}
