"""The dashboard says what the grade says (review inst-c 2, 3, 13): a step shown ("Show this step") before the
student typed it right is "shown", not "done"; the steps' figures count students, not answers (an answer sent twice
is one student); a U written with another zero is counted apart, as equivalent."""

from __future__ import annotations

from app.service.classroom import store
from app.service.classroom.database import Database
from app.service.classroom.grades import gradebook
from app.service.classroom.reports import students, summary
from app.settings import Settings

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
