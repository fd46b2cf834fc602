"""POST /api/derive, POST /api/simulate and POST /api/export: systems users type in.

The routes are ``async`` but never run SymPy: they check the request's shape,
names and expressions in pure Python (reading each expression's text, once:
docs/parsing.md), look up a cache, take a fair-share ticket and await a job in
the worker pool (app/service/runtime/worker.py), which builds what was read in SymPy,
derives and simulates under a hard time limit and a memory cap.  Bodies are capped in
size before they are read (app/web/api/limits.py, for every route).
"""

from __future__ import annotations

import json
from collections.abc import Callable, Coroutine
from typing import Annotated, Any

from fastapi import APIRouter, Body
from fastapi.responses import Response

from app.engine.document.model import Document
from app.service.export.exporting import Exported
from app.service.users.user_checks import InvalidSystem, checked
from app.web.api.deps import Client, ClientDep, UserSystemsDep
from app.web.api.errors import KINDS, held, json_problem
from app.web.api.examples_user import (
    DERIVE_EXAMPLES,
    DERIVE_RESPONSE,
    ERROR_EXAMPLES,
    SIMULATE_EXAMPLES,
    SIMULATE_RESPONSE,
)
from app.web.api.limits import MAX_BODY_BYTES
from app.web.api.scenes import EXPORT_CONTENT, download
from app.web.http.disconnect import ClientGone, unless_gone
from app.web.schemas.common import SESSION_COOKIE, Problem
from app.web.schemas.export import ExportRequest
from app.web.schemas.simulate import SimulateResponse
from app.web.schemas.user import (
    SystemSpec,
    UserSimulateRequest,
    simulate_request,
    system_of,
)

router = APIRouter(prefix="/api", tags=["your systems"])

BUSY_HEADERS = {"Retry-After": {"description": "Seconds to wait before retrying.", "schema": {"type": "integer"}}}


def _errors(*statuses: int) -> dict[int | str, dict[str, Any]]:
    """The documented error responses, each with its model and examples."""
    described = {
        400: (
            Problem,
            "The body could not be read (not UTF-8, a number JSON cannot hold, or nested too deeply).",
        ),
        413: (Problem, f"The body is larger than {MAX_BODY_BYTES} bytes."),
        422: (
            Problem,
            "The system was refused: a bad shape, name or expression (located by `loc`, `part`, "
            "`start`/`end`), a singular mass matrix, NaN or Infinity, or work beyond the time or memory limit.",
        ),
        429: (Problem, "You already have a derivation or simulation running (one at a time per session)."),
        503: (Problem, "The server is busy with other users' systems."),
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


def system_route(
    router: APIRouter, path: str, summary: str, description: str, response_model: Any = None, example: Any = None
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """POST ``path`` for a system the user declares, run in the worker pool: documented with the session cookie,
    the pool's errors and, if given, an ``example`` answer."""
    responses = _errors(400, 413, 422, 429, 503)
    if example is not None:
        responses = {200: {"content": {"application/json": {"example": example}}}, **responses}
    return router.post(
        path,
        summary=summary,
        description=description,
        response_model=response_model,
        openapi_extra={"parameters": [SESSION_COOKIE]},
        responses=responses,
    )


def _json(body: bytes) -> Response:
    return Response(body, media_type="application/json")


async def answer(
    client: Client,
    work: Callable[[str, str], Coroutine[Any, Any, bytes]],
    reply: Callable[[bytes], Response] = _json,
) -> Response:
    """Run the work for the client; a failure gets its response (app/web/api/errors.py), with the session cookie too."""
    response: Response
    try:
        # a client that leaves gives up its queued job
        body = await unless_gone(client.request, work(client.key, client.address))
    except ClientGone:
        return Response(status_code=499)  # nobody reads it: nginx's code for a client that closed the request
    except KINDS as exc:
        await held(exc)  # a flood's refusals are answered late (app/service/runtime/fairness.py HOLD_SECONDS)
        response = json_problem(exc)
    else:
        response = reply(body)
    return client.keep(response)


@system_route(
    router,
    "/derive",
    summary="Derive a system you declare",
    description=(
        "Give generalized coordinates, parameters and the mechanics in one form (particles with a potential, "
        "T and U, or L), optionally generalized forces. The answer is the same derivation JSON as a scene's: "
        "symbol convention q, q_dot, q_ddot, t and parameters by name. Expressions are parsed by an allowlist "
        "(never evaluated as code); the derivation runs in a worker process with a time and memory limit."
    ),
    response_model=Document,
    example=DERIVE_RESPONSE,
)
async def derive_system(
    client: ClientDep, users: UserSystemsDep, system: Annotated[SystemSpec, Body(openapi_examples=DERIVE_EXAMPLES)]
) -> Response:
    return await answer(client, lambda key, address: users.derive(checked(system.to_spec()), key, address))


@system_route(
    router,
    "/simulate",
    summary="Simulate a system you declare",
    description=(
        "The system as for POST /api/derive (parameter values from its `parameters`) plus the simulate fields of "
        "POST /api/scenes/{id}/simulate: `initial` (q and q_dot by name; missing ones are 0), `t_end` (default 10 s), "
        "`method`, `rtol`, `atol`, `samples`. The answer is the same result JSON as a scene's: samples of the state, "
        "E, h, conserved quantities, and stats with the method, an error estimate, drifts and warnings."
    ),
    response_model=SimulateResponse,
    example=SIMULATE_RESPONSE,
)
async def simulate_system(
    client: ClientDep,
    users: UserSystemsDep,
    body: Annotated[UserSimulateRequest, Body(openapi_examples=SIMULATE_EXAMPLES)],
) -> Response:
    spec = system_of(body)
    wanted = simulate_request(body)
    return await answer(client, lambda key, address: users.simulate(checked(spec), wanted, key, address))


# what the numerics may complain about at the top of an export request; the rest is inside "system"
_EXPORT_TOP_LEVEL = {"initial", "t_end", "format"}


def _in_system(exc: InvalidSystem) -> InvalidSystem:
    """A refusal located in the export body: the system's fields sit under ``system``."""
    if exc.loc and exc.loc[0] in _EXPORT_TOP_LEVEL:
        return exc
    return type(exc)(str(exc), ("system", *exc.loc), exc.part, exc.start, exc.end)


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
async def export_system(client: ClientDep, users: UserSystemsDep, body: ExportRequest) -> Response:
    initial, t_end = dict(body.initial), body.t_end

    async def work(key: str, address: str) -> bytes:
        try:
            return await users.export(checked(body.system.to_spec()), body.format, initial, t_end, key, address)
        except InvalidSystem as exc:
            raise _in_system(exc) from None

    def reply(document: bytes) -> Response:
        made = json.loads(document)
        return download(Exported(made["content"].encode(), made["filename"], made["media_type"]))

    return await answer(client, work, reply)
