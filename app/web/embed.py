"""Embed pages: a scene's mechanism for a frame in a course page (``/embed/scenes/{id}``).

What a lecturer puts in an ``<iframe>`` on a course site.  The page's options, each once here:

* ``?view=`` (``VIEWS``, app/web/embed_views.py): ``full`` (the default) is the animation with Play, the initial conditions,
  the parameters and the run's duration and tolerance; ``compact`` is the animation with Play and
  the time slider alone, no forms and no paragraphs, sized to fit a phone's screen without scrolling.
* ``?panel=`` one plot panel beside the animation (``embeddable``).

A link opens the whole page.  The scene page offers the frame's code for each view with the height it
needs (app/web/embed_views.py ``offers``).  Which sites may frame it is a setting (``embed_ancestors``, applied by
app/web/headers.py); by default none may.
"""

from __future__ import annotations

from fastapi import APIRouter, Query, Request
from fastapi.responses import HTMLResponse

from app.errors import UnknownScene
from app.web.deps import ChapterDep, PagesDep
from app.web.embed_views import DEFAULT_VIEW, VIEWS
from app.web.pages import page_model, unknown_scene
from app.web.templating import templates

router = APIRouter(tags=["pages"], include_in_schema=False)


def embeddable(model: dict) -> list[str]:
    """The panels an embed page may show beside the animation: the page's plots that are not folded away."""
    return [k for k in model["panels"] if not k.startswith("animation") and k not in model["folded_panels"]]


@router.get("/embed/scenes/{scene_id}", response_class=HTMLResponse)
def embed_scene(
    request: Request,
    scene_id: str,
    pages: PagesDep,
    chapter: ChapterDep,
    panel: str | None = Query(None, max_length=40, description="one plot panel to show beside the animation"),
    view: str = Query(DEFAULT_VIEW, max_length=40, description="full (the default) or compact"),
) -> HTMLResponse:
    try:
        model = page_model(scene_id, pages, chapter)
    except UnknownScene as exc:
        return unknown_scene(request, exc, "/embed/scenes/")
    allowed = embeddable(model)
    refused = None
    if view not in VIEWS:
        refused = {"missing": view[:40], "option": "view", "choices": list(VIEWS)}
    elif panel is not None and panel not in allowed:
        refused = {"missing": panel[:40], "option": "panel", "choices": allowed}
    if refused is not None:
        context = {"missing": refused["missing"], "known": [], "embed": {"scene": model["info"], **refused}}
        return templates.TemplateResponse(request, "404.html", context, status_code=422)
    context = {"m": model, "scene": model["info"], "embed_panels": [panel] if panel else [], "embed_view": view}
    return templates.TemplateResponse(request, "embed.html", context)
