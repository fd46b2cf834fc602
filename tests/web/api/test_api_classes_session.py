"""A session ended without deleting the class (review instr-j 3; issue 44, item 7), on SQLite and on PostgreSQL:
the instructor closes joining (a new student is refused with a message for them, a student who joined keeps
answering and opens their record on another device) and stops answers (every answer and shown step refused with a
message, the record kept), then reopens both.  The state is in the class's record: a second server on the same
database refuses alike."""

from __future__ import annotations

import pytest

from app.main import app
from app.service.classroom import store
from app.service.classroom.service import Classroom
from app.settings import Settings
from app.web.api.classes import classroom as classroom_dep
from tests.web.api.test_api_classes import RIGHT_T, SCENE, WRONG_T, bearer, check

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


@pytest.fixture
def classes(classes_on_both):
    """Every test here on SQLite and on PostgreSQL (tests/web/conftest.py)."""
    return classes_on_both


def _class(client) -> tuple[str, str]:
    r = client.post("/api/classes", json={"title": "Mechanics II, Tuesday practice"})
    assert r.status_code == 201, r.text
    code, teacher = r.json()["code"], r.json()["teacher_key"]
    items = {"items": [{"scene": SCENE, "steps": [{"step": "kinetic"}, {"step": "potential"}]}]}
    assert client.put(f"/api/classes/{code}/assignment", json=items, headers=bearer(teacher)).status_code == 200
    return code, teacher


def test_closing_joining_refuses_new_students_and_keeps_those_joined(client, classes):
    code, teacher = _class(client)
    ada = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()
    closed = client.put(f"/api/classes/{code}/session", json={"joining_open": False}, headers=bearer(teacher))
    assert closed.status_code == 200, closed.text
    state = closed.json()
    assert (state["joining_open"], state["answers_open"], state["answers_stopped_at"]) == (False, True, None)
    assert state["joining_closed_at"].endswith("Z")
    assert client.get(f"/api/classes/{code}/me", headers=bearer(teacher)).json()["session"]["joining_open"] is False

    refused = client.post(f"/api/classes/{code}/join", json={"name": "Quentin"})
    assert refused.status_code == 409
    assert refused.json()["detail"] == store.JOINING_CLOSED
    # Ada, who joined before, keeps answering, and opens her record on another device
    assert check(client, code, ada["student_key"], RIGHT_T).json()["verdict"] == "correct"
    again = client.post(f"/api/classes/{code}/rejoin", json={"name": "Ada", "recovery_code": ada["recovery_code"]})
    assert again.status_code == 200, again.text

    reopened = client.put(f"/api/classes/{code}/session", json={"joining_open": True}, headers=bearer(teacher))
    assert (reopened.json()["joining_open"], reopened.json()["joining_closed_at"]) == (True, None)
    assert client.post(f"/api/classes/{code}/join", json={"name": "Quentin"}).status_code == 200


def test_stopping_answers_refuses_them_keeps_the_record_and_reopens(client, classes):
    code, teacher = _class(client)
    ada = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()["student_key"]
    assert check(client, code, ada, WRONG_T, attempt="retry-0001").json()["verdict"] == "incorrect"
    stopped = client.put(f"/api/classes/{code}/session", json={"answers_open": False}, headers=bearer(teacher))
    assert (stopped.json()["answers_open"], stopped.json()["joining_open"]) == (False, True)

    refused = check(client, code, ada, RIGHT_T)
    assert refused.status_code == 409 and refused.json()["detail"] == store.ANSWERS_STOPPED
    shown = client.post(f"/api/classes/{code}/shown", json={"scene": SCENE, "step": "potential", "assignment": 1},
                        headers=bearer(ada))
    assert shown.status_code == 409 and shown.json()["detail"] == store.ANSWERS_STOPPED
    # an answer recorded before the stop, sent again by a page that lost its reply, gets its verdict back
    assert check(client, code, ada, WRONG_T, attempt="retry-0001").json()["verdict"] == "incorrect"
    # the record is kept: one answer, nothing shown; the student still reads the class and sees it stopped
    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    assert summary["attempts"] == 1 and summary["steps"][1]["students_shown"] == 0
    assert client.get(f"/api/classes/{code}/me", headers=bearer(ada)).json()["session"]["answers_open"] is False

    client.put(f"/api/classes/{code}/session", json={"answers_open": True}, headers=bearer(teacher))
    assert check(client, code, ada, RIGHT_T).json()["verdict"] == "correct"


def test_only_the_instructor_ends_a_session_and_bad_input_is_refused(client, classes):
    code, teacher = _class(client)
    ada = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()["student_key"]
    assert client.put(f"/api/classes/{code}/session", json={"answers_open": False}, headers=bearer(ada)).status_code == 403
    assert client.put(f"/api/classes/{code}/session", json={"answers_open": False}).status_code == 401
    wrong = client.put(f"/api/classes/{code}/session", json={"answers_open": "no"}, headers=bearer(teacher))
    assert wrong.status_code == 422
    extra = client.put(f"/api/classes/{code}/session", json={"close": True}, headers=bearer(teacher))
    assert extra.status_code == 422
    assert check(client, code, ada, RIGHT_T).status_code == 200  # nothing was changed


def test_every_server_on_the_database_refuses_alike(client, classes, services, tmp_path):
    """A second server on the same database (another replica): the first stops answers, the second refuses."""
    code, teacher = _class(client)
    ada = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()["student_key"]
    second = Classroom(services.checking, Settings(data_dir=tmp_path, database_url=classes.db.url))
    try:
        client.put(f"/api/classes/{code}/session", json={"answers_open": False}, headers=bearer(teacher))
        app.dependency_overrides[classroom_dep] = lambda: second
        refused = check(client, code, ada, RIGHT_T)
        assert refused.status_code == 409 and refused.json()["detail"] == store.ANSWERS_STOPPED
    finally:
        app.dependency_overrides[classroom_dep] = lambda: classes
        second.stop()
