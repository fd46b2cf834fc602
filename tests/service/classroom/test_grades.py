"""The gradebook's blanks and zeros (issue 45, review inst-a 16): nothing tried of an assignment not yet due, or
with no due time, is no score (a blank cell), not 0; once it is due, nothing tried is 0; tried and never right is
0 at any time.  The file to import holds one column per assignment and nothing else."""

from __future__ import annotations

import csv
import io
from datetime import timedelta

from app.service.classroom import store
from app.service.classroom.database import Database, now
from app.service.classroom.grades import gradebook, gradebook_csv
from app.settings import Settings

T = [{"item": "simple-pendulum", "system": None, "parameters": {}, "steps": [{"step": "kinetic", "coordinate": None}]}]


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
        rows = list(csv.reader(io.StringIO(gradebook_csv(book).decode())))
        assert rows == [["Student", "1. Past (100 points)", "2. Coming (100 points)", "3. Undated (100 points)"],
                        ["Ada", "0.0", "0.0", ""], ["Bo", "0.0", "", ""]]
    finally:
        db.stop()
