"""Embed pages: a scene's mechanism for a frame in a course page (``/embed/scenes/{id}``).

What a lecturer puts in an ``<iframe>`` on a course site.  The page's options, each once here:

* ``?view=`` (``VIEWS``, app/web/rendering/embed_views.py): ``full`` (the default) is the animation with Play, the initial conditions,
  the parameters and the run's duration and tolerance; ``compact`` is the animation with Play and
  the time slider alone, no forms and no paragraphs, sized to fit a phone's screen without scrolling.
* ``?panel=`` one plot panel beside the animation (``embeddable``, app/web/rendering/embed_views.py).

A link opens the whole page.  An address that shows nothing (no such scene, view or plot) is a page that fits
the frame (``embed_error``): a sentence, the choices by their titles, and a link that opens the book.  The scene page offers the frame's code for each view with the height it
needs (app/web/rendering/embed_views.py ``offers``).  Which sites may frame it is a setting (``embed_ancestors``, applied by
app/web/http/headers.py); by default none may.
"""

from __future__ import annotations

from fastapi import APIRouter, Query, Request
from fastapi.responses import HTMLResponse

from app.errors import UnknownScene
from app.web.api.deps import AnswersDep, ChapterDep, PagesDep
from app.web.pages.chapter import page_model
from app.web.rendering.embed_views import DEFAULT_VIEW, refusal, scene_choices
from app.web.rendering.templating import templates

router = APIRouter(tags=["pages"], include_in_schema=False)


@router.get("/embed/scenes/{scene_id}", response_class=HTMLResponse)
def embed_scene(
    request: Request,
    scene_id: str,
    pages: PagesDep,
    chapter: ChapterDep,
    answers: AnswersDep,
    panel: str | None = Query(None, max_length=40, description="one plot panel to show beside the animation"),
    view: str = Query(DEFAULT_VIEW, max_length=40, description="full (the default) or compact"),
) -> HTMLResponse:
    try:
        model = page_model(scene_id, pages, chapter, answers)
    except UnknownScene as exc:
        return embed_error(request, {"kind": "scene", "missing": exc.scene_id[:60], "choices": scene_choices()}, 404)
    refused = refusal(model, view, panel)
    if refused is not None:
        return embed_error(request, {**refused, "scene": model["info"]}, 422)
    context = {"m": model, "scene": model["info"], "embed_panels": [panel] if panel else [], "embed_view": view}
    return templates.TemplateResponse(request, "embed.html", context)


def embed_error(request: Request, refused: dict, status: int) -> HTMLResponse:
    """An embed address that shows nothing, as a page that fits the frame (templates/embed_error.html): what is
    wrong in a sentence, the choices there are by their titles, and a link that opens the book in the window."""
    return templates.TemplateResponse(request, "embed_error.html", {"refused": refused}, status_code=status)
