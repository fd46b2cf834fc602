"""The classes: an instructor creates a class, students join with its code and a pseudonym, their checks
are recorded, and the instructor reads the summary, each student's progress and a CSV export.

Keys travel as ``Authorization: Bearer <key>``: the instructor's key on the
instructor's routes, a student's on ``check``.  No key: 401; a key that does
not open the route (a student's key on an instructor's route, another class's
key, a wrong key, an unknown code): 403, the same answer in the same time.
Every answer that carries class data says ``Cache-Control: no-store``.  The
routes are ``async``: the database is reached in threads, answers are judged
in the worker pool (app/service/classroom/service.py).
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Annotated, Any, Literal

from fastapi import APIRouter, Depends, Query
from fastapi.responses import JSONResponse, Response
from fastapi.security import HTTPAuthorizationCredentials, HTTPBearer

from app.service.classroom.keys import MAX_KEY_LENGTH
from app.service.classroom.service import Classroom
from app.web.api_user import answer
from app.web.deps import ClientDep, ServicesDep
from app.web.limits import MAX_BODY_BYTES
from app.web.schemas import Problem
from app.web.schemas_check import CheckResponse
from app.web.schemas_classes import (
    Assignment,
    ClassCheckRequest,
    ClassCreated,
    ClassView,
    Joined,
    JoinRequest,
    NewClass,
    Students,
    Summary,
)

router = APIRouter(prefix="/api/classes", tags=["classes"])
bearer = HTTPBearer(auto_error=False, description="The instructor's key, or a student's key from joining.")
NO_STORE = {"Cache-Control": "no-store"}


async def classroom(running: ServicesDep) -> Classroom:
    return running.classes


ClassroomDep = Annotated[Classroom, Depends(classroom)]


async def class_key(credentials: Annotated[HTTPAuthorizationCredentials | None, Depends(bearer)]) -> str | None:
    return credentials.credentials.strip()[:MAX_KEY_LENGTH] or None if credentials else None


KeyDep = Annotated[str | None, Depends(class_key)]

ERRORS: dict[int | str, dict[str, Any]] = {
    400: {"model": Problem, "description": "The body could not be read (not JSON, or nested too deeply)."},
    413: {"model": Problem, "description": f"The body is larger than {MAX_BODY_BYTES} bytes."},
    401: {"model": Problem, "description": "No key: send `Authorization: Bearer <key>`."},
    403: {"model": Problem, "description": "This key does not open this route of this class."},
    422: {"model": Problem, "description": "Refused: the field at fault is in `loc`."},
    429: {"model": Problem, "description": "Too many joins or checks this minute, or your check is running."},
}


def _errors(*statuses: int) -> dict[int | str, dict[str, Any]]:
    return {status: ERRORS[status] for status in statuses}


KEYED = _errors(401, 403)  # a route that needs a key


def _keyed_read(
    path: str, name: str, summary: str, model: type, read: Callable[[Classroom, str, str | None], Awaitable[Any]]
) -> None:
    """GET ``path``: what ``read`` gives the key's holder (a student or the instructor), answered no-store."""

    async def endpoint(classes: ClassroomDep, code: str, key: KeyDep) -> JSONResponse:
        return _json(await read(classes, code, key))

    router.get(path, name=name, summary=summary, response_model=model, responses=KEYED)(endpoint)


def _json(data: Any, status: int = 200) -> JSONResponse:
    return JSONResponse(data, status_code=status, headers=NO_STORE)


@router.post("", status_code=201, summary="Create a class", response_model=ClassCreated,
             responses=_errors(400, 413, 422))
async def create_class(classes: ClassroomDep, body: NewClass) -> JSONResponse:
    created = await classes.create(body.title)
    response = _json(created, 201)
    response.headers["Location"] = f"/api/classes/{created['code']}/summary"  # the class, as its instructor reads it
    return response


@router.post(
    "/{code}/join",
    summary="Join a class with a pseudonym",
    response_model=Joined,
    responses={404: {"model": Problem, "description": "No class has this code."}, **_errors(400, 413, 422, 429)},
)
async def join_class(classes: ClassroomDep, client: ClientDep, code: str, body: JoinRequest) -> Response:
    return client.keep(_json(await classes.join(code, body.name, client.key, client.address)))


_keyed_read("/{code}/me", "view_class", "The class as your key sees it", ClassView, Classroom.view)


@router.post(
    "/{code}/check",
    summary="Check a step, recorded for the class",
    description="As POST /api/scenes/{id}/check (the same verdict), plus `scene` or `system` (an assigned "
    "system's name), with a student's key. The verdict, the named mistake if any, the step and the answer are "
    "recorded, on disk before the answer is sent. With an `attempt` id, a retry of the same press returns the "
    "first verdict and records nothing new.",
    response_model=CheckResponse,
    responses={**ERRORS, 503: {"model": Problem, "description": "The server is busy."}},
)
async def check_step(classes: ClassroomDep, client: ClientDep, code: str, key: KeyDep, body: ClassCheckRequest):
    target = {"scene": body.scene, "system": body.system}

    async def work(_session: str, _address: str) -> bytes:  # the student and their class are the fair share's units
        return await classes.check(code, key, target, body.step, body.coordinate, body.answer, body.attempt)

    response = await answer(client, work)
    response.headers.update(NO_STORE)
    return response


@router.put("/{code}/assignment", summary="Set the class's assignment",
            responses=_errors(400, 401, 403, 413, 422))
async def set_assignment(classes: ClassroomDep, code: str, key: KeyDep, body: Assignment) -> JSONResponse:
    return _json(await classes.assign(code, key, [item.to_item() for item in body.items]))


_keyed_read("/{code}/summary", "class_summary", "Each step: answers, students done, named mistakes", Summary,
            Classroom.summary)
_keyed_read("/{code}/students", "class_students", "Each student's progress", Students, Classroom.students)


@router.get(
    "/{code}/export",
    summary="Every recorded attempt, as CSV",
    response_class=Response,
    responses={200: {"content": {"text/csv": {}}}, **_errors(401, 403, 422)},
)
async def export_class(
    classes: ClassroomDep, code: str, key: KeyDep, format: Annotated[Literal["csv"], Query()] = "csv"
) -> Response:
    body = await classes.export(code, key)
    safe = "".join(c for c in code.upper() if c.isalnum())[:12]
    disposition = f'attachment; filename="class-{safe}.csv"'
    return Response(body, media_type="text/csv; charset=utf-8", headers={**NO_STORE, "Content-Disposition": disposition})


@router.delete("/{code}", status_code=204, summary="Delete the class and all it recorded",
               responses=KEYED)
async def delete_class(classes: ClassroomDep, code: str, key: KeyDep) -> Response:
    await classes.delete(code, key)
    return Response(status_code=204, headers=NO_STORE)
