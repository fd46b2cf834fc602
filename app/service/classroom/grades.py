"""The gradebook: per student and assignment, a score a teacher can read, and its CSV for an LMS.

For each assigned step a student has

* **right**: one of their answers to it was judged correct or equivalent;
* **first try**: their first answer to it was right;
* **shown**: they pressed "Show this step" on /join, which shows the step's answer (a hint used).

The score of an assignment is the share of its steps the student got right on their own, that is right and not
shown before their first right answer, in points out of 100 (one decimal).  The parts are given beside it, as
counts out of the assignment's steps, so a teacher can weigh them otherwise.

Read in **one SELECT** (the answers grouped per student and step, beside the steps shown, in a UNION ALL), so the
grades come from one state of the database, as the summary's figures do.
"""

from __future__ import annotations

import csv
import io
from collections import defaultdict
from typing import Any

from sqlalchemy import case, func, literal, null, select, union_all

from app.service.classroom.database import Database
from app.service.classroom.models import AttemptRow, HintRow, StudentRow
from app.service.classroom.reports import FORMULA_START, assigned_keys
from app.service.classroom.store import DONE

POINTS = 100  # an assignment's score is out of this many points
PARTS = (("first_try", "right first try"), ("right", "right"), ("shown", "shown"), ("steps", "steps"))


def _rows(db: Database, class_id: int) -> list[Any]:
    """Per student (every one) and step: the first answer's id, the first right answer's id and time; per student
    and step shown: when.  One statement, one snapshot."""
    right = AttemptRow.verdict.in_(DONE)
    answers = (
        select(StudentRow.id, StudentRow.name, StudentRow.joined_at, AttemptRow.assignment_id, AttemptRow.item,
               AttemptRow.step, func.coalesce(AttemptRow.coordinate, ""), literal("answer"),
               func.min(AttemptRow.id), func.min(case((right, AttemptRow.id))), func.min(case((right, AttemptRow.at))))
        .select_from(StudentRow)
        .outerjoin(AttemptRow, AttemptRow.student_id == StudentRow.id)
        .where(StudentRow.class_id == class_id)
        .group_by(StudentRow.id, StudentRow.name, StudentRow.joined_at, AttemptRow.assignment_id, AttemptRow.item,
                  AttemptRow.step, AttemptRow.coordinate)
    )
    shown = (
        select(StudentRow.id, StudentRow.name, StudentRow.joined_at, HintRow.assignment_id, HintRow.item,
               HintRow.step, HintRow.coordinate, literal("shown"), null(), null(), HintRow.at)
        .join(StudentRow, StudentRow.id == HintRow.student_id)
        .where(HintRow.class_id == class_id)
    )
    with db.session() as session:
        return list(session.execute(union_all(answers, shown)).all())


def gradebook(db: Database, class_id: int, series: list[dict[str, Any]]) -> dict[str, Any]:
    """``{"assignments": [{"n", "title", "due", "steps"}], "students": [{"name", "grades": [{"assignment",
    "steps", "first_try", "right", "shown", "score"}]}]}``, students in the order they joined."""
    people: dict[int, tuple[str, Any]] = {}
    first: dict[tuple, tuple[int | None, int | None, Any]] = {}  # (student, key): first id, first right id, its time
    shown_at: dict[tuple, Any] = {}
    for student, name, joined, assignment_id, item, step, coordinate, kind, first_id, right_id, at in _rows(db, class_id):
        people[student] = (name, joined)
        if item is None:  # a student with no answer yet
            continue
        key = (student, (assignment_id, item, step, coordinate or None))
        if kind == "shown":
            shown_at[key] = at
        else:
            first[key] = (first_id, right_id, at)
    heads = [{"n": a["n"], "title": a["title"], "due": a["due"], "steps": len(assigned_keys([a]))} for a in series]
    rows = []
    for student, (name, _joined) in sorted(people.items(), key=lambda p: (p[1][1], p[0])):
        grades = []
        for each, head in zip(series, heads, strict=True):
            count: defaultdict[str, int] = defaultdict(int)
            for step in assigned_keys([each]):
                first_id, right_id, right_at = first.get((student, step), (None, None, None))
                seen = shown_at.get((student, step))
                count["right"] += right_id is not None
                count["shown"] += seen is not None
                # on their own: right, and the step not shown before the first right answer
                own = right_id is not None and (seen is None or seen > right_at)
                count["own"] += own
                count["first_try"] += own and first_id == right_id
            score = round(POINTS * count["own"] / head["steps"], 1) if head["steps"] else 0.0
            grades.append({"assignment": head["n"], "steps": head["steps"], "first_try": count["first_try"],
                           "right": count["right"], "shown": count["shown"], "score": score})
        rows.append({"name": name, "grades": grades})
    return {"points": POINTS, "assignments": heads, "students": rows}


def _cell(value: Any) -> str:
    """A cell a spreadsheet will not run (as the attempts' export): a formula's start gets an apostrophe."""
    text = "" if value is None else str(value)
    return "'" + text if text.startswith(FORMULA_START) else text


def gradebook_csv(book: dict[str, Any]) -> bytes:
    """One row per student, one column per assignment (its score out of ``POINTS``), then its parts as extra
    columns: the shape Canvas's and Moodle's grade imports read (the pseudonym is the student's column; the
    assignment columns are the grade items)."""
    titles = [f"{a['n']}. {a['title']}" for a in book["assignments"]]
    header = ["Student", *(f"{t} ({book['points']} points)" for t in titles)]
    header += [f"{t}: {words}" for t in titles for _part, words in PARTS]
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\r\n")
    writer.writerow([_cell(h) for h in header])
    for student in book["students"]:
        scores = [g["score"] for g in student["grades"]]
        parts = [g[part] for g in student["grades"] for part, _words in PARTS]
        writer.writerow([_cell(student["name"]), *scores, *parts])
    return out.getvalue().encode("utf-8")
