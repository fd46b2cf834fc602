"""``Classroom``: what the class routes call — create, recover, join, check and record, show a step, report,
grade, assign (a series of assignments), delete.

Every database call runs in a thread (``asyncio.to_thread``); the event loop
only awaits.  A student's check is practice mode's check (app/service/tutor/checking.py,
the same worker pool, answer cache and fair share, keyed on the student), then
the verdict is recorded and committed before the answer goes back: what a
student has been told is on disk.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from datetime import datetime
from typing import Any, TypeVar

import orjson

from app.engine.tutor.check import KEYED
from app.engine.tutor.mistakes import RULES
from app.errors import ClassClosed, NoKey, Refused, WrongKey
from app.service.classroom import grades, keys, reports, store
from app.service.classroom.assignments import checked_due, checked_items, find_target
from app.service.classroom.database import Database
from app.service.classroom.rates import Window
from app.service.classroom.setup import givens
from app.service.classroom.shared_rates import SharedWindow, Store
from app.service.runtime.fairness import CLASS, shared
from app.service.tutor.checking import Checking, declared
from app.service.users.user_checks import InvalidSystem
from app.settings import Settings

T = TypeVar("T")
# the checker's hint for a matched mistake, back to the mistake's name (when the verdict carries no name)
_NAMED_BY_HINT = {rule.hint: rule.mistake for rule in RULES}


def named_mistake(result: dict[str, Any]) -> str | None:
    """The named mistake of a verdict: its ``mistake`` field (a name, or an object with one), else the mistake
    whose hint the checker gave; None for a right answer or an unrecognised mistake."""
    if result.get("verdict") != "incorrect":
        return None
    named = result.get("mistake")
    if isinstance(named, dict):
        named = named.get("key") or named.get("name")
    if isinstance(named, str) and named:
        return named[:60]
    return _NAMED_BY_HINT.get(result.get("hint") or "")


def mistake_text(result: dict[str, Any]) -> str | None:
    """The named mistake's display text (the tutor's ``mistake.name``), when the verdict carries one."""
    named = result.get("mistake") if result.get("verdict") == "incorrect" else None
    text = named.get("name") if isinstance(named, dict) else None
    return text[:200] if isinstance(text, str) and text else None


def _same_attempt(first: store.Recorded, this: tuple[str, str, str | None, str], attempt_id: str) -> bytes:
    """The first verdict of an attempt sent again (or the first refusal, of an answer not read); refused when the
    id comes back with another answer."""
    if (first.item, first.step, first.coordinate, first.answer) != this:
        raise Refused(
            "attempt: this attempt id was already used for another answer; send a new id with a new answer",
            attempt_id, ("attempt",),
        )
    if first.verdict == store.NOT_READ:
        raise unread_refusal(first.response)
    return first.response


def _unread(exc: Refused) -> bool:
    """Whether a refusal of a check is of the answer itself (the checker could not read it: "Not checked")."""
    return exc.loc == ("answer",)


def refusal_record(exc: Refused) -> bytes:
    """A refusal of an answer as recorded beside the attempt: its words, where, and its readings."""
    return orjson.dumps({"detail": str(exc), "loc": list(exc.loc or ()), "part": exc.part, "start": exc.start,
                         "end": exc.end, "readings": list(getattr(exc, "readings", ()))})


def unread_refusal(recorded: bytes) -> InvalidSystem:
    """The refusal an attempt not read was answered, again (a retry of the same press gets the same words)."""
    found = orjson.loads(recorded)
    return InvalidSystem(found["detail"], tuple(found["loc"]), found["part"], found["start"], found["end"],
                         tuple(found["readings"]))


class Classroom:
    """The classes of one web process: their database (connected at first use) and their rate windows."""

    def __init__(self, checking: Checking, config: Settings) -> None:
        self.db = Database(config)
        self.checking = checking
        # with a shared store every replica counts the same windows; else each counts its own
        self.store = Store(config.shared_store_url) if config.shared_store_url else None

        def window(limit: int, what: str, name: str) -> Window:
            return SharedWindow(limit, what, self.store, name) if self.store else Window(limit, what)

        self.class_joins = window(config.class_joins_per_minute, "joins to this class", "class-joins")
        self.client_joins = window(config.client_joins_per_minute, "joins from you", "client-joins")
        self.class_joins_by_address = window(
            config.class_joins_per_minute, "joins from your network address", "address-joins"
        )
        self.class_checks = window(config.class_checks_per_minute, "checks in this class", "class-checks")
        self.student_checks = window(config.student_checks_per_minute, "your checks", "student-checks")

    async def _db(self, work: Callable[..., T], *args: Any) -> T:
        return await asyncio.to_thread(work, self.db, *args)

    # ---- who is asking -------------------------------------------------------------------------
    def _who(self, db: Database, code: str, key: str | None, teacher: bool) -> store.Access:
        if key is None:
            whose = "the instructor's key" if teacher else "your student key (from joining)"
            raise NoKey(f"this route needs {whose} in an 'Authorization: Bearer <key>' header")
        who = store.access(db, code, key)
        if teacher and not who.teacher:
            raise WrongKey("a student's key does not open the instructor's view of a class")
        if not teacher and who.teacher:
            raise WrongKey("answers are recorded for students: join the class to get a student key")
        return who

    def _with_series(self, db: Database, code: str, key: str | None, teacher: bool):
        who = self._who(db, code, key, teacher)
        return who, store.series(db, who.class_id)

    # ---- instructor ----------------------------------------------------------------------------
    async def create(self, title: str, login_column: str | None = None) -> dict[str, str]:
        code, teacher_key, recovery = await self._db(store.create_class, title, login_column)
        # the teacher link carries the recovery code in its fragment: a browser never sends a fragment to a server
        return {"code": code, "teacher_key": teacher_key, "recovery_code": recovery,
                "teacher_link": f"/teach#class={code}&recover={recovery}"}

    async def recover(self, code: str, recovery: str, client: str, address: str) -> dict[str, str]:
        """The instructor's key of a class again, from its recovery code; tries count as joins do."""
        await self._count_join(code, client, address)
        who, teacher_key = await self._db(store.recover, code, recovery)
        return {"code": who.code, "title": who.title, "teacher_key": teacher_key}

    async def set_login_column(self, code: str, key: str | None, column: str | None) -> dict[str, Any]:
        """Ask the class's students for their institution login under ``column`` from now on (None: not)."""
        who = await self._db(self._who, code, key, True)
        await self._db(store.set_login_column, who.class_id, column)
        return {"code": who.code, "login_column": column}

    async def set_session(
        self, code: str, key: str | None, joining_open: bool | None, answers_open: bool | None
    ) -> dict[str, Any]:
        """Close or reopen joining, stop or reopen answers (None: as it is); kept in the class's record, so every
        replica of the server refuses alike.  What was recorded stays."""
        who = await self._db(self._who, code, key, True)
        return {"code": who.code} | await self._db(store.set_session, who.class_id, joining_open, answers_open)

    async def assign(self, code: str, key: str | None, items: list[dict[str, Any]]) -> dict[str, Any]:
        """Set the items of the first assignment of the series (the single assignment of before)."""
        who = await self._db(self._who, code, key, True)
        stored = await asyncio.to_thread(checked_items, self.checking, items)
        await self._db(store.set_first, who.class_id, stored)
        return {"code": who.code, "assignment": await self._db(store.assignment, who.class_id)}

    async def assignments(self, code: str, key: str | None) -> dict[str, Any]:
        who, found = await self._db(self._with_series, code, key, True)
        return {"code": who.code, "assignments": public(found)}

    async def add_assignment(
        self, code: str, key: str | None, title: str, due: datetime | None, items: list[dict[str, Any]]
    ) -> dict[str, Any]:
        who = await self._db(self._who, code, key, True)
        when = checked_due(due)
        stored = await asyncio.to_thread(checked_items, self.checking, items)
        n = await self._db(store.add_assignment, who.class_id, title, when, stored)
        return public(await self._db(store.series, who.class_id))[n - 1]

    async def replace_assignment(
        self, code: str, key: str | None, n: int, title: str | None, due: datetime | None, items: list[dict[str, Any]]
    ) -> dict[str, Any]:
        who, found = await self._db(self._with_series, code, key, True)
        kept = next((a["due"] for a in found if a["n"] == n), None)
        when = checked_due(due, kept)
        stored = await asyncio.to_thread(checked_items, self.checking, items)
        await self._db(store.replace_assignment, who.class_id, n, title, when, stored)
        return public(await self._db(store.series, who.class_id))[n - 1]

    async def delete_assignment(self, code: str, key: str | None, n: int) -> None:
        who = await self._db(self._who, code, key, True)
        await self._db(store.delete_assignment, who.class_id, n)

    def _report(self, db: Database, code: str, key: str | None, report: Callable[..., T]) -> T:
        who, found = self._with_series(db, code, key, True)
        return report(db, who.class_id, found)

    async def grades(self, code: str, key: str | None) -> dict[str, Any]:
        def read(db: Database) -> dict[str, Any]:
            who, found = self._with_series(db, code, key, True)
            return grades.gradebook(db, who.class_id, found, who.login_column)

        return await self._db(read)

    async def grades_csv(self, code: str, key: str | None, details: bool = False) -> bytes:
        book = await self.grades(code, key)
        return (grades.gradebook_details_csv if details else grades.gradebook_csv)(book)

    async def summary(self, code: str, key: str | None) -> dict[str, Any]:
        return await self._db(self._report, code, key, reports.summary)

    async def students(self, code: str, key: str | None) -> dict[str, Any]:
        return await self._db(self._report, code, key, reports.students)

    async def export(self, code: str, key: str | None) -> bytes:
        return await self._db(self._report, code, key, reports.export_csv)

    async def delete(self, code: str, key: str | None) -> None:
        who = await self._db(self._who, code, key, True)
        await self._db(store.delete_whole_class, who.class_id)

    # ---- students ------------------------------------------------------------------------------
    async def _count_join(self, code: str, client: str, address: str) -> None:
        # a session joins at most client_joins_per_minute times; a request that counts as one of its address's
        # shared keys (no cookie: ``new:``, or beyond the address's sessions this minute: ``many:``) counts
        # against its network, which may bring a whole class (class_joins_per_minute)
        if shared(client):
            await self.class_joins_by_address.take(address)
        else:
            await self.client_joins.take(client)
        await self.class_joins.take(keys.normal_code(code) or "?")

    async def join(self, code: str, name: str, client: str, address: str, login: str | None = None) -> dict[str, Any]:
        await self._count_join(code, client, address)
        student_key, who, recovery = await self._db(store.join, code, name, login)
        return await self._joined(student_key, who, name) | {"recovery_code": recovery}

    async def rejoin(self, code: str, name: str, recovery: str, client: str, address: str) -> dict[str, Any]:
        """A student's record on another device, from their pseudonym and recovery code; tries count as joins."""
        await self._count_join(code, client, address)
        student_key, who = await self._db(store.rejoin, code, name, recovery)
        return await self._joined(student_key, who, who.name or name)  # the pseudonym as joined ("Grace", not "grace")

    async def _joined(self, student_key: str, who: store.Access, name: str) -> dict[str, Any]:
        found = await self._db(store.series, who.class_id)
        return {"student_key": student_key, "code": who.code, "title": who.title, "name": name,
                "login_column": who.login_column, "login": who.login,
                "assignment": found[0]["items"] if found else [], "assignments": public(found)}

    async def new_student_code(self, code: str, key: str | None, name: str) -> dict[str, str]:
        """A new recovery code for a student, for their teacher to hand over (the old code stops working)."""
        who = await self._db(self._who, code, key, True)
        return {"name": name, "recovery_code": await self._db(store.new_student_code, who.class_id, name)}

    async def view(self, code: str, key: str | None) -> dict[str, Any]:
        """The class as its key sees it: title and assignment, and for a student their own progress."""
        if key is None:
            raise NoKey("this route needs a key of the class in an 'Authorization: Bearer <key>' header")

        def read(db: Database) -> dict[str, Any]:
            who = store.access(db, code, key)
            found = store.series(db, who.class_id)
            seen: dict[str, Any] = {"code": who.code, "title": who.title, "login_column": who.login_column,
                                    "assignment": found[0]["items"] if found else [], "assignments": public(found),
                                    "session": store.class_session(db, who.class_id)}
            if who.teacher:
                return seen | {"role": "instructor"}
            progress = [s for s in reports.students(db, who.class_id, found)["students"] if s["name"] == who.name]
            # the student's last answer per step, its verdict and the steps shown: the page as they left it
            mine = reports.own_record(db, who.class_id, who.student or 0, found)
            return seen | {"role": "student", "name": who.name, "progress": progress[0] if progress else None,
                           "record": mine}

        return await asyncio.to_thread(read, self.db)

    async def check(
        self,
        code: str,
        key: str | None,
        target: dict[str, str | None],
        step: str,
        coordinate: str | None,
        answer: str,
        attempt_id: str | None = None,
    ) -> bytes:
        """Judge a student's answer as practice mode does, record the verdict, then answer with it.

        A press of Check the page already sent (the same ``attempt_id``) gets the verdict first answered for it,
        judged and recorded once."""
        who, found = await self._db(self._with_series, code, key, False)
        assigned, item = find_target(found, target, step, coordinate)
        name = item["name"] if item.get("system") is not None else item["scene"]
        recorded = coordinate if step in KEYED else None
        this = (name, step, recorded, answer.strip())
        if attempt_id is not None and (first := await self._db(store.recorded, who, attempt_id)) is not None:
            return _same_attempt(first, this, attempt_id)
        if who.answers_stopped:  # an answer already recorded is answered as it was (above); a new one is refused
            raise ClassClosed(store.ANSWERS_STOPPED)
        await self.student_checks.take(f"{who.class_id}:{who.student}")
        await self.class_checks.take(who.code)
        # the student is the unit of fairness, their class's budget of check slots the bound (not their network's)
        client, address = f"class-student:{who.class_id}:{who.student}", f"{CLASS}{who.class_id}"
        try:
            if item.get("system") is not None:
                body = await self.checking.check_system(
                    declared(item["system"]), step, coordinate, answer, client, address
                )
            else:
                body = await self.checking.check_scene(name, step, coordinate, answer, client, address)
        except Refused as exc:
            if not _unread(exc):
                raise
            # an answer that could not be read is one of the student's answers: recorded with its refusal (on disk
            # before the refusal goes back), never judged
            raced = await self._db(
                store.record, who, name, step, recorded, store.NOT_READ, None, answer.strip(), None, attempt_id,
                refusal_record(exc), assigned["id"] if assigned else None,
            )
            if raced is not None:
                return _same_attempt(raced, this, attempt_id or "")
            raise
        result = orjson.loads(body)
        raced = await self._db(
            store.record, who, name, step, recorded, result["verdict"], named_mistake(result), answer.strip(),
            mistake_text(result), attempt_id, body if attempt_id is not None else None,
            assigned["id"] if assigned else None,
        )
        return body if raced is None else _same_attempt(raced, this, attempt_id or "")

    async def show_step(
        self, code: str, key: str | None, target: dict[str, Any], step: str, coordinate: str | None
    ) -> dict[str, Any]:
        """Record that a student was shown a step's answer ("Show this step"): a hint used, in the gradebook."""
        who, found = await self._db(self._with_series, code, key, False)
        if who.answers_stopped:  # a shown step is recorded as a hint used: refused with the answers
            raise ClassClosed(store.ANSWERS_STOPPED)
        assigned, item = find_target(found, target, step, coordinate)
        if assigned is None:
            raise Refused("nothing is assigned in this class: a shown step is recorded for an assigned step", step,
                          ("step",))
        name = item["name"] if item.get("system") is not None else item["scene"]
        recorded = coordinate if step in KEYED else None
        await self._db(store.record_hint, who, assigned["id"], name, step, recorded)
        return {"assignment": assigned["n"], "step": step, "coordinate": recorded}

    def stop(self) -> None:
        self.db.stop()



def public(found: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The series as the API shows it (without the database's ids); a typed system's item with ``given``, its
    defining data typeset for the students (app/service/classroom/setup.py)."""
    return [{k: v for k, v in a.items() if k != "id"} | {"items": [_shown(i) for i in a["items"]]} for a in found]


def _shown(item: dict[str, Any]) -> dict[str, Any]:
    return item if item.get("system") is None else item | {"given": givens(item)}
