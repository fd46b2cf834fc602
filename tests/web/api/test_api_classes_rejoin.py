"""A student who changes device (issue 45): a recovery code shown once at joining, with the pseudonym, opens the same
record again; the taken name says how to get back; the teacher can give a student a new code."""

from __future__ import annotations

import re

import pytest
from sqlalchemy import text

from app.service.classroom import keys
from tests.web.api.test_api_classes import RIGHT_T, WRONG_T, bearer, check, new_class

CODE = re.compile(r"[ACEFHKMNPRTWXY3479]{4}-[ACEFHKMNPRTWXY3479]{4}-[ACEFHKMNPRTWXY3479]{4}")


@pytest.mark.slow
def test_a_student_gets_back_to_their_record_on_another_device(client, classes):
    code, teacher = new_class(client)
    joined = client.post(f"/api/classes/{code}/join", json={"name": "ana"}).json()
    recovery, first_key = joined["recovery_code"], joined["student_key"]
    assert CODE.fullmatch(recovery)
    assert check(client, code, first_key, WRONG_T).json()["verdict"] == "incorrect"

    # the taken name says how to get back
    taken = client.post(f"/api/classes/{code}/join", json={"name": "ana"})
    assert taken.status_code == 422 and taken.json()["loc"] == ["body", "name"]
    assert taken.json()["detail"] == (
        "The name “ana” is taken in this class: if it is you, choose “I joined before on another device” and type "
        "your recovery code (or ask your teacher for a new one); otherwise choose another name.")

    # another device: the pseudonym and the code, typed loosely (lower case, spaces for dashes)
    again = client.post(f"/api/classes/{code.lower()}/rejoin",
                        json={"name": "ana", "recovery_code": recovery.lower().replace("-", " ")})
    assert again.status_code == 200, again.text
    body = again.json()
    assert body["name"] == "ana" and body["code"] == code and "recovery_code" not in body
    second_key = body["student_key"]
    assert second_key != first_key
    # the same record: the answer before is there, and the next adds to it
    assert check(client, code, second_key, RIGHT_T).json()["verdict"] == "correct"
    mine = client.get(f"/api/classes/{code}/me", headers=bearer(second_key)).json()
    assert mine["name"] == "ana" and mine["progress"]["attempts"] == 2
    rows = client.get(f"/api/classes/{code}/students", headers=bearer(teacher)).json()["students"]
    assert [(s["name"], s["attempts"], s["done"]) for s in rows] == [("ana", 2, 1)]
    # the first device's key no longer opens the record
    assert client.get(f"/api/classes/{code}/me", headers=bearer(first_key)).status_code == 403
    # the database keeps only the code's digest
    with classes.db.session() as session:
        stored = session.execute(text("SELECT recovery_hash FROM students")).scalar()
    assert stored == keys.digest(recovery.replace("-", "")) and recovery not in stored


@pytest.mark.parametrize(
    ("name", "recovery", "status", "says"),
    [
        ("ana", "ACEF-HKMN-PRTW", 403, "this pseudonym and recovery code do not open a record of this class"),
        ("bo", None, 403, "this pseudonym and recovery code do not open a record of this class"),  # another's code
        ("ana", "ACEF-HKMN", 403, "this recovery code is incomplete: it has 8 of its 12 letters and digits"),
        ("ana", "ACEF-HKMN-PRTB", 403, "“B” is never in a recovery code"),
        ("", "ACEF-HKMN-PRTW", 422, "name"),
    ],
)
def test_a_wrong_code_or_name_opens_nothing_and_says_why(client, classes, name, recovery, status, says):
    code, _teacher = new_class(client)
    ana = client.post(f"/api/classes/{code}/join", json={"name": "ana"}).json()
    client.post(f"/api/classes/{code}/join", json={"name": "bo"})
    r = client.post(f"/api/classes/{code}/rejoin", json={"name": name, "recovery_code": recovery or ana["recovery_code"]})
    assert r.status_code == status and says in r.text, r.text
    assert client.get(f"/api/classes/{code}/me", headers=bearer(ana["student_key"])).status_code == 200


@pytest.mark.slow
def test_the_teacher_gives_a_student_a_new_code(client, classes):
    code, teacher = new_class(client)
    ana = client.post(f"/api/classes/{code}/join", json={"name": "ana"}).json()
    assert client.post(f"/api/classes/{code}/students/recovery", json={"name": "ana"},
                       headers=bearer(ana["student_key"])).status_code == 403  # the teacher's, not a student's
    given = client.post(f"/api/classes/{code}/students/recovery", json={"name": "ana"}, headers=bearer(teacher))
    assert given.status_code == 200 and given.json()["name"] == "ana" and CODE.fullmatch(given.json()["recovery_code"])
    assert given.json()["recovery_code"] != ana["recovery_code"]
    old = client.post(f"/api/classes/{code}/rejoin", json={"name": "ana", "recovery_code": ana["recovery_code"]})
    assert old.status_code == 403  # the old code stops working
    new = client.post(f"/api/classes/{code}/rejoin", json={"name": "ana", "recovery_code": given.json()["recovery_code"]})
    assert new.status_code == 200 and new.json()["name"] == "ana"
    nobody = client.post(f"/api/classes/{code}/students/recovery", json={"name": "cy"}, headers=bearer(teacher))
    assert nobody.status_code == 422 and nobody.json()["detail"] == "no student of this class has the pseudonym 'cy'"
