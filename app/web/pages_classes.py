"""The classes' pages, /teach and /join, and the classes' API (one router for app/main.py).

The pages are static shells: everything a class shows comes from /api/classes
in the browser (static/js/teach.js, join.js), with the keys kept in the
browser's localStorage, never in a cookie or an address.  /join sets the
session cookie (app/service/fairness.py) so a student joins as their browser.  The instructor's
page polls the summary and the students every two seconds; a student's page
practises the assignment's steps with practice mode's checker, recorded.
"""

from __future__ import annotations

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response

from app.service import derivations
from app.web.api_classes import router as api_router
from app.web.deps import ClientDep
from app.web.templating import templates

pages = APIRouter(tags=["pages"], include_in_schema=False)


def _scenes() -> list[dict[str, str]]:
    return [{"id": s.id, "title": s.title} for s in derivations.SCENES.values()]


@pages.get("/teach", response_class=HTMLResponse)
def teach(request: Request) -> HTMLResponse:
    return templates.TemplateResponse(request, "teach.html", {"scenes": _scenes()})


@pages.get("/join", response_class=HTMLResponse)
def join(request: Request, client: ClientDep) -> Response:
    # the page hands out the browser's session (the cookie) before the student joins: each browser behind a
    # school's one address then joins as itself, not as one of the address's newcomers
    return client.keep(templates.TemplateResponse(request, "join.html", {"scenes": _scenes()}))


router = APIRouter()
router.include_router(api_router)
router.include_router(pages)
