"""The gradebook: per student and assignment, a score a teacher can read, and its CSV for an LMS.

For each assigned step a student has

* **right**: one of their answers to it was judged correct or equivalent;
* **first try**: their first answer to it was right;
* **shown**: they pressed "Show this step" on /join, which shows the step's answer (a hint used).

The score of an assignment is the share of its steps the student got right on their own by its due time, that is
right, not shown before their first right answer, and that answer not after the due time (a late answer is recorded
and marked late in the answers' file, never counted), in points out of 100 (one decimal).  The parts are given beside it, as
counts out of the assignment's steps, so a teacher can weigh them otherwise.  A student who has neither answered
nor been shown a step of an assignment that is not yet due (or has no due time) has no score (blank, not 0):
a grade imported before the due time posts no zero; once it is due, no answer scores 0.

Both CSV files start with a UTF-8 byte-order mark, so a spreadsheet opened by a double click reads θ̈ and ₁.
Two CSV files: the one to import into an LMS's gradebook (one row per student, one column per assignment: its
score, nothing else), and the detailed one (per assignment its score and its parts).

Read in **one SELECT** (the answers grouped per student and step, beside the steps shown, in a UNION ALL), so the
grades come from one state of the database, as the summary's figures do.
"""

from __future__ import annotations

import csv
import io
from collections import defaultdict
from collections.abc import Callable
from datetime import UTC, datetime
from typing import Any

from sqlalchemy import case, func, literal, null, select, union_all

from app.service.classroom.database import Database
from app.service.classroom.models import AttemptRow, HintRow, StudentRow
from app.service.classroom.reports import BOM, FORMULA_START, assigned_keys, due_utc, on_own
from app.service.classroom.store import DONE, NOT_READ

POINTS = 100  # an assignment's score is out of this many points
PARTS = (("first_try", "right first try"), ("right", "right"), ("shown", "shown"), ("steps", "steps"))


def _rows(db: Database, class_id: int) -> list[Any]:
    """Per student (every one) and step: the first answer's id, the first right answer's id and time; per student
    and step shown: when.  One statement, one snapshot."""
    right = AttemptRow.verdict.in_(DONE)
    answers = (
        select(StudentRow.id, StudentRow.name, StudentRow.joined_at, StudentRow.login, AttemptRow.assignment_id,
               AttemptRow.item, AttemptRow.step, func.coalesce(AttemptRow.coordinate, ""), literal("answer"),
               func.min(AttemptRow.id), func.min(case((right, AttemptRow.id))), func.min(case((right, AttemptRow.at))))
        .select_from(StudentRow)
        # an answer not read was never judged: neither a try nor a wrong answer in the gradebook
        .outerjoin(AttemptRow, (AttemptRow.student_id == StudentRow.id) & (AttemptRow.verdict != NOT_READ))
        .where(StudentRow.class_id == class_id)
        .group_by(StudentRow.id, StudentRow.name, StudentRow.joined_at, StudentRow.login, AttemptRow.assignment_id,
                  AttemptRow.item, AttemptRow.step, AttemptRow.coordinate)
    )
    shown = (
        select(StudentRow.id, StudentRow.name, StudentRow.joined_at, StudentRow.login, HintRow.assignment_id,
               HintRow.item, HintRow.step, HintRow.coordinate, literal("shown"), null(), null(), HintRow.at)
        .join(StudentRow, StudentRow.id == HintRow.student_id)
        .where(HintRow.class_id == class_id)
    )
    with db.session() as session:
        return list(session.execute(union_all(answers, shown)).all())


def gradebook(db: Database, class_id: int, series: list[dict[str, Any]], login_column: str | None = None) -> dict[str, Any]:
    """``{"login_column", "assignments": [{"n", "title", "due", "steps"}], "students": [{"name", "login", "grades":
    [{"assignment", "steps", "first_try", "right", "shown", "score"}]}]}``, students in the order they joined;
    ``login_column`` is the header of the institution login the class asks for (None: it does not)."""
    people: dict[int, tuple[str, Any, str | None]] = {}
    first: dict[tuple, tuple[int | None, int | None, Any]] = {}  # (student, key): first id, first right id, its time
    shown_at: dict[tuple, Any] = {}
    for student, name, joined, login, assignment_id, item, step, coordinate, kind, first_id, right_id, at in (
        _rows(db, class_id)
    ):
        people[student] = (name, joined, login)
        if item is None:  # a student with no answer yet
            continue
        key = (student, (assignment_id, item, step, coordinate or None))
        if kind == "shown":
            shown_at[key] = at
        else:
            first[key] = (first_id, right_id, at)
    now = datetime.now(UTC).replace(tzinfo=None)  # due times are stored naive, in UTC
    heads = [{"n": a["n"], "title": a["title"], "due": a["due"], "steps": len(assigned_keys([a]))} for a in series]
    rows = []
    for student, (name, _joined, login) in sorted(people.items(), key=lambda p: (p[1][1], p[0])):
        grades = []
        for each, head in zip(series, heads, strict=True):
            count: defaultdict[str, int] = defaultdict(int)
            for step in assigned_keys([each]):
                first_id, right_id, right_at = first.get((student, step), (None, None, None))
                seen = shown_at.get((student, step))
                count["tried"] += first_id is not None or seen is not None
                count["right"] += right_id is not None
                count["shown"] += seen is not None
                # on their own: right by the due time, and the step not shown before the first right answer
                own = on_own(right_at, seen, each["due"])
                count["own"] += own
                count["first_try"] += own and first_id == right_id
            score: float | None = round(POINTS * count["own"] / head["steps"], 1) if head["steps"] else 0.0
            # nothing tried before it is due (or when it has no due time): no score yet, not a zero
            due = due_utc(each["due"])
            if not count["tried"] and (due is None or due > now):
                score = None
            grades.append({"assignment": head["n"], "steps": head["steps"], "first_try": count["first_try"],
                           "right": count["right"], "shown": count["shown"], "score": score})
        rows.append({"name": name, "login": login, "grades": grades})
    return {"points": POINTS, "login_column": login_column, "assignments": heads, "students": rows}


def _cell(value: Any) -> str:
    """A cell a spreadsheet will not run (as the attempts' export): a formula's start gets an apostrophe."""
    text = "" if value is None else str(value)
    return "'" + text if text.startswith(FORMULA_START) else text


def _sheet(header: list[str], rows: list[list[Any]]) -> bytes:
    out = io.StringIO()
    out.write(BOM)
    writer = csv.writer(out, lineterminator="\r\n")
    writer.writerow([_cell(h) for h in header])
    writer.writerows([_cell(value) for value in row] for row in rows)
    return out.getvalue().encode("utf-8")


def _who(book: dict[str, Any]) -> tuple[list[str], Callable[[dict[str, Any]], list[Any]]]:
    """The columns naming a student: the institution login first, under the header its LMS matches rows by
    ("SIS Login ID" for Canvas, "username" for Moodle), when the class asks for it; then the pseudonym."""
    column = book.get("login_column")
    if column is None:
        return ["Student"], lambda s: [s["name"]]
    return [column, "Student"], lambda s: [s.get("login"), s["name"]]


def gradebook_csv(book: dict[str, Any]) -> bytes:
    """The file to import: one row per student, keyed by their institution login when the class asks for it, one
    column per assignment (its score out of ``POINTS``, blank when there is none yet) and nothing else, so an
    LMS's import makes one grade item per assignment."""
    titles = [f"{a['n']}. {a['title']}" for a in book["assignments"]]
    heads, who = _who(book)
    header = [*heads, *(f"{t} ({book['points']} points)" for t in titles)]
    return _sheet(header, [[*who(s), *(g["score"] for g in s["grades"])] for s in book["students"]])


def gradebook_details_csv(book: dict[str, Any]) -> bytes:
    """The detailed file: per student and assignment its score, then the parts it comes from."""
    titles = [f"{a['n']}. {a['title']}" for a in book["assignments"]]
    heads, who = _who(book)
    header = list(heads)
    for t in titles:
        header += [f"{t} ({book['points']} points)", *(f"{t}: {words}" for _part, words in PARTS)]
    rows = [[*who(s), *(value for g in s["grades"] for value in (g["score"], *(g[p] for p, _w in PARTS)))]
            for s in book["students"]]
    return _sheet(header, rows)
