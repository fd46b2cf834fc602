"""The classes' pages, /teach and /join, and the classes' API (one router for app/main.py).

The pages are static shells: everything a class shows comes from /api/classes
in the browser (static/js/teach.js, join.js), with the keys kept in the
browser's localStorage, never in a cookie or an address.  /join sets the
session cookie (app/service/runtime/fairness.py) so a student joins as their browser.  The instructor's
page polls the summary and the students every two seconds; a student's page
practises the assignment's steps with practice mode's checker, recorded.
"""

from __future__ import annotations

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, RedirectResponse, Response

from app.service.chapter import derivations
from app.service.classroom.keys import normal_code, why_not_code
from app.service.classroom.logins import LMS, LOGIN_COLUMNS
from app.service.classroom.reports import NOT_READ_WORDS
from app.viz.page_model import unit_latex
from app.viz.qr import qr_svg
from app.web.api.classes import router as api_router
from app.web.api.deps import ClientDep
from app.web.rendering.templating import templates

pages = APIRouter(tags=["pages"], include_in_schema=False)


def _scenes() -> list[dict[str, object]]:
    # each scene's parameters' units as LaTeX, so that a value the instructor sets is read with its unit ("l₂ = 0.5 m")
    return [{"id": s.id, "title": s.title, "units": {p.name: unit_latex(p.unit) for p in s.system.parameters}}
            for s in derivations.SCENES.values()]


@pages.get("/teach", response_class=HTMLResponse)
def teach(request: Request) -> HTMLResponse:
    # the teacher's words for an answer the checker could not read: one home (reports), the CSV's and the page's
    # and the LMS login columns a class may ask for, each with its LMS (one home: service/classroom/logins.py)
    return templates.TemplateResponse(request, "teach.html", {
        "scenes": _scenes(), "not_read_words": NOT_READ_WORDS, "login_columns": [(c, LMS[c]) for c in LOGIN_COLUMNS]})


@pages.get("/join", response_class=HTMLResponse)
def join(request: Request, client: ClientDep) -> Response:
    # the page hands out the browser's session (the cookie) before the student joins: each browser behind a
    # school's one address then joins as itself, not as one of the address's newcomers
    return client.keep(templates.TemplateResponse(request, "join.html", {"scenes": _scenes()}))


def _code_or_404(request: Request, code: str) -> str | HTMLResponse:
    """The class code of a short link, or the page saying why the link is not one."""
    normal = normal_code(code[:40])
    if normal is not None:
        return normal
    return templates.TemplateResponse(
        request, "404.html", {"missing": code[:40], "class_link": {"why": why_not_code(code)}}, status_code=404
    )


@pages.get("/j/{code}")
def short_join_link(request: Request, code: str) -> Response:
    """The short link a slide shows (/j/ABC123): the join page with the code filled in."""
    normal = _code_or_404(request, code)
    if isinstance(normal, Response):
        return normal
    return RedirectResponse(f"/join?code={normal}", status_code=303)


@pages.get("/j/{code}/qr.svg")
def join_qr(request: Request, code: str) -> Response:
    """The short link as a QR code (SVG), drawn here: a phone that scans it opens the join page."""
    normal = _code_or_404(request, code)
    if isinstance(normal, Response):
        return normal
    link = f"{str(request.base_url).rstrip('/')}/j/{normal}"
    return Response(
        qr_svg(link, f"QR code of {link}"),
        media_type="image/svg+xml",
        headers={"Cache-Control": "public, max-age=86400"},
    )


router = APIRouter()
router.include_router(api_router)
router.include_router(pages)
