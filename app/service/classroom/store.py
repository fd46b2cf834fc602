"""The classes' queries: each function opens one transaction and commits it before returning.

Synchronous (SQLAlchemy's ORM on a pooled connection): the service runs each
in a thread, never on the event loop.  Keys arrive as text and are compared
only as digests (``keys.digest``); ``access`` does the same two indexed
look-ups and one constant-time comparison whatever the code and the key, so an
unknown code and a wrong key cannot be told apart, by the answer or its time.
"""

from __future__ import annotations

import hashlib
import hmac
import json
import unicodedata
from dataclasses import dataclass
from datetime import datetime
from typing import Any

from sqlalchemy import delete, func, select
from sqlalchemy.exc import IntegrityError

from app.errors import ClassClosed, Refused, UnknownAssignment, UnknownClass, WrongKey
from app.service.classroom import keys
from app.service.classroom.database import Database, delete_class, now
from app.service.classroom.logins import checked_login
from app.service.classroom.models import (
    AssignmentRow,
    AttemptRow,
    ClassAssignmentRow,
    ClassRow,
    HintRow,
    StudentRow,
)

DONE = ("correct", "equivalent")  # the verdicts that finish a step
# an answer the checker could not read ("Not checked" on the page): recorded with its refusal, never judged, so
# counted among a student's answers and never as a wrong one (nor in the gradebook)
NOT_READ = "not read"
MAX_ASSIGNMENTS = 40  # the assignments a class's series may hold
FIRST_TITLE = "Assignment 1"  # the title of a first assignment set without one (PUT /assignment)


def pseudonym_key(name: str) -> str:
    """What two pseudonyms are compared by: equal when they read alike whatever their case or Unicode form
    ("Grace", "grace" and "ＧＲＡＣＥ" are one name), by Unicode case folding between two NFKC normalisations (NFKC
    after folding too, since folding may undo it), spaces around trimmed."""
    return unicodedata.normalize("NFKC", unicodedata.normalize("NFKC", name.strip()).casefold())


def pseudonym_digest(name: str) -> str:
    """The SHA-256 of ``pseudonym_key(name)``, kept beside each student and unique in the class (a fixed 64
    characters, whatever folding and NFKC make of 40 typed ones: "ﷺ" alone unfolds to 18)."""
    return hashlib.sha256(pseudonym_key(name).encode()).hexdigest()


def _same_pseudonym(names: list[str], name: str) -> str | None:
    """The pseudonym of ``names`` that ``name`` is: the same text first, else the one equal by ``pseudonym_key``
    (a class that joined both before the rule keeps them apart: each opens with its exact spelling)."""
    if name in names:
        return name
    wanted = pseudonym_key(name)
    alike = [n for n in names if pseudonym_key(n) == wanted]
    return alike[0] if len(alike) == 1 else None


@dataclass(frozen=True)
class Access:
    """Who a key is, in a class: its instructor (``student`` None) or one of its students."""

    class_id: int
    code: str
    title: str
    student: int | None = None
    name: str | None = None
    login_column: str | None = None  # the institution login the class asks its students for (None: none)
    login: str | None = None  # a student's own institution login, when they gave one
    joining_closed: bool = False  # the instructor closed joining: no new student (those joined keep working)
    answers_stopped: bool = False  # the instructor stopped answers: none recorded (the record kept)

    @property
    def teacher(self) -> bool:
        return self.student is None


def create_class(db: Database, title: str, login_column: str | None = None) -> tuple[str, str, str]:
    """A new class: its code, its instructor's key and its recovery code (the only time either is seen); it asks
    its students for their institution login under ``login_column`` (None: it does not).

    The key is derived from the recovery code and the class code (``keys.teacher_key_from``)."""
    recovery = keys.new_recovery_code()
    for _ in range(20):  # a code already taken: draw again
        code = keys.new_code()
        teacher_key = keys.teacher_key_from(keys.normal_recovery(recovery) or "", code)
        try:
            with db.session() as session:
                row = ClassRow(code=code, title=title, teacher_hash=keys.digest(teacher_key), created_at=now(),
                               recovery_hash=keys.digest(keys.normal_recovery(recovery) or ""), login_column=login_column)
                session.add(row)
            return code, teacher_key, recovery
        except IntegrityError:
            continue
    raise RuntimeError("no free class code after 20 draws")


def recover(db: Database, code: str, recovery: str) -> tuple[Access, str]:
    """The class and its instructor's key, from its recovery code; WrongKey for anything else.

    One indexed look-up and one constant-time comparison of two digests, whether the code names a class or not
    (a class from before recovery codes is compared against the fixed digest: no code opens it)."""
    normal = keys.normal_code(code) or ""
    typed = keys.normal_recovery(recovery)
    if typed is None:  # its shape is public: saying what is wrong with it tells nothing of the class
        raise WrongKey(keys.why_not_recovery(recovery))
    with db.session() as session:
        found = session.execute(
            select(ClassRow.id, ClassRow.code, ClassRow.title, ClassRow.recovery_hash).where(ClassRow.code == normal)
        ).first()
    stored = found.recovery_hash if found and found.recovery_hash else keys.NO_CLASS_HASH
    matches = hmac.compare_digest(stored, keys.digest(typed or ""))
    if found is None or typed is None or not matches:
        raise WrongKey("this recovery code does not open this class (check the class code and the recovery code)")
    return Access(found.id, found.code, found.title), keys.teacher_key_from(typed, found.code)


def access(db: Database, code: str, key: str) -> Access:
    """The class and role the key opens for this code; WrongKey for anything else (an unknown code included)."""
    wanted = keys.digest(key)
    normal = keys.normal_code(code) or ""
    with db.session() as session:
        found = session.execute(
            select(ClassRow.id, ClassRow.code, ClassRow.title, ClassRow.teacher_hash, ClassRow.login_column,
                   ClassRow.joining_closed_at, ClassRow.answers_stopped_at)
            .where(ClassRow.code == normal)
        ).first()
        student = session.execute(
            select(StudentRow.id, StudentRow.class_id, StudentRow.name).where(StudentRow.key_hash == wanted)
        ).first()
    teacher = hmac.compare_digest(found.teacher_hash if found else keys.NO_CLASS_HASH, wanted)
    # read from the database at each request: every replica of the server enforces what the instructor set
    joining_closed = bool(found and found.joining_closed_at)
    answers_stopped = bool(found and found.answers_stopped_at)
    if found and teacher:
        return Access(found.id, found.code, found.title, login_column=found.login_column,
                      joining_closed=joining_closed, answers_stopped=answers_stopped)
    if found and student and student.class_id == found.id:
        return Access(found.id, found.code, found.title, student.id, student.name, found.login_column,
                      joining_closed=joining_closed, answers_stopped=answers_stopped)
    raise WrongKey("this key does not open this class (check the class code and the key)")


def join(db: Database, code: str, name: str, login: str | None = None) -> tuple[str, Access, str]:
    """A new student of the class: their key, the class, and their recovery code (the only time it is seen); their
    institution login is required when the class asks for it, and refused when it does not."""
    normal = keys.normal_code(code)
    if normal is None:
        raise UnknownClass(
            f"“{code.strip()[:20]}” is not a class code: {keys.why_not_code(code)}. Check the code on the board."
        )
    student_key = keys.new_key()
    recovery = keys.new_recovery_code(keys.STUDENT_RECOVERY_LENGTH)
    try:
        return student_key, _add_student(db, normal, name, login, student_key, recovery), recovery
    except IntegrityError:  # the same name joined at the same moment
        raise _taken(name) from None


def _taken(name: str) -> Refused:
    return Refused(
        f"The name “{name}” is taken in this class: if it is you, choose “I joined before on another device” "
        "and type your recovery code (or ask your teacher for a new one); otherwise choose another name.",
        name, ("name",),
    )


def rejoin(db: Database, code: str, name: str, recovery: str) -> tuple[str, Access]:
    """A student's record opened on another device: a new key for it (the old device's key no longer opens it),
    from the pseudonym and the student's recovery code; WrongKey for anything else, after the same work."""
    normal = keys.normal_code(code) or ""
    typed = keys.normal_recovery(recovery, keys.STUDENT_RECOVERY_LENGTH)
    if typed is None:  # its shape is public: saying what is wrong with it tells nothing of the class
        raise WrongKey(keys.why_not_recovery(recovery, keys.STUDENT_RECOVERY_LENGTH))
    student_key = keys.new_key()
    with db.session() as session:
        # the pseudonym as joined, or one equal to it by case folding and NFKC ("grace" opens "Grace")
        names = session.scalars(
            select(StudentRow.name).join(ClassRow, StudentRow.class_id == ClassRow.id).where(ClassRow.code == normal)
        ).all()
        name = _same_pseudonym(list(names), name) or name
        found = session.execute(
            select(ClassRow.id, ClassRow.code, ClassRow.title, ClassRow.login_column, StudentRow)
            .join(StudentRow, StudentRow.class_id == ClassRow.id)
            .where(ClassRow.code == normal, StudentRow.name == name)
        ).first()
        stored = found.StudentRow.recovery_hash if found and found.StudentRow.recovery_hash else keys.NO_CLASS_HASH
        if found is None or not hmac.compare_digest(stored, keys.digest(typed)):
            raise WrongKey("this pseudonym and recovery code do not open a record of this class (check the class "
                           "code, your pseudonym as you typed it when you joined, and the code; or ask your teacher "
                           "for a new code)")
        found.StudentRow.key_hash = keys.digest(student_key)
        # the same record: its institution login is kept as it was given at joining
        return student_key, Access(found.id, found.code, found.title, found.StudentRow.id, name, found.login_column,
                                   found.StudentRow.login)


def set_login_column(db: Database, class_id: int, column: str | None) -> None:
    """Ask the class's students for their institution login under ``column`` from now on (None: stop asking).
    Logins already given are kept; students who joined before it was asked have none until they join again."""
    with db.session() as session:
        row = session.get(ClassRow, class_id)
        if row is not None:
            row.login_column = column


JOINING_CLOSED = ("Your teacher has closed joining for this class: ask them to open it again. A student who has "
                  "joined already opens their record with “I joined before on another device” and their recovery code.")
ANSWERS_STOPPED = ("Your teacher has stopped answers for this class: this answer is not recorded. Your answers so far "
                   "are kept; answers are taken again when your teacher reopens them.")


def set_session(db: Database, class_id: int, joining_open: bool | None, answers_open: bool | None) -> dict[str, Any]:
    """Close or reopen joining, stop or reopen answers (None: left as it is); the class's state afterwards, with the
    times each was closed (ISO 8601, UTC; None while open).  Closing what is closed keeps its first time."""
    with db.session() as session:
        row = session.get(ClassRow, class_id)
        if row is None:
            raise WrongKey("this key does not open this class (check the class code and the key)")
        if joining_open is not None:
            row.joining_closed_at = None if joining_open else row.joining_closed_at or now()
        if answers_open is not None:
            row.answers_stopped_at = None if answers_open else row.answers_stopped_at or now()
        return session_state(row)


def session_state(row: ClassRow) -> dict[str, Any]:
    """Whether the class takes new students and answers, and since when it does not."""
    iso = lambda at: None if at is None else at.isoformat() + "Z"  # noqa: E731
    return {"joining_open": row.joining_closed_at is None, "joining_closed_at": iso(row.joining_closed_at),
            "answers_open": row.answers_stopped_at is None, "answers_stopped_at": iso(row.answers_stopped_at)}


def class_session(db: Database, class_id: int) -> dict[str, Any]:
    with db.session() as session:
        row = session.get(ClassRow, class_id)
        if row is None:
            raise WrongKey("this key does not open this class (check the class code and the key)")
        return session_state(row)


def new_student_code(db: Database, class_id: int, name: str) -> str:
    """A new recovery code for a student of the class (their teacher gives it: the old one stops working)."""
    recovery = keys.new_recovery_code(keys.STUDENT_RECOVERY_LENGTH)
    with db.session() as session:
        student = session.scalar(select(StudentRow).where(StudentRow.class_id == class_id, StudentRow.name == name))
        if student is None:
            raise Refused(f"no student of this class has the pseudonym {name!r}", name, ("name",))
        student.recovery_hash = keys.digest(keys.normal_recovery(recovery, keys.STUDENT_RECOVERY_LENGTH) or "")
    return recovery


def _add_student(db: Database, normal: str, name: str, login: str | None, student_key: str, recovery: str) -> Access:
    with db.session() as session:
        found = session.execute(
            select(ClassRow.id, ClassRow.title, ClassRow.login_column, ClassRow.joining_closed_at)
            .where(ClassRow.code == normal)
        ).first()
        if found is None:
            raise UnknownClass(f"No class has the code {normal}. Check the code on the board.")
        if found.joining_closed_at is not None:
            raise ClassClosed(JOINING_CLOSED)
        kept = checked_login(found.login_column, login)
        # a pseudonym equal to one of the class's by case folding and NFKC is taken too ("Grace" and "grace")
        wanted = pseudonym_key(name)
        names = session.scalars(select(StudentRow.name).where(StudentRow.class_id == found.id)).all()
        if any(pseudonym_key(other) == wanted for other in names):
            raise _taken(name)
        # the key is unique in the class: of two equal names joining at the same moment, on any replica, the
        # database refuses the second (IntegrityError, "taken")
        student = StudentRow(class_id=found.id, name=name, name_key=pseudonym_digest(name), key_hash=keys.digest(student_key), joined_at=now(),
                             recovery_hash=keys.digest(keys.normal_recovery(recovery, keys.STUDENT_RECOVERY_LENGTH) or ""),
                             login=kept)
        session.add(student)
        session.flush()
        return Access(found.id, normal, found.title, student.id, name, found.login_column, kept)


def _item_rows(class_id: int, assignment_id: int, items: list[dict[str, Any]]) -> list[AssignmentRow]:
    return [
        AssignmentRow(
            class_id=class_id,
            assignment_id=assignment_id,
            position=position,
            item=item["item"],
            system=None if item.get("system") is None else json.dumps(item["system"]),
            steps=json.dumps(item["steps"]),
            parameters=json.dumps(item.get("parameters") or {}),
            setup=item.get("setup"),
        )
        for position, item in enumerate(items)
    ]


def _item_entry(row: AssignmentRow) -> dict[str, Any]:
    entry: dict[str, Any] = (
        {"scene": row.item} if row.system is None else {"name": row.item, "system": json.loads(row.system)}
    )
    if row.system is not None:  # a typed system's set-up (None: assigned before set-ups were asked for)
        entry["setup"] = row.setup
    return entry | {"steps": json.loads(row.steps), "parameters": json.loads(row.parameters)}


def _numbered(session: Any, class_id: int, n: int) -> ClassAssignmentRow:
    """The class's assignment number ``n`` (1 for the first), or UnknownAssignment."""
    rows = session.scalars(
        select(ClassAssignmentRow).where(ClassAssignmentRow.class_id == class_id).order_by(ClassAssignmentRow.position)
    ).all()
    if not 1 <= n <= len(rows):
        have = f"1 to {len(rows)}" if rows else "none yet"
        raise UnknownAssignment(f"this class has no assignment {n}; its assignments are numbered {have}")
    return rows[n - 1]


def add_assignment(db: Database, class_id: int, title: str, due: datetime | None, items: list[dict[str, Any]]) -> int:
    """A new assignment at the end of the class's series; its number."""
    with db.session() as session:
        count = session.scalar(
            select(func.count()).select_from(ClassAssignmentRow).where(ClassAssignmentRow.class_id == class_id)
        ) or 0
        if count >= MAX_ASSIGNMENTS:
            raise Refused(f"a class holds at most {MAX_ASSIGNMENTS} assignments; delete one first", "", ())
        row = ClassAssignmentRow(class_id=class_id, position=count, title=title, due=due)
        session.add(row)
        session.flush()
        session.add_all(_item_rows(class_id, row.id, items))
        return count + 1


def replace_assignment(
    db: Database, class_id: int, n: int, title: str | None, due: datetime | None, items: list[dict[str, Any]]
) -> None:
    """Replace assignment ``n``'s items, title (None: kept) and due time; what its students answered stays."""
    with db.session() as session:
        row = _numbered(session, class_id, n)
        if title is not None:
            row.title = title
        row.due = due
        session.execute(delete(AssignmentRow).where(AssignmentRow.assignment_id == row.id))
        session.flush()
        session.add_all(_item_rows(class_id, row.id, items))


def set_first(db: Database, class_id: int, items: list[dict[str, Any]]) -> None:
    """Set the items of the class's first assignment (created, titled FIRST_TITLE, when the series is empty)."""
    with db.session() as session:
        first = session.scalar(
            select(ClassAssignmentRow).where(ClassAssignmentRow.class_id == class_id, ClassAssignmentRow.position == 0)
        )
        if first is None:
            first = ClassAssignmentRow(class_id=class_id, position=0, title=FIRST_TITLE, due=None)
            session.add(first)
            session.flush()
        session.execute(delete(AssignmentRow).where(AssignmentRow.assignment_id == first.id))
        session.flush()
        session.add_all(_item_rows(class_id, first.id, items))


def delete_assignment(db: Database, class_id: int, n: int) -> None:
    """Remove assignment ``n`` with its items, the answers and hints recorded for it; the later ones move up."""
    with db.session() as session:
        row = _numbered(session, class_id, n)
        for table in (HintRow, AttemptRow, AssignmentRow):
            session.execute(delete(table).where(table.assignment_id == row.id))
        session.delete(row)
        session.flush()
        later = session.scalars(
            select(ClassAssignmentRow)
            .where(ClassAssignmentRow.class_id == class_id, ClassAssignmentRow.position > row.position)
            .order_by(ClassAssignmentRow.position)
        ).all()
        for each in later:  # one at a time, in order: no two rows share a position at any moment
            each.position -= 1
            session.flush()


def series(db: Database, class_id: int) -> list[dict[str, Any]]:
    """The class's assignments in order: ``{"n", "id", "title", "due", "items": [...]}`` (due: ISO 8601, UTC)."""
    with db.session() as session:
        rows = session.execute(
            select(ClassAssignmentRow, AssignmentRow)
            .outerjoin(AssignmentRow, AssignmentRow.assignment_id == ClassAssignmentRow.id)
            .where(ClassAssignmentRow.class_id == class_id)
            .order_by(ClassAssignmentRow.position, AssignmentRow.position)
        ).all()
    out: dict[int, dict[str, Any]] = {}
    for head, item in rows:
        entry = out.setdefault(head.id, {
            "n": head.position + 1, "id": head.id, "title": head.title,
            "due": None if head.due is None else head.due.isoformat() + "Z", "items": [],
        })
        if item is not None:
            entry["items"].append(_item_entry(item))
    return list(out.values())


def assignment(db: Database, class_id: int) -> list[dict[str, Any]]:
    """The items of the class's first assignment (what the single assignment was), in order."""
    found = series(db, class_id)
    return found[0]["items"] if found else []


def record_hint(db: Database, who: Access, assignment_id: int, item: str, step: str, coordinate: str | None) -> None:
    """Record that a step's answer was shown to the student (once: showing it again records nothing)."""
    if who.student is None:
        raise WrongKey("only a student's key records a shown step")
    try:
        with db.session() as session:
            session.add(HintRow(class_id=who.class_id, student_id=who.student, assignment_id=assignment_id,
                                item=item, step=step, coordinate=coordinate or "", at=now()))
    except IntegrityError:
        pass  # shown before


@dataclass(frozen=True)
class Recorded:
    """An attempt already recorded under a page's attempt id: what it was for, and the verdict it was answered."""

    item: str
    step: str
    coordinate: str | None
    answer: str
    response: bytes
    verdict: str = ""  # NOT_READ: ``response`` is the refusal (its words and where), not a verdict


def recorded(db: Database, who: Access, attempt_id: str) -> Recorded | None:
    """The student's attempt with this id, if one is recorded (a retried Check), else None."""
    with db.session() as session:
        row = session.execute(
            select(AttemptRow.item, AttemptRow.step, AttemptRow.coordinate, AttemptRow.answer, AttemptRow.response,
                   AttemptRow.verdict)
            .where(AttemptRow.student_id == who.student, AttemptRow.attempt_id == attempt_id)
        ).first()
    if row is None or row.response is None:
        return None
    return Recorded(row.item, row.step, row.coordinate, row.answer, row.response.encode(), row.verdict)


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
    assignment_id: int | None = None,
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
                assignment_id=assignment_id,
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
