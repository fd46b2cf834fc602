"""POST /api/derive/equations: the first stage of a derivation, answered before the whole document.

The same system as POST /api/derive; the answer holds the equations of motion, the accelerations (or the
mass matrix and f of ℳ q̈ = f when they stay ℳ⁻¹f), the symbols and parameters, what was left out so far and what
POST /api/derive will add (``pending``).  A worker-pool job of its own under the derivation's limits
(app/service/users/staged.py); when the whole document is cached, its members are answered at once.
"""

from __future__ import annotations

import asyncio
from typing import Annotated

from fastapi import APIRouter, Body
from fastapi.responses import Response
from pydantic import BaseModel, Field

from app.engine.document.model import MM, FirstStage
from app.errors import Refused
from app.service.runtime import progress
from app.service.users.staged import equations_bytes
from app.service.users.user_checks import checked
from app.web.api.deps import ClientDep, UserSystemsDep
from app.web.api.errors import json_problem
from app.web.api.examples_user import DERIVE_EXAMPLES
from app.web.api.user import answer, system_route
from app.web.schemas.common import Problem
from app.web.schemas.user import SystemSpec

router = APIRouter(prefix="/api", tags=["your systems"])


@system_route(
    router,
    "/derive/equations",
    summary="The equations of a system you declare, first",
    description=(
        "The same system as POST /api/derive. The answer comes before the whole derivation: the equations of "
        f"motion and the accelerations (or the mass matrix and f of {MM} q̈ = f), with the symbols and parameters, "
        "`skipped` so far and `pending` (what POST /api/derive adds). A worker job under the derivation's limits."
    ),
    response_model=FirstStage,
)
async def derive_equations(
    client: ClientDep, users: UserSystemsDep, system: Annotated[SystemSpec, Body(openapi_examples=DERIVE_EXAMPLES)]
) -> Response:
    return await answer(client, lambda key, address: equations_bytes(users, checked(system.to_spec()), key, address))


class Progress(BaseModel):
    running: bool = Field(description="Whether a derivation of this key runs on this server now.")
    part: str | None = Field(
        None, description="The part it is on, as the playground names it (`Hamilton's equations`)."
    )
    part_seconds: float | None = Field(None, description="How long it has been on that part (s).")
    seconds: float | None = Field(None, description="How long the derivation has run (s).")


def _key(key: str) -> str:
    if not progress.KEY.fullmatch(key):
        raise Refused("a derivation's key is 64 hexadecimal digits, as the playground's page gives it", part=key[:80])
    return key


@router.get(
    "/derive/progress/{key}",
    summary="Which part a running derivation is on",
    description=(
        "For the derivation of a system the playground is waiting for (its key is on the page, "
        "`data-progress-url`): the part it is on and for how long. `running` is false once it has ended, or when "
        "another replica runs it."
    ),
    response_model=Progress,
    responses={422: {"model": Problem, "description": "The key is not 64 hexadecimal digits."}},
)
async def derive_progress(key: str) -> Response:
    try:
        found = await asyncio.to_thread(progress.read, _key(key))
    except Refused as exc:
        return json_problem(exc)
    body = Progress(running=False) if found is None else Progress(running=True, **found)
    return Response(body.model_dump_json(), media_type="application/json", headers={"Cache-Control": "no-store"})


@router.post(
    "/derive/cancel/{key}",
    status_code=202,
    summary="Stop a derivation you started",
    description=(
        "Stops the derivation of this key that your session started (its worker is stopped); the request "
        "waiting for it is answered 422 with `kind` `cancelled`. Refused (422) when none of yours runs here, or "
        "when others wait for the same derivation."
    ),
    responses={422: {"model": Problem, "description": "Nothing of yours to stop, with the reason."}},
)
async def derive_cancel(key: str, client: ClientDep, users: UserSystemsDep) -> Response:
    try:
        users.cancel(_key(key), client.key)
    except Refused as exc:
        return client.keep(json_problem(exc))
    return client.keep(Response('{"cancelled":true}', status_code=202, media_type="application/json"))
