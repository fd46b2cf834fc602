"""The dashboard says what the grade says (review inst-c 2, 3, 13): a step shown ("Show this step") before the
student typed it right is "shown", not "done"; the steps' figures count students, not answers (an answer sent twice
is one student); a U written with another zero is counted apart, as equivalent."""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

import pytest

from app.service.classroom import store
from app.service.classroom.database import Database
from app.service.classroom.grades import gradebook
from app.service.classroom.reports import students, summary
from app.settings import Settings

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

TU = [{"item": "simple-pendulum", "system": None, "parameters": {},
       "steps": [{"step": "kinetic", "coordinate": None}, {"step": "potential", "coordinate": None}]}]


def _class(tmp_path):
    db = Database(Settings(data_dir=tmp_path))
    code, key, _recovery = store.create_class(db, "Mechanics")
    class_id = store.access(db, code, key).class_id
    store.add_assignment(db, class_id, "Week 3", None, TU)
    return db, code, class_id


def test_a_step_shown_before_it_was_typed_is_shown_not_done(tmp_path):
    db, code, class_id = _class(tmp_path)
    try:
        ada, gus = (store.join(db, code, name)[1] for name in ("Ada", "Gus"))
        first = store.series(db, class_id)[0]["id"]
        for who in (ada, gus):
            store.record(db, who, "simple-pendulum", "potential", None, "correct", None, "m*g*R*(1-cos(theta))",
                         assignment_id=first)
        # Gus presses "Show this step" on T, then types it; Ada types it on her own
        store.record_hint(db, gus, first, "simple-pendulum", "kinetic", None)
        for who in (ada, gus):
            store.record(db, who, "simple-pendulum", "kinetic", None, "correct", None, "m*R**2*theta_dot**2/2",
                         assignment_id=first)
        series = store.series(db, class_id)
        found = summary(db, class_id, series)
        [kinetic] = [s for s in found["steps"] if s["step"] == "kinetic"]
        assert (kinetic["students_done"], kinetic["students_shown"], kinetic["stuck"]) == (1, 1, 0)
        assert found["assignments"][0]["students_done"] == ["Ada"]
        assert found["assignments"][0]["students_shown"] == ["Gus"]
        rows = {s["name"]: s for s in students(db, class_id, series)["students"]}
        assert (rows["Gus"]["own"], rows["Gus"]["shown"], rows["Ada"]["own"], rows["Ada"]["shown"]) == (1, 1, 2, 0)
        assert [s["shown"] for s in rows["Gus"]["steps"] if s["step"] == "kinetic"] == [True]
        # the grade agrees: Gus has one of two steps on his own
        scores = {s["name"]: s["grades"][0]["score"] for s in gradebook(db, class_id, series)["students"]}
        assert scores == {"Ada": 100.0, "Gus": 50.0}
    finally:
        db.stop()


def test_the_figures_count_students_and_another_zero_of_u_apart(tmp_path):
    db, code, class_id = _class(tmp_path)
    try:
        ada, bo, cy = (store.join(db, code, name)[1] for name in ("Ada", "Bo", "Cy"))
        first = store.series(db, class_id)[0]["id"]
        # Ada writes U with its zero at the pivot, twice; Bo as the set-up says; Cy wrong twice
        for _ in range(2):
            store.record(db, ada, "simple-pendulum", "potential", None, "equivalent", None, "-m*g*R*cos(theta)",
                         assignment_id=first)
            store.record(db, cy, "simple-pendulum", "potential", None, "incorrect", "potential.sign", "m*g*R*cos(theta)",
                         "The sign of U", assignment_id=first)
        store.record(db, bo, "simple-pendulum", "potential", None, "correct", None, "m*g*R*(1-cos(theta))",
                     assignment_id=first)
        [potential] = [s for s in summary(db, class_id, store.series(db, class_id))["steps"]
                       if s["step"] == "potential"]
        assert (potential["correct"], potential["incorrect"]) == (3, 2)  # answers
        assert (potential["students_right"], potential["students_wrong"], potential["students_equivalent"]) == (2, 1, 1)
    finally:
        db.stop()


def test_a_right_answer_after_the_due_time_is_late_not_done(tmp_path):
    db = Database(Settings(data_dir=tmp_path))
    try:
        code, key, _recovery = store.create_class(db, "Mechanics")
        class_id = store.access(db, code, key).class_id
        # due an hour ago: every answer recorded now comes after it
        store.add_assignment(db, class_id, "Week 3", datetime.now(UTC).replace(tzinfo=None) - timedelta(hours=1), TU)
        first = store.series(db, class_id)[0]["id"]
        chloe, dev = (store.join(db, code, name)[1] for name in ("Chloe", "Dev"))
        store.record(db, chloe, "simple-pendulum", "kinetic", None, "correct", None, "m*R**2*theta_dot**2/2",
                     assignment_id=first)
        store.record(db, dev, "simple-pendulum", "kinetic", None, "incorrect", None, "m*R*theta_dot**2/2",
                     assignment_id=first)
        series = store.series(db, class_id)
        found = summary(db, class_id, series)
        [kinetic] = [s for s in found["steps"] if s["step"] == "kinetic"]
        # Chloe is right, late: neither done nor stuck (Dev is stuck); the bar still counts her right answer
        assert (kinetic["students_done"], kinetic["students_late"], kinetic["stuck"]) == (0, 1, 1)
        assert (kinetic["students_right"], kinetic["students_wrong"]) == (1, 1)
        assert found["assignments"][0]["students_done"] == []
        assert found["assignments"][0]["students_stuck"] == ["Dev"]
        rows = {s["name"]: s for s in students(db, class_id, series)["students"]}
        assert (rows["Chloe"]["own"], rows["Chloe"]["late"]) == (0, 1)
        assert [s["late"] for s in rows["Chloe"]["steps"]] == [True]
        # the grade agrees: no step on her own by the due time
        scores = {s["name"]: s["grades"][0]["score"] for s in gradebook(db, class_id, series)["students"]}
        assert scores == {"Chloe": 0.0, "Dev": 0.0}
    finally:
        db.stop()


def test_mistakes_count_students_and_a_step_shown_unanswered_is_said_apart(tmp_path):
    db, code, class_id = _class(tmp_path)
    try:
        ada, bo, cy, di = (store.join(db, code, name)[1] for name in ("Ada", "Bo", "Cy", "Di"))
        first = store.series(db, class_id)[0]["id"]
        # the ½ left out: Ada three times (3 answers, 1 student); the sign of U: Bo and Cy once each (2 students)
        for _ in range(3):
            store.record(db, ada, "simple-pendulum", "kinetic", None, "incorrect", "kinetic.half", "m*R**2*theta_dot**2",
                         "the ½ of ½ m v² left out", assignment_id=first)
        for who in (bo, cy):
            store.record(db, who, "simple-pendulum", "potential", None, "incorrect", "potential.sign",
                         "m*g*R*cos(theta)", "The sign of U", assignment_id=first)
        store.record_hint(db, di, first, "simple-pendulum", "kinetic", None)  # Di is shown T and never answers it
        found = summary(db, class_id, store.series(db, class_id))
        # the mistake most students made first, though the other has more answers
        assert [(m["key"], len(m["students"]), m["count"]) for m in found["mistakes"]] == [
            ("potential.sign", 2, 2), ("kinetic.half", 1, 3)]
        assert found["mistakes"][1]["steps"][0]["students"] == 1
        [kinetic] = [s for s in found["steps"] if s["step"] == "kinetic"]
        assert (kinetic["students_shown"], kinetic["students_shown_unanswered"]) == (1, 1)
        assert kinetic["students_right"] + kinetic["students_wrong"] == 1  # the bar: Ada alone answered
    finally:
        db.stop()


def test_a_mistake_says_who_has_since_put_it_right(tmp_path):
    db, code, class_id = _class(tmp_path)
    try:
        bo, cy = (store.join(db, code, name)[1] for name in ("Bo", "Cy"))
        first = store.series(db, class_id)[0]["id"]
        for who in (bo, cy):
            store.record(db, who, "simple-pendulum", "potential", None, "incorrect", "potential.sign",
                         "m*g*R*cos(theta)", "The sign of U", assignment_id=first)
        # Cy then answers U right: still among those who made it, and said to have put it right since
        store.record(db, cy, "simple-pendulum", "potential", None, "correct", None, "-m*g*R*cos(theta)",
                     assignment_id=first)
        [mistake] = summary(db, class_id, store.series(db, class_id))["mistakes"]
        assert (mistake["students"], mistake["students_since_right"]) == (["Bo", "Cy"], ["Cy"])
    finally:
        db.stop()
