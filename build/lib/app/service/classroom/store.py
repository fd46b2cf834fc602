"""The classes' queries: each function opens one transaction and commits it before returning.

Synchronous (SQLAlchemy's ORM on a pooled connection): the service runs each
in a thread, never on the event loop.  Keys arrive as text and are compared
only as digests (``keys.digest``); ``access`` does the same two indexed
look-ups and one constant-time comparison whatever the code and the key, so an
unknown code and a wrong key cannot be told apart, by the answer or its time.
"""

from __future__ import annotations

import hmac
import json
from dataclasses import dataclass
from typing import Any

from sqlalchemy import delete, func, select
from sqlalchemy.exc import IntegrityError

from app.errors import Refused, UnknownClass, WrongKey
from app.service.classroom import keys
from app.service.classroom.database import Database, delete_class, now
from app.service.classroom.models import AssignmentRow, AttemptRow, ClassRow, StudentRow

DONE = ("correct", "equivalent")  # the verdicts that finish a step


@dataclass(frozen=True)
class Access:
    """Who a key is, in a class: its instructor (``student`` None) or one of its students."""

    class_id: int
    code: str
    title: str
    student: int | None = None
    name: str | None = None

    @property
    def teacher(self) -> bool:
        return self.student is None


def create_class(db: Database, title: str) -> tuple[str, str]:
    """A new class: its code and its instructor's key (the only time the key is seen)."""
    teacher_key = keys.new_key()
    for _ in range(20):  # a code already taken: draw again
        code = keys.new_code()
        try:
            with db.session() as session:
                row = ClassRow(code=code, title=title, teacher_hash=keys.digest(teacher_key), created_at=now())
                session.add(row)
            return code, teacher_key
        except IntegrityError:
            continue
    raise RuntimeError("no free class code after 20 draws")


def access(db: Database, code: str, key: str) -> Access:
    """The class and role the key opens for this code; WrongKey for anything else (an unknown code included)."""
    wanted = keys.digest(key)
    normal = keys.normal_code(code) or ""
    with db.session() as session:
        found = session.execute(
            select(ClassRow.id, ClassRow.code, ClassRow.title, ClassRow.teacher_hash).where(ClassRow.code == normal)
        ).first()
        student = session.execute(
            select(StudentRow.id, StudentRow.class_id, StudentRow.name).where(StudentRow.key_hash == wanted)
        ).first()
    teacher = hmac.compare_digest(found.teacher_hash if found else keys.NO_CLASS_HASH, wanted)
    if found and teacher:
        return Access(found.id, found.code, found.title)
    if found and student and student.class_id == found.id:
        return Access(found.id, found.code, found.title, student.id, student.name)
    raise WrongKey("this key does not open this class (check the class code and the key)")


def join(db: Database, code: str, name: str) -> tuple[str, Access]:
    """A new student of the class: their key, and the class."""
    normal = keys.normal_code(code)
    if normal is None:
        raise UnknownClass(
            f"a class code is {keys.CODE_LENGTH} characters from {keys.ALPHABET}; check the code on the board"
        )
    student_key = keys.new_key()
    try:
        return student_key, _add_student(db, normal, name, student_key)
    except IntegrityError:  # the same name joined at the same moment
        raise _taken(name) from None


def _taken(name: str) -> Refused:
    return Refused(f"the name {name!r} is taken in this class; choose another", name, ("name",))


def _add_student(db: Database, normal: str, name: str, student_key: str) -> Access:
    with db.session() as session:
        found = session.execute(select(ClassRow.id, ClassRow.title).where(ClassRow.code == normal)).first()
        if found is None:
            raise UnknownClass(f"no class has the code {normal}; check the code on the board")
        taken = session.scalar(
            select(func.count()).select_from(StudentRow).where(StudentRow.class_id == found.id, StudentRow.name == name)
        )
        if taken:
            raise _taken(name)
        student = StudentRow(class_id=found.id, name=name, key_hash=keys.digest(student_key), joined_at=now())
        session.add(student)
        session.flush()
        return Access(found.id, normal, found.title, student.id, name)


def set_assignment(db: Database, class_id: int, items: list[dict[str, Any]]) -> None:
    """Replace the class's assignment with ``items`` (each: item, system or None, steps, parameters)."""
    with db.session() as session:
        session.execute(delete(AssignmentRow).where(AssignmentRow.class_id == class_id))
        for position, item in enumerate(items):
            session.add(
                AssignmentRow(
                    class_id=class_id,
                    position=position,
                    item=item["item"],
                    system=None if item.get("system") is None else json.dumps(item["system"]),
                    steps=json.dumps(item["steps"]),
                    parameters=json.dumps(item.get("parameters") or {}),
                )
            )


def assignment(db: Database, class_id: int) -> list[dict[str, Any]]:
    """The class's assignment, in order: ``{"scene" | "system", "name", "steps", "parameters"}``."""
    with db.session() as session:
        rows = session.scalars(
            select(AssignmentRow).where(AssignmentRow.class_id == class_id).order_by(AssignmentRow.position)
        ).all()
    items = []
    for row in rows:
        entry: dict[str, Any] = (
            {"scene": row.item} if row.system is None else {"name": row.item, "system": json.loads(row.system)}
        )
        entry |= {"steps": json.loads(row.steps), "parameters": json.loads(row.parameters)}
        items.append(entry)
    return items


@dataclass(frozen=True)
class Recorded:
    """An attempt already recorded under a page's attempt id: what it was for, and the verdict it was answered."""

    item: str
    step: str
    coordinate: str | None
    answer: str
    response: bytes


def recorded(db: Database, who: Access, attempt_id: str) -> Recorded | None:
    """The student's attempt with this id, if one is recorded (a retried Check), else None."""
    with db.session() as session:
        row = session.execute(
            select(AttemptRow.item, AttemptRow.step, AttemptRow.coordinate, AttemptRow.answer, AttemptRow.response)
            .where(AttemptRow.student_id == who.student, AttemptRow.attempt_id == attempt_id)
        ).first()
    if row is None or row.response is None:
        return None
    return Recorded(row.item, row.step, row.coordinate, row.answer, row.response.encode())


def record(
    db: Database,
    who: Access,
    item: str,
    step: str,
    coordinate: str | None,
    verdict: str,
    mistake: str | None,
    answer: str,
    mistake_name: str | None = None,
    attempt_id: str | None = None,
    response: bytes | None = None,
) -> Recorded | None:
    """Record one judged answer; committed (on disk) when this returns.

    With an ``attempt_id`` (and the ``response`` answered), an attempt of the student already recorded under
    that id is kept and returned instead (a retry that raced the first press to the database); else None."""
    if who.student is None:
        raise WrongKey("only a student's key records answers")
    try:
        with db.session() as session:
            session.add(AttemptRow(
                class_id=who.class_id,
                student_id=who.student,
                item=item,
                step=step,
                coordinate=coordinate,
                verdict=verdict,
                mistake=mistake,
                mistake_name=mistake_name,
                answer=answer,
                at=now(),
                attempt_id=attempt_id,
                response=None if response is None else response.decode(),
            ))
    except IntegrityError:
        first = recorded(db, who, attempt_id) if attempt_id is not None else None
        if first is None:
            raise
        return first
    return None


def delete_whole_class(db: Database, class_id: int) -> None:
    with db.session() as session:
        delete_class(session, class_id)
