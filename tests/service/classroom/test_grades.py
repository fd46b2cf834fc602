"""The gradebook's blanks and zeros (issue 45, review inst-a 16): nothing tried of an assignment not yet due, or
with no due time, is no score (a blank cell), not 0; once it is due, nothing tried is 0; tried and never right is
0 at any time.  The file to import holds one column per assignment and nothing else."""

from __future__ import annotations

import csv
import io
from datetime import timedelta

import pytest

from app.service.classroom import store
from app.service.classroom.database import Database, now
from app.service.classroom.grades import gradebook, gradebook_csv
from app.settings import Settings

T = [{"item": "simple-pendulum", "system": None, "parameters": {}, "steps": [{"step": "kinetic", "coordinate": None}]}]


@pytest.mark.slow
def test_a_blank_before_the_due_time_a_zero_after_it(tmp_path):
    db = Database(Settings(data_dir=tmp_path))
    try:
        code, key, _recovery = store.create_class(db, "Mechanics")
        class_id = store.access(db, code, key).class_id
        store.add_assignment(db, class_id, "Past", now() - timedelta(days=1), T)
        store.add_assignment(db, class_id, "Coming", now() + timedelta(days=7), T)
        store.add_assignment(db, class_id, "Undated", None, T)
        ada, bo = (store.join(db, code, name)[1] for name in ("Ada", "Bo"))
        series = store.series(db, class_id)
        # Ada: the coming week's T tried, never right
        store.record(db, ada, "simple-pendulum", "kinetic", None, "incorrect", None, "m*g", assignment_id=series[1]["id"])
        book = gradebook(db, class_id, series)
        scores = {s["name"]: [g["score"] for g in s["grades"]] for s in book["students"]}
        assert scores == {"Ada": [0.0, 0.0, None], "Bo": [0.0, None, None]}
        rows = list(csv.reader(io.StringIO(gradebook_csv(book).decode("utf-8-sig"))))
        assert rows == [["Student", "1. Past (100 points)", "2. Coming (100 points)", "3. Undated (100 points)"],
                        ["Ada", "0.0", "0.0", ""], ["Bo", "0.0", "", ""]]
    finally:
        db.stop()


def test_a_right_answer_after_the_due_time_is_recorded_and_not_counted(tmp_path):
    db = Database(Settings(data_dir=tmp_path))
    try:
        code, key, _recovery = store.create_class(db, "Mechanics")
        class_id = store.access(db, code, key).class_id
        store.add_assignment(db, class_id, "Past", now() - timedelta(minutes=1), T)
        store.add_assignment(db, class_id, "Coming", now() + timedelta(days=7), T)
        ada = store.join(db, code, "Ada")[1]
        past, coming = (a["id"] for a in store.series(db, class_id))
        for assignment in (past, coming):
            store.record(db, ada, "simple-pendulum", "kinetic", None, "correct", None, "m*R**2*theta_dot**2/2",
                         assignment_id=assignment)
        [grades] = [s["grades"] for s in gradebook(db, class_id, store.series(db, class_id))["students"]]
        # right both times; counted only where it came by the due time
        assert [(g["right"], g["score"]) for g in grades] == [(1, 0.0), (1, 100.0)]
        raw = gradebook_csv(gradebook(db, class_id, store.series(db, class_id)))
        assert raw.startswith("\ufeff".encode())  # a spreadsheet opened by a double click reads it as UTF-8
    finally:
        db.stop()
