"""The step checker: a student's answer for one step, judged against the engine's derivation.

The routes are ``async`` and run no SymPy: the service refuses bad text in pure
Python and judges the answer in the worker pool (app/service/tutor/checking.py), as
/api/derive does for a declared system. The practice routes list each system's
steps with the engine's answers, for the practice mode of the pages.
"""

from __future__ import annotations

import asyncio

from fastapi import APIRouter
from fastapi.responses import Response

from app.service.tutor.checking import declared
from app.web.api.deps import CheckingDep, ClientDep
from app.web.api.user import answer
from app.web.schemas.check import CheckRequest, CheckResponse, Exercises, SystemCheckRequest
from app.web.schemas.common import Problem
from app.web.schemas.user import SystemSpec

router = APIRouter(prefix="/api", tags=["practice"])

ERRORS = {
    400: {"model": Problem, "description": "The body could not be read (not JSON, or not UTF-8)."},
    404: {"model": Problem, "description": "No scene has this id (the message lists the known ones)."},
    413: {"model": Problem, "description": "The body is larger than 32 KiB."},
    422: {
        "model": Problem,
        "description": "Refused: `loc` names the field (`answer`, `step`, `coordinate`, or `system.…`); for an "
        "answer, `part` and `start`/`end` locate the offending part; an unknown step or coordinate lists the "
        "allowed ones.",
    },
    429: {"model": Problem, "description": "You already have a job running (one at a time per session)."},
    503: {"model": Problem, "description": "The server is busy with other users' jobs."},
}


@router.post(
    "/scenes/{scene_id}/check",
    summary="Check a step of a scene",
    description="Judge a student's expression for one step against the engine's: `correct`, `equivalent` (a "
    "constant added to U, L or h; an equation times a nonzero factor) or `incorrect` with a hint naming the mistake (the difference is kept in `reveal`, for the step). "
    "An incorrect answer that matches a mistake generated from the system's derivation names it (`mistake`), says "
    "what else is right (`partial`) and may ask a follow-up question (`follow_up`), answered by sending its `key` "
    "as `follow_up` with the same step.",
    response_model=CheckResponse,
    responses=ERRORS,
)
async def check_scene_step(client: ClientDep, checker: CheckingDep, scene_id: str, body: CheckRequest) -> Response:
    return await answer(
        client,
        lambda key, address: checker.check_scene(
            scene_id, body.step, body.coordinate, body.answer, key, address, body.follow_up
        ),
    )


@router.post(
    "/check",
    summary="Check a step of a system you declare",
    description="As POST /api/scenes/{id}/check, for the system in `system` (the request shape of POST /api/derive).",
    response_model=CheckResponse,
    responses=ERRORS,
)
async def check_system_step(client: ClientDep, checker: CheckingDep, body: SystemCheckRequest) -> Response:
    return await answer(
        client,
        lambda key, address: checker.check_system(
            declared(body.system.to_spec()), body.step, body.coordinate, body.answer, key, address, body.follow_up
        ),
    )


@router.get(
    "/scenes/{scene_id}/practice",
    summary="The steps a student can check for a scene",
    response_model=Exercises,
    responses={404: ERRORS[404]},
)
async def scene_exercises(checker: CheckingDep, scene_id: str) -> Response:
    return Response(await asyncio.to_thread(checker.scene_exercises, scene_id), media_type="application/json")


@router.post(
    "/practice",
    summary="The steps a student can check for a system you declare",
    response_model=Exercises,
    responses=ERRORS,
)
async def system_exercises(client: ClientDep, checker: CheckingDep, system: SystemSpec) -> Response:
    return await answer(client, lambda key, address: checker.system_exercises(declared(system.to_spec()), key, address))
