"""Error responses: a clear 4xx with what was wrong and what is allowed, never a 500.

FastAPI's default validation handler echoes the offending input back; a huge
or non-finite input would then be repeated or break JSON encoding.  This one
reports where and what, and never the input itself; a name in a location (a
dictionary key) is cut to a short excerpt.
"""

from __future__ import annotations

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse

from app.engine.errors import DerivationError, excerpt
from app.service.derivations import UnknownScene


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
    return JSONResponse(status_code=422, content={"detail": detail, "errors": errors})


async def unknown_scene(request: Request, exc: UnknownScene) -> JSONResponse:
    return JSONResponse(status_code=404, content={"detail": str(exc)})


async def derivation_error(request: Request, exc: DerivationError) -> JSONResponse:
    return JSONResponse(status_code=422, content={"detail": str(exc)[:500], "part": exc.part[:80]})


def install(app: FastAPI) -> None:
    app.add_exception_handler(RequestValidationError, validation_error)
    app.add_exception_handler(UnknownScene, unknown_scene)
    app.add_exception_handler(DerivationError, derivation_error)
