"""A class that asks for its students' institution login (inst-b 12), on SQLite and on PostgreSQL: the teacher
chooses the header the LMS matches grades by; the join asks for the login (required, checked); the students'
table shows it; the grades files have it first under that header; a student back on another device keeps it."""

from __future__ import annotations

import csv
import io

import pytest

from tests.web.api.test_api_classes import RIGHT_T, SCENE, WRONG_T, bearer, check

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


@pytest.fixture
def classes(classes_on_both):
    """Every test here on SQLite and on PostgreSQL (tests/web/conftest.py)."""
    return classes_on_both


def created(client, **more) -> tuple[str, str]:
    r = client.post("/api/classes", json={"title": "Mechanics", **more})
    assert r.status_code == 201, r.text
    return r.json()["code"], r.json()["teacher_key"]


def rows_of(response) -> list[list[str]]:
    assert response.status_code == 200, response.text
    return list(csv.reader(io.StringIO(response.content.decode("utf-8-sig"))))


def test_a_class_that_asks_for_the_canvas_login_grades_by_it(client, classes):
    code, teacher = created(client, login_column="SIS Login ID")
    assert client.get(f"/api/classes/{code}/me", headers=bearer(teacher)).json()["login_column"] == "SIS Login ID"
    client.put(f"/api/classes/{code}/assignment", json={"items": [{"scene": SCENE, "steps": [{"step": "kinetic"}]}]},
               headers=bearer(teacher))

    # asked, so required: the join says what to type, located at the login
    missing = client.post(f"/api/classes/{code}/join", json={"name": "Ada L."})
    assert missing.status_code == 422 and missing.json()["loc"] == ["body", "login"]
    assert missing.json()["detail"] == ("This class asks for your institution login (the SIS Login ID Canvas knows you "
                                        "by): type it as you sign in there.")
    ada = client.post(f"/api/classes/{code}/join", json={"name": "Ada L.", "login": "  alovelace  "})
    assert ada.status_code == 200, ada.text
    assert (ada.json()["login_column"], ada.json()["login"]) == ("SIS Login ID", "alovelace")
    bo = client.post(f"/api/classes/{code}/join", json={"name": "bo_92", "login": "=bo92@uni.example"}).json()
    assert check(client, code, ada.json()["student_key"], RIGHT_T).json()["verdict"] == "correct"
    assert check(client, code, bo["student_key"], WRONG_T).json()["verdict"] == "incorrect"

    students = client.get(f"/api/classes/{code}/students", headers=bearer(teacher)).json()["students"]
    assert [(s["name"], s["login"]) for s in students] == [("Ada L.", "alovelace"), ("bo_92", "=bo92@uni.example")]
    book = client.get(f"/api/classes/{code}/grades", headers=bearer(teacher)).json()
    assert book["login_column"] == "SIS Login ID"
    assert [(s["login"], s["grades"][0]["score"]) for s in book["students"]] == [("alovelace", 100.0), ("=bo92@uni.example", 0.0)]

    # the file to import: the login first, under Canvas's header; a login that starts like a formula is quoted
    grades = rows_of(client.get(f"/api/classes/{code}/grades?format=csv", headers=bearer(teacher)))
    assert grades == [["SIS Login ID", "Student", "1. Assignment 1 (100 points)"],
                      ["alovelace", "Ada L.", "100.0"], ["'=bo92@uni.example", "bo_92", "0.0"]]
    details = rows_of(client.get(f"/api/classes/{code}/grades?format=details-csv", headers=bearer(teacher)))
    assert details[0][:3] == ["SIS Login ID", "Student", "1. Assignment 1 (100 points)"]
    assert [row[:3] for row in details[1:]] == [["alovelace", "Ada L.", "100.0"], ["'=bo92@uni.example", "bo_92", "0.0"]]

    # back on another device with the recovery code: the same login
    again = client.post(f"/api/classes/{code}/rejoin", json={"name": "Ada L.", "recovery_code": ada.json()["recovery_code"]})
    assert again.status_code == 200 and again.json()["login"] == "alovelace"
    students = client.get(f"/api/classes/{code}/students", headers=bearer(teacher)).json()["students"]
    assert students[0]["login"] == "alovelace"


def test_the_teacher_asks_for_moodle_usernames_later_and_stops(client, classes):
    code, teacher = created(client)
    # not asked: a login is refused, and the grades are keyed by pseudonym
    refused = client.post(f"/api/classes/{code}/join", json={"name": "cy", "login": "cy1"})
    assert refused.status_code == 422 and refused.json()["loc"] == ["body", "login"]
    assert refused.json()["detail"] == "This class does not ask for an institution login: leave it out."
    assert client.post(f"/api/classes/{code}/join", json={"name": "cy"}).status_code == 200
    assert rows_of(client.get(f"/api/classes/{code}/grades?format=csv", headers=bearer(teacher)))[0] == ["Student"]

    # the instructor's key only
    cy_key = client.post(f"/api/classes/{code}/join", json={"name": "dee"}).json()["student_key"]
    assert client.put(f"/api/classes/{code}/login", json={"login_column": "username"},
                      headers=bearer(cy_key)).status_code == 403
    r = client.put(f"/api/classes/{code}/login", json={"login_column": "username"}, headers=bearer(teacher))
    assert r.status_code == 200 and r.json() == {"code": code, "login_column": "username"}
    assert client.post(f"/api/classes/{code}/join", json={"name": "fen", "login": "fen7"}).status_code == 200
    # Moodle's header; students who joined before it was asked have an empty cell
    assert rows_of(client.get(f"/api/classes/{code}/grades?format=csv", headers=bearer(teacher))) == [
        ["username", "Student"], ["", "cy"], ["", "dee"], ["fen7", "fen"]]
    assert client.put(f"/api/classes/{code}/login", json={"login_column": None}, headers=bearer(teacher)).status_code == 200
    assert rows_of(client.get(f"/api/classes/{code}/grades?format=csv", headers=bearer(teacher)))[0] == ["Student"]


@pytest.mark.parametrize(
    ("login", "says"),
    [
        ("   ", "This class asks for your institution login (the one your school's learning platform knows you by)"),
        ("x" * 65, "An institution login has at most 64 characters; this one has 65."),
        ("ada\tlovelace", "without control characters (a tab or a line break)"),
        ("ada\u0085", "without control characters"),
    ],
)
def test_a_login_that_is_no_login_is_refused_with_what_is_allowed(client, classes, login, says):
    code, _teacher = created(client, login_column="Login")
    r = client.post(f"/api/classes/{code}/join", json={"name": "ada", "login": login})
    assert r.status_code == 422 and r.json()["loc"] == ["body", "login"] and says in r.json()["detail"], r.text
    # nothing was recorded: the same pseudonym joins once the login is right
    assert client.post(f"/api/classes/{code}/join", json={"name": "ada", "login": "x" * 64}).status_code == 200


@pytest.mark.parametrize("column", ["Username", "email", "", 3])
def test_a_column_no_lms_matches_by_is_refused(client, classes, column):
    r = client.post("/api/classes", json={"title": "M", "login_column": column})
    assert r.status_code == 422 and r.json()["errors"][0]["loc"] == ["body", "login_column"], r.text
    assert r.json()["detail"] == "login_column: Input should be 'SIS Login ID', 'username' or 'Login'"
