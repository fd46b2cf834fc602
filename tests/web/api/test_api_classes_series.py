"""A class's series of assignments, its gradebook and the instructor's recovery code, through the API, on SQLite
and on PostgreSQL."""

from __future__ import annotations

import csv
import io
from datetime import UTC, datetime, timedelta

import pytest

from app.main import app
from app.service.classroom import store
from app.web.api.classes import classroom as classroom_dep
from tests.classes import classroom
from tests.web.api.test_api_classes import RIGHT_T, SCENE, WRONG_T, bearer, join

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

RIGHT_U = "-m*g*R*cos(theta)"
SPRING = {"coordinates": ["x"], "parameters": ["m", "k"], "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}
SETUP = "x is the stretch of the spring from its natural length; U = 0 at x = 0."
LATER = (datetime.now(UTC) + timedelta(days=7)).replace(microsecond=0)
DUE = LATER.isoformat().replace("+00:00", "Z")


@pytest.fixture
def classes(classes_on_both):
    """Every test here on SQLite and on PostgreSQL (tests/web/conftest.py)."""
    return classes_on_both


def created(client, title="Mechanics") -> dict:
    r = client.post("/api/classes", json={"title": title})
    assert r.status_code == 201, r.text
    return r.json()


def answer(client, code, key, step, text, assignment=None, **target):
    body = {**(target or {"scene": SCENE}), "step": step, "answer": text}
    if assignment is not None:
        body["assignment"] = assignment
    r = client.post(f"/api/classes/{code}/check", json=body, headers=bearer(key))
    assert r.status_code == 200, r.text
    return r.json()["verdict"]


def test_a_series_its_progress_and_its_grades(client, classes):
    made = created(client)
    code, teacher = made["code"], made["teacher_key"]
    week1 = {"title": "Week 1: the pendulum's T and U", "due": DUE,
             "items": [{"scene": SCENE, "steps": [{"step": "kinetic"}, {"step": "potential"}]}]}
    r = client.post(f"/api/classes/{code}/assignments", json=week1, headers=bearer(teacher))
    assert r.status_code == 201, r.text
    assert r.headers["location"] == f"/api/classes/{code}/assignments/1"
    assert (r.json()["n"], r.json()["title"], r.json()["due"]) == (1, week1["title"], LATER.replace(tzinfo=None).isoformat() + "Z")
    week2 = {"title": "Week 2", "items": [
        {"system": SPRING, "name": "spring", "steps": [{"step": "acceleration", "coordinate": "x"}], "setup": SETUP},
        {"scene": SCENE, "steps": [{"step": "kinetic"}]}]}  # the pendulum's T again: answered apart from week 1
    assert client.post(f"/api/classes/{code}/assignments", json=week2, headers=bearer(teacher)).json()["n"] == 2
    series = client.get(f"/api/classes/{code}/assignments", headers=bearer(teacher)).json()["assignments"]
    assert [(a["n"], a["title"], a["due"] is None) for a in series] == [(1, week1["title"], False), (2, "Week 2", True)]

    joined = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()
    assert [a["title"] for a in joined["assignments"]] == [week1["title"], "Week 2"]
    assert joined["assignment"] == series[0]["items"]  # the first assignment, as the single one was
    ada, bo = joined["student_key"], join(client, code, "Bo")
    join(client, code, "Cy")  # joins and answers nothing

    # Ada: week 1's T wrong then right, its U right at once; week 2 both right at once
    assert answer(client, code, ada, "kinetic", WRONG_T) == "incorrect"  # no number: the first holding the step
    assert answer(client, code, ada, "kinetic", RIGHT_T, 1) == "correct"
    assert answer(client, code, ada, "potential", RIGHT_U) == "equivalent"  # done, as a correct answer
    assert answer(client, code, ada, "acceleration", "-k*x/m", system="spring", coordinate="x") == "correct"
    assert answer(client, code, ada, "kinetic", RIGHT_T, 2) == "correct"
    # Bo: shown week 1's T, then right; its U wrong
    shown = client.post(f"/api/classes/{code}/shown", json={"scene": SCENE, "step": "kinetic", "assignment": 1},
                        headers=bearer(bo))
    assert shown.status_code == 200 and shown.json() == {"assignment": 1, "step": "kinetic", "coordinate": None}
    assert client.post(f"/api/classes/{code}/shown", json={"scene": SCENE, "step": "kinetic"},
                       headers=bearer(bo)).status_code == 200  # shown twice: counted once
    assert answer(client, code, bo, "kinetic", RIGHT_T, 1) == "correct"
    assert answer(client, code, bo, "potential", "m*g*R*cos(theta)", 1) == "incorrect"

    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    assert summary["assignments"] == [
        {"n": 1, "title": week1["title"], "due": series[0]["due"], "steps": 2, "students_done": ["Ada"],
         "students_shown": [], "students_stuck": ["Bo"]},
        {"n": 2, "title": "Week 2", "due": None, "steps": 2, "students_done": ["Ada"], "students_shown": [], "students_stuck": []}]
    counts = [(s["assignment"], s.get("scene") or s.get("system"), s["step"], s["correct"], s["incorrect"], s["stuck"])
              for s in summary["steps"]]
    assert counts == [(1, SCENE, "kinetic", 2, 1, 0), (1, SCENE, "potential", 1, 1, 1),
                      (2, "spring", "acceleration", 1, 0, 0), (2, SCENE, "kinetic", 1, 0, 0)]
    mine = client.get(f"/api/classes/{code}/me", headers=bearer(ada)).json()
    assert sorted((s["assignment"], s["step"], s["done"]) for s in mine["progress"]["steps"]) == [
        (1, "kinetic", True), (1, "potential", True), (2, "acceleration", True), (2, "kinetic", True)]

    grades = client.get(f"/api/classes/{code}/grades", headers=bearer(teacher))
    assert grades.status_code == 200 and grades.headers["cache-control"] == "no-store"
    book = grades.json()
    assert book["points"] == 100 and [a["steps"] for a in book["assignments"]] == [2, 2]
    assert {s["name"]: [(g["first_try"], g["right"], g["shown"], g["score"]) for g in s["grades"]]
            for s in book["students"]} == {
        "Ada": [(1, 2, 0, 100.0), (2, 2, 0, 100.0)],
        "Bo": [(0, 1, 1, 0.0), (0, 0, 0, None)],  # his right T came after it was shown: not his own
        "Cy": [(0, 0, 0, None), (0, 0, 0, None)]}  # nothing tried, nothing due yet: no score, not a zero
    sheet = client.get(f"/api/classes/{code}/grades?format=csv", headers=bearer(teacher))
    assert sheet.headers["content-type"].startswith("text/csv")
    assert 'filename="grades-' in sheet.headers["content-disposition"]
    rows = list(csv.reader(io.StringIO(sheet.content.decode("utf-8-sig"))))
    one, two = f"1. {week1['title']}", "2. Week 2"
    # the file to import: one column per assignment and nothing else; blank where there is no score yet
    assert rows == [["Student", f"{one} (100 points)", f"{two} (100 points)"],
                    ["Ada", "100.0", "100.0"], ["Bo", "0.0", ""], ["Cy", "", ""]]
    details = client.get(f"/api/classes/{code}/grades?format=details-csv", headers=bearer(teacher))
    assert 'filename="grades-' in details.headers["content-disposition"] and "-details.csv" in details.headers[
        "content-disposition"]
    rows = list(csv.reader(io.StringIO(details.content.decode("utf-8-sig"))))
    assert rows[0] == ["Student", f"{one} (100 points)", f"{one}: right first try", f"{one}: right", f"{one}: shown",
                       f"{one}: steps", f"{two} (100 points)", f"{two}: right first try", f"{two}: right",
                       f"{two}: shown", f"{two}: steps"]
    assert rows[1:] == [["Ada", "100.0", "1", "2", "0", "2", "100.0", "2", "2", "0", "2"],
                        ["Bo", "0.0", "0", "1", "1", "2", "", "0", "0", "0", "2"],
                        ["Cy", "", "0", "0", "0", "2", "", "0", "0", "0", "2"]]

    # deleting week 1 removes its answers; week 2 becomes number 1
    assert client.delete(f"/api/classes/{code}/assignments/1", headers=bearer(teacher)).status_code == 204
    left = client.get(f"/api/classes/{code}/assignments", headers=bearer(teacher)).json()["assignments"]
    assert [(a["n"], a["title"]) for a in left] == [(1, "Week 2")]
    assert client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()["attempts"] == 2


def test_the_first_assignment_through_the_single_assignment_route(client, classes):
    made = created(client)
    code, teacher = made["code"], made["teacher_key"]
    items = {"items": [{"scene": SCENE, "steps": [{"step": "kinetic"}]}]}
    assert client.put(f"/api/classes/{code}/assignment", json=items, headers=bearer(teacher)).status_code == 200
    series = client.get(f"/api/classes/{code}/assignments", headers=bearer(teacher)).json()["assignments"]
    assert [(a["n"], a["title"], len(a["items"])) for a in series] == [(1, "Assignment 1", 1)]
    # a second one, then the old route again: it replaces the first's items only
    more = {"title": "Week 2", "items": [{"scene": "double-pendulum", "steps": [{"step": "kinetic"}]}]}
    client.post(f"/api/classes/{code}/assignments", json=more, headers=bearer(teacher))
    items["items"][0]["steps"] = [{"step": "potential"}]
    client.put(f"/api/classes/{code}/assignment", json=items, headers=bearer(teacher))
    series = client.get(f"/api/classes/{code}/assignments", headers=bearer(teacher)).json()["assignments"]
    assert [(a["title"], a["items"][0]["steps"][0]["step"]) for a in series] == [
        ("Assignment 1", "potential"), ("Week 2", "kinetic")]
    # PUT /assignments/{n} replaces one, keeping its place
    renamed = {"title": "Week 2, again", "due": DUE, "items": more["items"]}
    r = client.put(f"/api/classes/{code}/assignments/2", json=renamed, headers=bearer(teacher))
    assert r.status_code == 200 and (r.json()["n"], r.json()["title"]) == (2, "Week 2, again")
    again = client.put(f"/api/classes/{code}/assignments/2", json=renamed, headers=bearer(teacher))
    assert again.status_code == 200  # its stored due time, sent back unchanged, is accepted


def test_refusals_of_the_series_say_what_is_wrong(client, classes, monkeypatch):
    made = created(client)
    code, teacher = made["code"], made["teacher_key"]
    url = f"/api/classes/{code}/assignments"

    def post(body):
        return client.post(url, json=body, headers=bearer(teacher))

    steps = [{"scene": SCENE, "steps": [{"step": "kinetic"}]}]
    r = post({"title": "x", "items": [{"scene": SCENE, "steps": [{"step": "equation", "coordinate": "phi"}]}]})
    assert r.status_code == 422 and r.json()["loc"][:4] == ["body", "items", "0", "steps"] and "its steps are" in r.text
    r = post({"title": "x", "due": "Friday", "items": steps})
    assert r.status_code == 422 and "due" in r.text
    r = post({"title": "x", "due": "2030-12-06T17:00:00", "items": steps})  # no time zone
    assert r.status_code == 422 and "due" in r.text
    r = post({"title": "x", "due": "2020-01-01T12:00:00Z", "items": steps})
    assert r.status_code == 422 and r.json()["loc"] == ["body", "due"] and "already past" in r.json()["detail"]
    assert post({"title": "x", "items": []}).status_code == 422  # an assignment has an item
    assert post({"title": "", "items": steps}).status_code == 422
    monkeypatch.setattr(store, "MAX_ASSIGNMENTS", 2)
    assert post({"title": "one", "items": steps}).status_code == 201
    assert post({"title": "two", "items": steps}).status_code == 201
    r = post({"title": "three", "items": steps})
    assert r.status_code == 422 and "at most 2 assignments" in r.json()["detail"]
    r = client.put(f"{url}/3", json={"title": "x", "items": steps}, headers=bearer(teacher))
    assert r.status_code == 404 and "numbered 1 to 2" in r.json()["detail"]
    assert client.delete(f"{url}/3", headers=bearer(teacher)).status_code == 404
    assert client.delete(f"{url}/0", headers=bearer(teacher)).status_code == 422
    student = join(client, code, "Ada")
    assert client.post(url, json={"title": "x", "items": steps}, headers=bearer(student)).status_code == 403
    assert client.get(url).status_code == 401
    r = client.post(f"/api/classes/{code}/check", headers=bearer(student),
                    json={"scene": SCENE, "step": "kinetic", "answer": RIGHT_T, "assignment": 3})
    assert r.status_code == 422 and r.json()["loc"][-1] == "assignment"
    assert client.get(f"/api/classes/{code}/grades", headers=bearer(student)).status_code == 403
    assert client.get(f"/api/classes/{code}/grades?format=xls", headers=bearer(teacher)).status_code == 422
    # a method the address does not take: 405, naming every method it does (two routes share the address)
    for method, path, allowed in (("PATCH", url, "GET, POST"), ("PATCH", f"{url}/1", "DELETE, PUT")):
        r = client.request(method, path)
        assert r.status_code == 405 and r.headers["allow"] == allowed


def test_a_formula_in_a_name_or_title_is_not_run_by_a_spreadsheet(client, classes):
    made = created(client)
    code, teacher = made["code"], made["teacher_key"]
    client.post(f"/api/classes/{code}/assignments", headers=bearer(teacher),
                json={"title": "=HYPERLINK(\"x\")", "items": [{"scene": SCENE, "steps": [{"step": "kinetic"}]}]})
    join(client, code, "@SUM(A1)")
    rows = list(csv.reader(io.StringIO(client.get(f"/api/classes/{code}/grades?format=csv",
                                                   headers=bearer(teacher)).content.decode("utf-8-sig"))))
    assert rows[0][1] == '1. =HYPERLINK("x") (100 points)'  # not at the start of its cell: harmless
    assert rows[1][0] == "'@SUM(A1)"


def test_the_answers_csv_keeps_the_answer_as_typed(client, classes):
    made = created(client)
    code, teacher = made["code"], made["teacher_key"]
    client.post(f"/api/classes/{code}/assignments", headers=bearer(teacher),
                json={"title": "Week 1", "items": [{"scene": SCENE, "steps": [{"step": "potential"}]}]})
    ada = join(client, code, "-Ada")
    assert answer(client, code, ada, "potential", RIGHT_U) in ("correct", "equivalent")
    rows = list(csv.DictReader(io.StringIO(client.get(f"/api/classes/{code}/export?format=csv",
                                                      headers=bearer(teacher)).content.decode("utf-8-sig"))))
    # the answer begins with a minus and stays as typed; a name beginning like a formula gets the apostrophe
    assert [(r["student"], r["assignment"], r["item"], r["answer"]) for r in rows] == [
        ("'-Ada", "1. Week 1", "Simple pendulum", RIGHT_U)]


def test_the_recovery_code_gives_the_instructors_key_back(client, classes):
    made = created(client)
    code, teacher, recovery = made["code"], made["teacher_key"], made["recovery_code"]
    assert len(recovery.replace("-", "")) == 24 and made["teacher_link"] == f"/teach#class={code}&recover={recovery}"
    with classes.db.session() as session:
        from sqlalchemy import text

        dumped = repr(session.execute(text("SELECT * FROM classes")).all())
    assert recovery not in dumped and recovery.replace("-", "") not in dumped and teacher not in dumped
    url = f"/api/classes/{code}/recover"
    typed = " " + recovery.lower().replace("-", " ") + " "  # as typed from paper: lower case, spaces
    r = client.post(url, json={"recovery_code": typed})
    assert r.status_code == 200 and r.json() == {"code": code, "title": "Mechanics", "teacher_key": teacher}
    wrong = client.post(url, json={"recovery_code": "ACEF-HKMN-PRTW-XY34-79AC-EFHK"})
    unknown = client.post("/api/classes/ACEFHK/recover", json={"recovery_code": recovery})
    assert wrong.status_code == unknown.status_code == 403 and wrong.json() == unknown.json()
    assert client.post(url, json={"recovery_code": "not a code"}).status_code == 403
    # a teacher link cut short (as mail programs do): the refusal says it is incomplete, and what a code is
    cut = client.post(url, json={"recovery_code": recovery[:4]})
    assert cut.status_code == 403
    assert cut.json()["detail"].startswith("this recovery code is incomplete: it has 4 of its 24 letters and digits")
    other = created(client, "another")  # one class's recovery code opens no other class
    assert client.post(f"/api/classes/{other['code']}/recover", json={"recovery_code": recovery}).status_code == 403


@pytest.mark.parametrize("backend", ["sqlite"])
def test_wrong_recovery_codes_are_rate_limited_as_joins(client, services, tmp_path, backend):
    room = classroom(services.checking, backend, tmp_path, None, client_joins_per_minute=3, class_joins_per_minute=50)
    app.dependency_overrides[classroom_dep] = lambda: room
    try:
        made = created(client)
        url = f"/api/classes/{made['code']}/recover"
        client.get("/join")  # a session of its own
        statuses = [client.post(url, json={"recovery_code": "ACEF-HKMN-PRTW-XY34-79AC-EFH" + c}).status_code
                    for c in "KMNP"]
        assert statuses == [403, 403, 403, 429]
        assert client.post(url, json={"recovery_code": made["recovery_code"]}).status_code == 429  # this minute
    finally:
        app.dependency_overrides.pop(classroom_dep, None)
        room.stop()
        client.cookies.clear()
