"""A student's own page tells the truth (issue 44): a step counts as done only as the grade counts it (right on one's
own by the due time), the page as they left it comes back from the record (last answer, its verdict, steps shown),
and two pseudonyms equal but for case or Unicode form are one name."""

from __future__ import annotations

import json
from datetime import timedelta

import pytest

from app.errors import Refused, WrongKey
from app.service.classroom import store
from app.service.classroom.database import Database, now
from app.service.classroom.grades import gradebook
from app.service.classroom.reports import own_record, students
from app.settings import Settings

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

STEPS = [{"step": "kinetic", "coordinate": None}, {"step": "potential", "coordinate": None}]
ITEMS = [{"item": "simple-pendulum", "system": None, "parameters": {}, "steps": STEPS}]
RIGHT_T = "m*l**2*theta_dot**2/2"


@pytest.fixture
def db(tmp_path):
    found = Database(Settings(data_dir=tmp_path))
    yield found
    found.stop()


def _class(db, due):
    code, key, _recovery = store.create_class(db, "Mechanics")
    class_id = store.access(db, code, key).class_id
    store.add_assignment(db, class_id, "Week 3", due, ITEMS)
    return code, class_id


def test_a_step_counts_as_done_only_as_the_grade_counts_it(db):
    code, class_id = _class(db, None)
    ada, mei = (store.join(db, code, name)[1] for name in ("Ada", "Mei"))
    [week] = store.series(db, class_id)
    store.record(db, ada, "simple-pendulum", "kinetic", None, "correct", None, RIGHT_T, assignment_id=week["id"])
    # Mei is shown T, then types it right: right, not counted
    store.record_hint(db, mei, week["id"], "simple-pendulum", "kinetic", None)
    store.record(db, mei, "simple-pendulum", "kinetic", None, "correct", None, RIGHT_T, assignment_id=week["id"])
    rows = {s["name"]: s for s in students(db, class_id, store.series(db, class_id))["students"]}
    assert [(rows[n]["done"], rows[n]["counted"], rows[n]["shown"]) for n in ("Ada", "Mei")] == [(1, 1, 0), (1, 0, 1)]
    [mine] = rows["Mei"]["steps"]
    assert (mine["done"], mine["shown"], mine["counted"], mine["late"]) == (True, True, False, False)
    # the same rule as the score
    book = {s["name"]: s["grades"][0]["score"] for s in gradebook(db, class_id, store.series(db, class_id))["students"]}
    assert book == {"Ada": 50.0, "Mei": 0.0}


def test_a_right_answer_after_the_due_time_is_late_and_not_counted(db):
    code, class_id = _class(db, now() - timedelta(minutes=1))
    chloe = store.join(db, code, "Chloe")[1]
    [week] = store.series(db, class_id)
    store.record(db, chloe, "simple-pendulum", "kinetic", None, "correct", None, RIGHT_T, assignment_id=week["id"])
    [row] = students(db, class_id, store.series(db, class_id))["students"]
    # right (done), but neither done on their own by the due time (own, counted: the grade's rule) nor stuck: late
    assert (row["done"], row["own"], row["counted"], row["late"]) == (1, 0, 0, 1)
    [step] = row["steps"]
    assert (step["counted"], step["late"], step["shown"]) == (False, True, False)


def test_the_page_as_the_student_left_it(db):
    code, class_id = _class(db, None)
    ben = store.join(db, code, "Ben")[1]
    [week] = store.series(db, class_id)
    verdict = json.dumps({"verdict": "incorrect", "mistake": {"key": "potential.sign", "name": "the sign of U"}})
    store.record(db, ben, "simple-pendulum", "potential", None, "correct", None, "-m*g*l*cos(theta)",
                 assignment_id=week["id"], attempt_id="a" * 22, response=b'{"verdict": "correct"}')
    store.record(db, ben, "simple-pendulum", "potential", None, "incorrect", "potential.sign", "m*g*l*cos(theta)",
                 assignment_id=week["id"], attempt_id="b" * 22, response=verdict.encode())
    store.record(db, ben, "simple-pendulum", "kinetic", None, store.NOT_READ, None, "m*(",
                 assignment_id=week["id"], attempt_id="c" * 22, response=b'{"detail": "answer: never closed"}')
    store.record_hint(db, ben, week["id"], "simple-pendulum", "kinetic", None)
    found = {r["step"]: r for r in own_record(db, class_id, ben.student, store.series(db, class_id))}
    # the last answer of each step, what it was answered, and the step shown
    assert found["potential"]["answer"] == "m*g*l*cos(theta)"
    assert found["potential"]["answered"] == {"status": 200, "body": json.loads(verdict)}
    assert not found["potential"]["shown"]
    assert found["kinetic"]["answered"] == {"status": 422, "body": {"detail": "answer: never closed"}}
    assert (found["kinetic"]["shown"], found["kinetic"]["assignment"]) == (True, 1)
    # another student's record is not theirs
    other = store.join(db, code, "Bo")[1]
    assert own_record(db, class_id, other.student, store.series(db, class_id)) == []


@pytest.mark.parametrize("again", ["grace", "GRACE", " Grace ", "ＧＲＡＣＥ", "graCe"])
def test_pseudonyms_equal_but_for_case_or_form_are_one_name(db, again):
    code, _class_id = _class(db, None)
    store.join(db, code, "Grace")
    with pytest.raises(Refused) as refused:
        store.join(db, code, again)
    with pytest.raises(Refused) as same:
        store.join(db, code, "Grace")
    # the message an exact duplicate gets, with the name as typed
    assert str(refused.value) == str(same.value).replace("“Grace”", f"“{again}”")
    assert refused.value.loc == ("name",)


def test_a_rejoin_with_the_pseudonym_in_another_case_opens_the_record(db):
    code, _class_id = _class(db, None)
    _key, grace, recovery = store.join(db, code, "Grace")
    _new, back = store.rejoin(db, code, "grace", recovery)
    assert (back.student, back.name) == (grace.student, "Grace")
    with pytest.raises(WrongKey):
        store.rejoin(db, code, "gracie", recovery)


def test_a_pseudonym_of_other_letters_is_another_name(db):
    code, _class_id = _class(db, None)
    store.join(db, code, "Zoë")
    assert store.join(db, code, "Zoe")[1].name == "Zoe"  # ë is not e: NFKC keeps the accent
    with pytest.raises(Refused):
        store.join(db, code, "zoË")  # the same letters in another case; Ë as E + combining diaeresis too
    with pytest.raises(Refused):
        store.join(db, code, "Zoe\u0308")
