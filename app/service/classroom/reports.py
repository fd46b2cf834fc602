"""What an instructor reads of a class: the summary per step, each student's progress, the CSV export.

Counted in the database (GROUP BY), so a dashboard polling every few seconds
reads a few rows per step, not every attempt.  A step is done for a student
once one of their answers to it was ``correct`` or ``equivalent``; the
``correct`` count of a step counts such answers, ``incorrect`` the others.
"""

from __future__ import annotations

import csv
import io
from collections import defaultdict
from typing import Any

from sqlalchemy import case, func, select

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


def summary(db: Database, class_id: int, items: list[dict[str, Any]]) -> dict[str, Any]:
    """``{"students", "attempts", "steps": [...]}``: the assigned steps first (in order), then any other tried."""
    done = AttemptRow.verdict.in_(DONE)
    with db.session() as session:
        students = session.scalar(select(func.count()).select_from(StudentRow).where(StudentRow.class_id == class_id))
        counted = session.execute(
            select(AttemptRow.item, AttemptRow.step, AttemptRow.coordinate, AttemptRow.verdict, AttemptRow.mistake,
                   func.count(), func.max(AttemptRow.mistake_name))
            .where(AttemptRow.class_id == class_id)
            .group_by(AttemptRow.item, AttemptRow.step, AttemptRow.coordinate, AttemptRow.verdict, AttemptRow.mistake)
        ).all()
        finished = session.execute(
            select(AttemptRow.item, AttemptRow.step, AttemptRow.coordinate, func.count(AttemptRow.student_id.distinct()))
            .where(AttemptRow.class_id == class_id, done)
            .group_by(AttemptRow.item, AttemptRow.step, AttemptRow.coordinate)
        ).all()
    steps: dict[Key, dict[str, Any]] = {key: _step_entry(key, items) for key in _assigned_keys(items)}
    attempts = 0
    for item, step, coordinate, verdict, mistake, n, text in counted:
        entry = steps.setdefault((item, step, coordinate), _step_entry((item, step, coordinate), items))
        entry["correct" if verdict in DONE else "incorrect"] += n
        attempts += n
        if mistake:
            entry["mistakes"][mistake] = entry["mistakes"].get(mistake, 0) + n
            if text:  # the mistake in words (one system's mistakes are worded alike)
                entry["mistake_names"][mistake] = text
    for item, step, coordinate, n in finished:
        steps[(item, step, coordinate)]["students_done"] = n
    for entry in steps.values():  # the most common mistake first
        entry["mistakes"] = dict(sorted(entry["mistakes"].items(), key=lambda kv: (-kv[1], kv[0])))
    return {"students": students or 0, "attempts": attempts, "steps": list(steps.values())}


def students(db: Database, class_id: int, items: list[dict[str, Any]]) -> dict[str, Any]:
    """Each student's progress: attempts, steps done of the assignment's, and per step tried its tally."""
    done = case((AttemptRow.verdict.in_(DONE), 1), else_=0)
    with db.session() as session:
        people = session.execute(
            select(StudentRow.id, StudentRow.name, StudentRow.joined_at)
            .where(StudentRow.class_id == class_id)
            .order_by(StudentRow.joined_at, StudentRow.id)
        ).all()
        tallies = session.execute(
            select(AttemptRow.student_id, AttemptRow.item, AttemptRow.step, AttemptRow.coordinate, func.count(),
                   func.sum(done), func.max(AttemptRow.at))
            .where(AttemptRow.class_id == class_id)
            .group_by(AttemptRow.student_id, AttemptRow.item, AttemptRow.step, AttemptRow.coordinate)
        ).all()
    per: dict[int, list[dict[str, Any]]] = defaultdict(list)
    for student_id, item, step, coordinate, n, n_done, last in tallies:
        per[student_id].append({"item": item, "step": step, "coordinate": coordinate, "attempts": n,
                                "done": bool(n_done), "last": last.isoformat() + "Z"})
    assigned = set(_assigned_keys(items))
    rows = []
    for student_id, name, joined in people:
        steps = per.get(student_id, [])
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
