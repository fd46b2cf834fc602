"""POST /api/derive, POST /api/simulate and POST /api/export: systems users type in.

The routes are ``async`` but never run SymPy: they check the request's shape
and names in pure Python, look up a cache, take a fair-share ticket and await
a job in the worker pool (app/service/worker.py), which parses, derives and
simulates under a hard time limit and a memory cap.  Bodies are capped in
size before they are read (app/web/limits.py, for every route).
"""

from __future__ import annotations

import json
from collections.abc import Callable, Coroutine
from typing import Annotated, Any

from fastapi import APIRouter, Body, Request
from fastapi.responses import JSONResponse, Response

from app.service import user_systems
from app.service.exporting import Exported
from app.service.fairness import COOKIE, COOKIE_MAX_AGE, Busy
from app.service.user_systems import InvalidSystem
from app.service.worker import JobFailed
from app.web.api_scenes import EXPORT_CONTENT, download
from app.web.disconnect import ClientGone, unless_gone
from app.web.examples_user import DERIVE_EXAMPLES, DERIVE_RESPONSE, ERROR_EXAMPLES, SIMULATE_EXAMPLES, SIMULATE_RESPONSE
from app.web.limits import MAX_BODY_BYTES
from app.web.schemas import SESSION_COOKIE, ErrorResponse
from app.web.schemas_export import ExportRequest
from app.web.schemas_simulate import SimulateResponse
from app.web.schemas_user import (
    BusyError,
    DerivationDocument,
    SystemSpec,
    UserError,
    UserSimulateRequest,
    simulate_request,
)

router = APIRouter(prefix="/api", tags=["your systems"])

BUSY_HEADERS = {"Retry-After": {"description": "Seconds to wait before retrying.", "schema": {"type": "integer"}}}


def _errors(*statuses: int) -> dict[int | str, dict[str, Any]]:
    """The documented error responses, each with its model and examples."""
    described = {
        400: (
            ErrorResponse,
            "The body could not be read (not UTF-8, a number JSON cannot hold, or nested too deeply).",
        ),
        413: (ErrorResponse, f"The body is larger than {MAX_BODY_BYTES} bytes."),
        422: (
            UserError,
            "The system was refused: a bad shape, name or expression (located by `loc`, `part`, "
            "`start`/`end`), a singular mass matrix, NaN or Infinity, or work beyond the time or memory limit.",
        ),
        429: (BusyError, "You already have a derivation or simulation running (one at a time per session)."),
        503: (BusyError, "The server is busy with other users' systems."),
    }
    responses: dict[int | str, dict[str, Any]] = {}
    for status in statuses:
        model, text = described[status]
        examples = {
            name: {"summary": e["summary"], "value": e["response"]} for name, e in ERROR_EXAMPLES[status].items()
        }
        entry: dict[str, Any] = {
            "model": model,
            "description": text,
            "content": {"application/json": {"examples": examples}},
        }
        if status in (429, 503):
            entry["headers"] = BUSY_HEADERS
        responses[status] = entry
    return responses


def _address(request: Request) -> str:
    return request.client.host if request.client else "unknown"


def _json(body: bytes) -> Response:
    return Response(body, media_type="application/json")


async def _answer(
    request: Request,
    work: Callable[[str, str], Coroutine[Any, Any, bytes]],
    reply: Callable[[bytes], Response] = _json,
) -> Response:
    """Identify the client, run the work, and turn refusals into their documented responses."""
    service = user_systems.service
    address = _address(request)
    session = service.gate.verify(request.cookies.get(COOKIE))
    minted = None if session else service.gate.mint(address)
    client = f"session:{session}" if session else f"address:{address}"
    response: Response
    try:
        body = await unless_gone(request, work(client, address))  # a client that left gives up its queued job
    except ClientGone:
        return Response(status_code=499)  # nobody reads it: nginx's code for a client that closed the request
    except InvalidSystem as exc:
        response = JSONResponse(exc.as_json(), status_code=422)
    except Busy as exc:
        response = JSONResponse(
            {"detail": str(exc), "retry_after": exc.retry_after},
            status_code=exc.status,
            headers={"Retry-After": str(exc.retry_after)},
        )
    except JobFailed as exc:
        if exc.kind == "unavailable":
            response = JSONResponse(
                {"detail": str(exc), "retry_after": 1}, status_code=503, headers={"Retry-After": "1"}
            )
        else:
            response = JSONResponse({"detail": str(exc), "kind": exc.kind}, status_code=422)
    else:
        response = reply(body)
    if minted:
        response.set_cookie(COOKIE, minted, max_age=COOKIE_MAX_AGE, httponly=True, samesite="lax")
    return response


@router.post(
    "/derive",
    summary="Derive a system you declare",
    description=(
        "Give generalized coordinates, parameters and the mechanics in one form (particles with a potential, "
        "T and U, or L), optionally generalized forces. The answer is the same derivation JSON as a scene's: "
        "symbol convention q, q_dot, q_ddot, t and parameters by name. Expressions are parsed by an allowlist "
        "(never evaluated as code); the derivation runs in a worker process with a time and memory limit."
    ),
    response_model=DerivationDocument,
    openapi_extra={"parameters": [SESSION_COOKIE]},
    responses={
        200: {"content": {"application/json": {"example": DERIVE_RESPONSE}}},
        **_errors(400, 413, 422, 429, 503),
    },
)
async def derive_system(
    request: Request, system: Annotated[SystemSpec, Body(openapi_examples=DERIVE_EXAMPLES)]
) -> Response:
    spec = system.to_spec()
    return await _answer(request, lambda client, address: user_systems.service.derive(spec, client, address))


@router.post(
    "/simulate",
    summary="Simulate a system you declare",
    description=(
        "The system as for POST /api/derive (parameter values from its `parameters`) plus the simulate fields of "
        "POST /api/scenes/{id}/simulate: `initial` (q and q_dot by name; missing ones are 0), `t_end` (default 10 s), "
        "`method`, `rtol`, `atol`, `samples`. The answer is the same result JSON as a scene's: samples of the state, "
        "E, h, conserved quantities, and stats with the method, an error estimate, drifts and warnings."
    ),
    response_model=SimulateResponse,
    openapi_extra={"parameters": [SESSION_COOKIE]},
    responses={
        200: {"content": {"application/json": {"example": SIMULATE_RESPONSE}}},
        **_errors(400, 413, 422, 429, 503),
    },
)
async def simulate_system(
    request: Request, body: Annotated[UserSimulateRequest, Body(openapi_examples=SIMULATE_EXAMPLES)]
) -> Response:
    spec = SystemSpec.model_validate(body.model_dump(include=set(SystemSpec.model_fields))).to_spec()
    wanted = simulate_request(body)
    return await _answer(request, lambda client, address: user_systems.service.simulate(spec, wanted, client, address))


# what the numerics may complain about at the top of an export request; the rest is inside "system"
_EXPORT_TOP_LEVEL = {"initial", "t_end", "format"}


def _in_system(exc: InvalidSystem) -> InvalidSystem:
    """A refusal located in the export body: the system's fields sit under ``system``."""
    if exc.loc and exc.loc[0] in _EXPORT_TOP_LEVEL:
        return exc
    return InvalidSystem(str(exc), ("system", *exc.loc), exc.part, exc.start, exc.end)


@router.post(
    "/export",
    summary="A system you declare as a notebook, a Python script or a LaTeX document",
    description=(
        "The body holds `system` (as for POST /api/derive, parameter values from its `parameters`), `format` "
        "(ipynb, py or tex, as for GET /api/scenes/{id}/export) and optionally `initial` (q and q_dot by name; "
        "missing ones are 0) and `t_end` (default 10 s) for the exported simulation. The export is made in the "
        "worker pool under the derivation's limits; only the engine's checked expressions and names reach the file."
    ),
    response_class=Response,
    responses={
        200: {"content": EXPORT_CONTENT, "description": "The file, as an attachment."},
        **_errors(400, 413, 422, 429, 503),
    },
)
async def export_system(request: Request, body: ExportRequest) -> Response:
    spec = body.system.to_spec()
    initial, t_end = dict(body.initial), body.t_end

    async def work(client: str, address: str) -> bytes:
        try:
            return await user_systems.service.export(spec, body.format, initial, t_end, client, address)
        except InvalidSystem as exc:
            raise _in_system(exc) from None

    def reply(document: bytes) -> Response:
        made = json.loads(document)
        return download(Exported(made["content"].encode(), made["filename"], made["media_type"]))

    return await _answer(request, work, reply)
