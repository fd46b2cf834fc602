"""Answers the checker could not read ("Not checked"): recorded with their refusal, counted among a student's
answers on the dashboard and in the answers' CSV, never counted wrong, and not in the gradebook (issue 45)."""

from __future__ import annotations

import csv
import io
import json

import pytest

from app.service.classroom import store
from app.service.classroom.database import Database
from app.service.classroom.grades import gradebook
from app.service.classroom.reports import export_csv, students, summary
from app.settings import Settings

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

T = [{"item": "simple-pendulum", "system": None, "parameters": {}, "steps": [{"step": "kinetic", "coordinate": None}]}]
SCENE = "simple-pendulum"


def _unread(db, who, answer: str, words: str, assignment_id: int) -> None:
    refusal = json.dumps({"detail": f"answer: {words}", "loc": ["answer"], "part": answer, "start": 0,
                          "end": len(answer), "readings": []}).encode()
    store.record(db, who, SCENE, "kinetic", None, store.NOT_READ, None, answer, None, None, refusal, assignment_id)


def test_answers_not_read_count_as_answers_never_as_wrong(tmp_path):
    db = Database(Settings(data_dir=tmp_path))
    try:
        code, key, _recovery = store.create_class(db, "Mechanics")
        class_id = store.access(db, code, key).class_id
        store.add_assignment(db, class_id, "Week 1", None, T)
        series = store.series(db, class_id)
        week = series[0]["id"]
        ada, bo = (store.join(db, code, name)[1] for name in ("Ada", "Bo"))
        # Ada: two answers not read, then right on her first judged answer
        _unread(db, ada, "1/2m R^2", "a factor after a quotient is ambiguous", week)
        _unread(db, ada, "=m g", "one side of '=' is empty", week)
        store.record(db, ada, SCENE, "kinetic", None, "correct", None, "m*R**2*theta_dot**2/2", assignment_id=week)
        # Bo: one answer not read, nothing judged
        _unread(db, bo, "m g R cos(", "the '(' is never closed", week)

        seen = summary(db, class_id, series)
        assert seen["attempts"] == 4
        (step,) = seen["steps"]
        assert (step["correct"], step["incorrect"], step["not_read"]) == (1, 0, 3)
        assert step["mistakes"] == {} and seen["mistakes"] == []
        # Bo tried the step and has no right answer: stuck on it, as the dashboard should say
        assert step["students_stuck"] == ["Bo"] and seen["assignments"][0]["students_stuck"] == ["Bo"]

        rows = {s["name"]: s for s in students(db, class_id, series)["students"]}
        assert (rows["Ada"]["attempts"], rows["Ada"]["not_read"], rows["Ada"]["done"]) == (3, 2, 1)
        assert (rows["Bo"]["attempts"], rows["Bo"]["not_read"], rows["Bo"]["done"]) == (1, 1, 0)

        table = list(csv.DictReader(io.StringIO(export_csv(db, class_id, series).decode())))
        assert [(r["student"], r["verdict"], r["mistake"], r["answer"]) for r in table] == [
            ("Ada", "could not be read", "a factor after a quotient is ambiguous", "1/2m R^2"),
            # an answer not read is no checked expression: a formula's start gets its apostrophe
            ("Ada", "could not be read", "one side of '=' is empty", "'=m g"),
            ("Ada", "right", "", "m*R**2*theta_dot**2/2"),
            ("Bo", "could not be read", "the '(' is never closed", "m g R cos("),
        ]

        # the gradebook: Ada right on her first judged try; Bo has tried nothing that was judged (a blank)
        grades = {s["name"]: s["grades"][0] for s in gradebook(db, class_id, series)["students"]}
        assert (grades["Ada"]["first_try"], grades["Ada"]["right"], grades["Ada"]["score"]) == (1, 1, 100.0)
        assert (grades["Bo"]["first_try"], grades["Bo"]["right"], grades["Bo"]["score"]) == (0, 0, None)
    finally:
        db.stop()
