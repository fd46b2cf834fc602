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
from app.web.api.deps import ClientDep, ServicesDep
from app.web.api.limits import MAX_BODY_BYTES
from app.web.api.user import answer
from app.web.schemas.check import CheckResponse
from app.web.schemas.classes import (
    Assignment,
    Assignments,
    AssignmentView,
    ClassCheckRequest,
    ClassCreated,
    ClassView,
    Grades,
    Joined,
    JoinRequest,
    LoginSet,
    LoginSetting,
    NewAssignment,
    NewClass,
    Number,
    Recovered,
    RecoverRequest,
    RejoinRequest,
    SessionSetting,
    SessionState,
    Shown,
    ShowStep,
    StudentCode,
    StudentCodeRequest,
    Students,
    Summary,
)
from app.web.schemas.common import Problem

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
    409: {"model": Problem, "description": "The class's instructor has closed joining, or stopped answers: the "
          "message says which (what was recorded is kept)."},
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
    created = await classes.create(body.title, body.login_column)
    response = _json(created, 201)
    response.headers["Location"] = f"/api/classes/{created['code']}/summary"  # the class, as its instructor reads it
    return response


@router.post(
    "/{code}/join",
    summary="Join a class with a pseudonym",
    response_model=Joined,
    responses={404: {"model": Problem, "description": "No class has this code."}, **_errors(400, 409, 413, 422, 429)},
)
async def join_class(classes: ClassroomDep, client: ClientDep, code: str, body: JoinRequest) -> Response:
    return client.keep(_json(await classes.join(code, body.name, client.key, client.address, body.login)))


@router.post(
    "/{code}/rejoin",
    summary="Open your record again on another device",
    description="For a student on another device: the pseudonym and the recovery code shown at joining give the "
    "record a new key (the old device's key no longer opens it). Tries count against the joins per minute.",
    response_model=Joined,
    responses={**_errors(400, 403, 413, 422, 429)},
)
async def rejoin_class(classes: ClassroomDep, client: ClientDep, code: str, body: RejoinRequest) -> Response:
    return client.keep(_json(await classes.rejoin(code, body.name, body.recovery_code, client.key, client.address)))


@router.post(
    "/{code}/students/recovery",
    summary="A new recovery code for a student",
    description="With the instructor's key: a new recovery code for the student of this pseudonym, to hand over "
    "(their old code stops working; the server keeps only the hash of either, so it cannot show the old one).",
    response_model=StudentCode,
    responses=_errors(400, 401, 403, 413, 422),
)
async def new_student_code(classes: ClassroomDep, code: str, key: KeyDep, body: StudentCodeRequest) -> JSONResponse:
    return _json(await classes.new_student_code(code, key, body.name))


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
    target = {"scene": body.scene, "system": body.system, "assignment": body.assignment}

    async def work(_session: str, _address: str) -> bytes:  # the student and their class are the fair share's units
        return await classes.check(code, key, target, body.step, body.coordinate, body.answer, body.attempt)

    response = await answer(client, work)
    response.headers.update(NO_STORE)
    return response


@router.post(
    "/{code}/recover",
    summary="The instructor's key again, from the recovery code",
    description="For the instructor on another machine: the recovery code shown when the class was created gives "
    "back the instructor's key. Tries count against the joins per minute.",
    response_model=Recovered,
    responses={**_errors(400, 403, 413, 422, 429)},
)
async def recover_class(classes: ClassroomDep, client: ClientDep, code: str, body: RecoverRequest) -> Response:
    return client.keep(_json(await classes.recover(code, body.recovery_code, client.key, client.address)))


@router.post(
    "/{code}/shown",
    summary="Record a step shown to a student",
    description="With a student's key: the student pressed \"Show this step\" (the step's answer), a hint used "
    "in the gradebook; recorded once per student, assignment and step.",
    response_model=Shown,
    responses=_errors(400, 401, 403, 409, 413, 422),
)
async def show_step(classes: ClassroomDep, code: str, key: KeyDep, body: ShowStep) -> JSONResponse:
    target = {"scene": body.scene, "system": body.system, "assignment": body.assignment}
    return _json(await classes.show_step(code, key, target, body.step, body.coordinate))


@router.put("/{code}/login", summary="Ask students for their institution login, or not",
            description="With the instructor's key: from now on the join form asks for the students' institution "
            "login under this header (the grades file's first column), or for none (null). Logins already given are "
            "kept.", response_model=LoginSet, responses=_errors(400, 401, 403, 413, 422))
async def set_login_column(classes: ClassroomDep, code: str, key: KeyDep, body: LoginSetting) -> JSONResponse:
    return _json(await classes.set_login_column(code, key, body.login_column))


@router.put("/{code}/session", summary="Close or reopen joining; stop or reopen answers",
            description="With the instructor's key: `joining_open: false` refuses new students (409, with a message "
            "for them) while those joined keep working; `answers_open: false` refuses every answer and shown step "
            "(409) and keeps what was recorded. `true` reopens either. Kept in the class's record, so every replica "
            "of the server refuses alike.", response_model=SessionState, responses=_errors(400, 401, 403, 413, 422))
async def set_session(classes: ClassroomDep, code: str, key: KeyDep, body: SessionSetting) -> JSONResponse:
    return _json(await classes.set_session(code, key, body.joining_open, body.answers_open))


@router.put("/{code}/assignment", summary="Set the first assignment's items",
            description="Sets (or replaces) the items of the series' first assignment, created as "
            "\"Assignment 1\" when the series is empty. The series is under /assignments.",
            responses=_errors(400, 401, 403, 413, 422))
async def set_assignment(classes: ClassroomDep, code: str, key: KeyDep, body: Assignment) -> JSONResponse:
    return _json(await classes.assign(code, key, [item.to_item() for item in body.items]))


_keyed_read("/{code}/assignments", "class_assignments", "The series of assignments", Assignments,
            Classroom.assignments)

NOT_AN_ASSIGNMENT = {404: {"model": Problem, "description": "The class has no assignment of this number."}}


@router.post("/{code}/assignments", status_code=201, summary="Add an assignment to the series",
             response_model=AssignmentView, responses=_errors(400, 401, 403, 413, 422))
async def add_assignment(classes: ClassroomDep, code: str, key: KeyDep, body: NewAssignment) -> JSONResponse:
    added = await classes.add_assignment(code, key, body.title, body.due, [i.to_item() for i in body.items])
    response = _json(added, 201)
    response.headers["Location"] = f"/api/classes/{code}/assignments/{added['n']}"
    return response


@router.put("/{code}/assignments/{n}", summary="Replace an assignment of the series",
            response_model=AssignmentView, responses={**_errors(400, 401, 403, 413, 422), **NOT_AN_ASSIGNMENT})
async def replace_assignment(
    classes: ClassroomDep, code: str, n: Number, key: KeyDep, body: NewAssignment
) -> JSONResponse:
    return _json(await classes.replace_assignment(code, key, n, body.title, body.due, [i.to_item() for i in body.items]))


@router.delete("/{code}/assignments/{n}", status_code=204, summary="Delete an assignment and its answers",
               responses={**_errors(401, 403, 422), **NOT_AN_ASSIGNMENT})
async def delete_assignment(classes: ClassroomDep, code: str, n: Number, key: KeyDep) -> Response:
    await classes.delete_assignment(code, key, n)
    return Response(status_code=204, headers=NO_STORE)


@router.get(
    "/{code}/grades",
    summary="The gradebook: a score per student and assignment",
    description="JSON, or with `format=csv` the file to import into an LMS: one row per student, one column per "
    "assignment (its score out of 100, blank when the student has tried nothing of an assignment not yet due or "
    "with no due time) and nothing else; `format=details-csv`: per assignment its score, then its parts (right "
    "first try, right, shown, steps).  The score: the assignment's steps answered right without the answer shown "
    "first, out of its steps.",
    response_model=Grades,
    responses={200: {"content": {"text/csv": {}}}, **_errors(401, 403, 422)},
)
async def class_grades(
    classes: ClassroomDep, code: str, key: KeyDep,
    format: Annotated[Literal["json", "csv", "details-csv"], Query()] = "json",
) -> Response:
    if format == "json":
        return _json(await classes.grades(code, key))
    body = await classes.grades_csv(code, key, details=format == "details-csv")
    safe = "".join(c for c in code.upper() if c.isalnum())[:12]
    name = f"grades-{safe}{'-details' if format == 'details-csv' else ''}.csv"
    disposition = f'attachment; filename="{name}"'
    return Response(body, media_type="text/csv; charset=utf-8", headers={**NO_STORE, "Content-Disposition": disposition})


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
