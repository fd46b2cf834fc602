"""Error responses: one mapping from the kinds of failure (app/errors.py) to HTTP, for every route.

``problem(exc)`` gives the status, the JSON body and the headers of a failure;
the JSON routes answer with it (through the app's exception handlers or
``json_problem``), the HTML pages take its status and headers and show its
message.  Never a 500 for bad input: a clear 4xx with what was wrong and what
is allowed.

Every error the API sends is an RFC 9457 problem (``problem_body``): media type
``application/problem+json``, with ``type`` (``about:blank``: the status says
what kind of problem it is), ``title`` (the status's phrase), ``status`` and
``detail`` (what was wrong and what is allowed), and the fields clients read
besides (``loc``, ``part``, ``start``/``end``, ``readings``, ``errors``,
``retry_after``, ``kind``).  The OpenAPI document describes them with one
schema (app/web/api/openapi.py).

FastAPI's default validation handler echoes the offending input back; a huge
or non-finite input would then be repeated or break JSON encoding.  This one
reports where and what, and never the input itself; a name in a location (a
dictionary key) is cut to a short excerpt.
"""

from __future__ import annotations

import asyncio
from dataclasses import dataclass, field
from http import HTTPStatus
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exception_handlers import http_exception_handler
from fastapi.exceptions import RequestValidationError
from fastapi.responses import HTMLResponse, JSONResponse, Response
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.routing import Match

from app.engine.errors import excerpt
from app.errors import (
    ClassClosed,
    NoKey,
    OverCapacity,
    Refused,
    UnknownAssignment,
    UnknownClass,
    UnknownScene,
    WorkerFailed,
    WrongKey,
)
from app.limits import RETRY_SECONDS as UNAVAILABLE_RETRY_SECONDS
from app.web.rendering.embed_views import scene_choices
from app.web.rendering.templating import templates

# what each kind of failure is, in HTTP
REFUSED = 422  # Refused and TooMuchWork: the request as sent cannot be served
CLIENT_BUSY = 429  # OverCapacity for this client: its own work is in the way
SERVER_BUSY = 503  # OverCapacity of the whole server, or no worker to be had
NOT_FOUND = 404  # UnknownScene, UnknownClass, UnknownAssignment
NO_KEY = 401  # NoKey
WRONG_KEY = 403  # WrongKey
CLOSED = 409  # ClassClosed: the class exists and the key opens it, but its instructor has closed it to this for now

KINDS = (Refused, OverCapacity, WorkerFailed, UnknownScene, NoKey, WrongKey, UnknownClass, UnknownAssignment,
         ClassClosed)


PROBLEM_JSON = "application/problem+json"


def problem_body(status: int, detail: str, **fields: Any) -> dict[str, Any]:
    """An RFC 9457 problem: ``type``, ``title``, ``status`` and ``detail``, then the route's own fields."""
    return {"type": "about:blank", "title": HTTPStatus(status).phrase, "status": status, "detail": detail, **fields}


def problem_response(status: int, detail: str, headers: dict[str, str] | None = None, **fields: Any) -> JSONResponse:
    return JSONResponse(problem_body(status, detail, **fields), status_code=status, headers=headers, media_type=PROBLEM_JSON)


@dataclass(frozen=True)
class Failure:
    """A failure as HTTP: its status, its problem's fields and its headers."""

    status: int
    body: dict[str, Any]
    headers: dict[str, str] = field(default_factory=dict)

    @property
    def detail(self) -> str:
        return self.body["detail"]


def _busy(message: str, retry_after: int, status: int) -> Failure:
    return Failure(status, {"detail": message, "retry_after": retry_after}, {"Retry-After": str(retry_after)})


def problem(exc: Exception) -> Failure:
    """The response to a failure of one of the kinds in app/errors.py."""
    if isinstance(exc, Refused):
        body: dict[str, Any] = {"detail": str(exc)[:600], "part": exc.part[:80]}
        if exc.loc is not None:  # a refusal located in the request body
            body |= {"loc": ["body", *(excerpt(x) for x in exc.loc)], "start": exc.start, "end": exc.end}
        if getattr(exc, "readings", ()):  # an expression that reads two ways: both readings, to choose from
            body["readings"] = [excerpt(r, 200) for r in exc.readings]
        return Failure(REFUSED, body)
    if isinstance(exc, OverCapacity):
        return _busy(str(exc), exc.retry_after, SERVER_BUSY if exc.whole_server else CLIENT_BUSY)
    if isinstance(exc, WorkerFailed):
        if exc.kind == "unavailable":
            return _busy(str(exc), UNAVAILABLE_RETRY_SECONDS, SERVER_BUSY)
        return Failure(REFUSED, {"detail": str(exc), "kind": exc.kind})
    if isinstance(exc, UnknownScene | UnknownClass | UnknownAssignment):
        return Failure(NOT_FOUND, {"detail": str(exc)})
    if isinstance(exc, NoKey):
        return Failure(NO_KEY, {"detail": str(exc)}, {"WWW-Authenticate": "Bearer"})
    if isinstance(exc, WrongKey):
        return Failure(WRONG_KEY, {"detail": str(exc)})
    if isinstance(exc, ClassClosed):
        return Failure(CLOSED, {"detail": str(exc)})
    raise TypeError(f"not a kind of failure: {type(exc).__name__}") from exc


def json_problem(exc: Exception) -> JSONResponse:
    found = problem(exc)
    fields = {k: v for k, v in found.body.items() if k != "detail"}
    return problem_response(found.status, found.detail, found.headers, **fields)


async def held(exc: Exception) -> None:
    """Wait as long as a refusal asks before it is answered (a flood's refusals: app/service/runtime/fairness.py)."""
    hold = getattr(exc, "hold", 0.0)
    if isinstance(exc, OverCapacity) and hold > 0:
        await asyncio.sleep(hold)


async def _handler(request: Request, exc: Exception) -> JSONResponse:
    await held(exc)
    return json_problem(exc)


def _location(loc: tuple | list) -> str:
    return ".".join(excerpt(part) for part in loc if part != "body") or "body"


async def validation_error(request: Request, exc: RequestValidationError) -> JSONResponse:
    errors = [
        {
            "loc": [excerpt(p) for p in e.get("loc", ())],
            "msg": excerpt(e.get("msg", ""), 300),
            "type": e.get("type", ""),
        }
        for e in exc.errors()[:20]
    ]
    first = errors[0] if errors else {"loc": [], "msg": "invalid request"}
    detail = f"{_location(first['loc'])}: {first['msg']}"
    return problem_response(REFUSED, detail, errors=errors)


UNENCODABLE = (
    "the request holds text that cannot be shown: a lone surrogate escape (\\ud800 to \\udfff without its pair) "
    "is not a character; send the character itself"
)


async def unencodable_text(request: Request, exc: Exception) -> Response:
    """A text the request gave that no page can encode (a lone surrogate from a JSON escape): a refusal, never a 500.

    The pages that echo input check their own fields first (app/web/pages/playground.py); this is the net under them."""
    if request.url.path.startswith("/api/"):
        return problem_response(REFUSED, UNENCODABLE)
    page = f"<!doctype html><html lang=en><title>Refused</title><main><h1>Refused</h1><p>{UNENCODABLE}</p></main>"
    return HTMLResponse(page, status_code=REFUSED)


async def http_error(request: Request, exc: Exception) -> Response:
    """Starlette's own refusals (no such address: 404, a method the address does not take: 405) as problems."""
    assert isinstance(exc, StarletteHTTPException)
    headers = dict(exc.headers or {})
    if exc.status_code == 405:  # every method the address takes, over all its routes (Starlette names one route's)
        headers["Allow"] = _allowed(request) or headers.get("Allow", "")
    if exc.status_code == 404 and request.method in ("GET", "HEAD") and not request.url.path.startswith(_NOT_PAGES):
        return _no_such_page(request)
    if exc.status_code < 400 or not request.url.path.startswith(_API):
        return await http_exception_handler(request, exc)
    return problem_response(exc.status_code, str(exc.detail), headers)


_API = ("/api/", "/openapi.json", "/healthz")
_NOT_PAGES = (*_API, "/static/")


def _no_such_page(request: Request) -> Response:
    """A page address that leads nowhere: a page (never the API's JSON) saying what the addresses near it are,
    for a class link cut before its code (/j/) and an embed address guessed (/embed/...)."""
    path = request.url.path
    if path.startswith("/embed"):  # inside a course page's frame: the embed pages' own error page
        refused = {"kind": "address", "missing": excerpt(path, 60), "choices": scene_choices()}
        return templates.TemplateResponse(request, "embed_error.html", {"refused": refused}, status_code=404)
    near = "class" if path.rstrip("/") in ("/j", "/join") or path.startswith("/j/") else ""
    context = {"missing": excerpt(path, 60), "nowhere": {"near": near}}
    return templates.TemplateResponse(request, "404.html", context, status_code=404)


def _allowed(request: Request) -> str:
    """The methods of every route whose path matches the request's, as an ``Allow`` header (routers included in
    routers are walked through)."""
    methods: set[str] = set()
    routes = list(request.app.router.routes)
    while routes:
        route = routes.pop()
        inner = getattr(getattr(route, "original_router", None), "routes", None)
        if inner is not None:
            routes.extend(inner)
            continue
        takes = getattr(route, "methods", None)
        if takes and route.matches(request.scope)[0] != Match.NONE:
            methods |= set(takes)
    return ", ".join(sorted(methods))


def install(app: FastAPI) -> None:
    app.add_exception_handler(StarletteHTTPException, http_error)
    app.add_exception_handler(RequestValidationError, validation_error)
    app.add_exception_handler(UnicodeEncodeError, unencodable_text)
    for kind in KINDS:
        app.add_exception_handler(kind, _handler)
