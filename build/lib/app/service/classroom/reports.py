"""What an instructor reads of a class: the summary per step, each student's progress, the CSV export.

Counted in the database (GROUP BY) in one statement, so a dashboard polling
every few seconds reads a few rows per student and step, not every attempt,
and every figure of one answer comes from the same state of the database.  A step is done for a student
once one of their answers to it was ``correct`` or ``equivalent``; the
``correct`` count of a step counts such answers, ``incorrect`` the others.
"""

from __future__ import annotations

import csv
import io
from collections import defaultdict
from typing import Any

from sqlalchemy import func, select

from app.service.classroom.database import Database
from app.service.classroom.models import AttemptRow, StudentRow
from app.service.classroom.store import DONE

Key = tuple[str, str, str | None]  # (item, step, coordinate)
CSV_COLUMNS = ("time", "student", "item", "step", "coordinate", "verdict", "mistake", "answer")
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def _assigned_keys(items: list[dict[str, Any]]) -> list[Key]:
    return [
        (item.get("scene") or item["name"], s["step"], s.get("coordinate"))
        for item in items
        for s in item["steps"]
    ]


def _step_entry(key: Key, items: list[dict[str, Any]]) -> dict[str, Any]:
    item, step, coordinate = key
    kind = "scene" if any(i.get("scene") == item for i in items) or not items else "system"
    return {kind: item, "step": step, "coordinate": coordinate, "correct": 0, "incorrect": 0, "students_done": 0,
            "mistakes": {}, "mistake_names": {}}


def _tallies(db: Database, class_id: int) -> list[Any]:
    """The class in one statement, so in one snapshot of the database: per student (every student, those who
    have not answered yet with empty columns) and per item, step, coordinate, verdict and named mistake, how many
    answers, the mistake's words and the last answer's time.

    One SELECT reads one consistent state on SQLite and on PostgreSQL alike (two statements in READ COMMITTED,
    or in SQLite's autocommit reads, may each see a different state while answers arrive)."""
    with db.session() as session:
        return list(session.execute(
            select(StudentRow.id, StudentRow.name, StudentRow.joined_at, AttemptRow.item, AttemptRow.step,
                   AttemptRow.coordinate, AttemptRow.verdict, AttemptRow.mistake, func.count(AttemptRow.id),
                   func.max(AttemptRow.mistake_name), func.max(AttemptRow.at))
            .select_from(StudentRow)
            .outerjoin(AttemptRow, AttemptRow.student_id == StudentRow.id)
            .where(StudentRow.class_id == class_id)
            .group_by(StudentRow.id, StudentRow.name, StudentRow.joined_at, AttemptRow.item, AttemptRow.step,
                      AttemptRow.coordinate, AttemptRow.verdict, AttemptRow.mistake)
        ).all())


def _item_of(entry: dict[str, Any]) -> dict[str, Any]:
    return {k: entry[k] for k in ("scene", "system") if k in entry} | {"step": entry["step"],
                                                                      "coordinate": entry["coordinate"]}


def summary(db: Database, class_id: int, items: list[dict[str, Any]]) -> dict[str, Any]:
    """``{"students", "attempts", "steps": [...], "mistakes": [...]}`` from one snapshot.

    ``steps``: the assigned steps first (in order), then any other tried; each with its counts, the students
    stuck on it (tried, not done yet) and its named mistakes.  ``mistakes``: each named mistake totalled over
    every step and scene it was made in (mistakes are totalled by their words, so the same slip in two scenes
    is one line), most common first, with the steps and the students concerned."""
    rows = _tallies(db, class_id)
    steps: dict[Key, dict[str, Any]] = {key: _step_entry(key, items) for key in _assigned_keys(items)}
    names = {student_id: name for student_id, name, *_ in rows}
    tried: dict[Key, set[int]] = defaultdict(set)
    finished: dict[Key, set[int]] = defaultdict(set)
    by_mistake: dict[Key, dict[str, set[int]]] = defaultdict(lambda: defaultdict(set))
    attempts = 0
    for student_id, _name, _joined, item, step, coordinate, verdict, mistake, n, text, _last in rows:
        if item is None:  # a student who has not answered yet
            continue
        key = (item, step, coordinate)
        entry = steps.setdefault(key, _step_entry(key, items))
        entry["correct" if verdict in DONE else "incorrect"] += n
        attempts += n
        tried[key].add(student_id)
        if verdict in DONE:
            finished[key].add(student_id)
        if mistake:
            entry["mistakes"][mistake] = entry["mistakes"].get(mistake, 0) + n
            by_mistake[key][mistake].add(student_id)
            if text:  # the mistake in words (one system's mistakes are worded alike)
                entry["mistake_names"][mistake] = text
    totals: dict[str, dict[str, Any]] = {}
    for key, entry in steps.items():
        stuck = tried[key] - finished[key]
        entry["students_done"] = len(finished[key])
        entry["stuck"] = len(stuck)
        entry["students_stuck"] = sorted(names[s] for s in stuck)
        # the most common mistake first
        entry["mistakes"] = dict(sorted(entry["mistakes"].items(), key=lambda kv: (-kv[1], kv[0])))
        for mistake, count in entry["mistakes"].items():
            words = entry["mistake_names"].get(mistake, "")
            total = totals.setdefault(words or mistake, {"key": mistake, "name": words, "count": 0, "steps": [],
                                                         "students": set()})
            total["count"] += count
            total["steps"].append(_item_of(entry) | {"count": count})
            total["students"] |= by_mistake[key][mistake]
    mistakes = sorted(totals.values(), key=lambda t: (-t["count"], t["name"] or t["key"]))
    for total in mistakes:
        total["students"] = sorted(names[s] for s in total["students"])
        total["steps"].sort(key=lambda s: -s["count"])
    return {"students": len(names), "attempts": attempts, "steps": list(steps.values()), "mistakes": mistakes}


def students(db: Database, class_id: int, items: list[dict[str, Any]]) -> dict[str, Any]:
    """Each student's progress (from one snapshot): attempts, steps done of the assignment's, and per step
    tried its tally."""
    people: dict[int, tuple[str, Any]] = {}
    per: dict[int, dict[Key, dict[str, Any]]] = defaultdict(dict)
    for student_id, name, joined, item, step, coordinate, verdict, _mistake, n, _text, last in _tallies(db, class_id):
        people[student_id] = (name, joined)
        if item is None:
            continue
        tally = per[student_id].setdefault((item, step, coordinate), {
            "item": item, "step": step, "coordinate": coordinate, "attempts": 0, "done": False, "last": last})
        tally["attempts"] += n
        tally["done"] = tally["done"] or verdict in DONE
        tally["last"] = max(tally["last"], last)
    assigned = set(_assigned_keys(items))
    rows = []
    for student_id, (name, joined) in sorted(people.items(), key=lambda p: (p[1][1], p[0])):
        steps = [t | {"last": t["last"].isoformat() + "Z"} for t in per.get(student_id, {}).values()]
        finished = {(s["item"], s["step"], s["coordinate"]) for s in steps if s["done"]}
        rows.append({
            "name": name,
            "joined": joined.isoformat() + "Z",
            "attempts": sum(s["attempts"] for s in steps),
            "done": len(finished & assigned) if assigned else len(finished),
            "assigned": len(assigned),
            "steps": steps,
        })
    return {"students": rows}


def _cell(value: Any) -> str:
    """A cell a spreadsheet will not run: text starting like a formula gets a leading apostrophe."""
    text = "" if value is None else str(value)
    return "'" + text if text.startswith(FORMULA_START) else text


def export_csv(db: Database, class_id: int) -> bytes:
    """Every attempt of the class, oldest first, as CSV (UTF-8)."""
    with db.session() as session:
        rows = session.execute(
            select(AttemptRow.at, StudentRow.name, AttemptRow.item, AttemptRow.step, AttemptRow.coordinate,
                   AttemptRow.verdict, AttemptRow.mistake, AttemptRow.answer)
            .join(StudentRow, StudentRow.id == AttemptRow.student_id)
            .where(AttemptRow.class_id == class_id)
            .order_by(AttemptRow.id)
        ).all()
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\r\n")
    writer.writerow(CSV_COLUMNS)
    for at, *rest in rows:
        writer.writerow([at.isoformat() + "Z", *(_cell(v) for v in rest)])
    return out.getvalue().encode("utf-8")
