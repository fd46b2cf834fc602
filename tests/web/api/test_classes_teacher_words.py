"""What the teacher reads of a class speaks about the student, never to him: a named mistake on the dashboard's
summary and in the answers file is in the third person ("the term …"), while the student's own verdict keeps the
tutor's second person ("your term …")."""

from __future__ import annotations

import csv
import io
import re
from datetime import timedelta

import pytest

from app.service.classroom import store
from app.service.classroom.database import now

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

SCENE = "simple-pendulum"
RIGHT_T = "m*R**2*theta_dot**2/2"
SWAPPED_U = "m*g*R*sin(theta)"  # U = −m g R cos θ with sin for cos: a named mistake spoken as "your term …"


def bearer(key: str) -> dict[str, str]:
    return {"Authorization": f"Bearer {key}"}


def test_the_teacher_reads_the_mistake_in_the_third_person(client, classes):
    made = client.post("/api/classes", json={"title": "Mechanics"}).json()
    code, teacher = made["code"], made["teacher_key"]
    items = {"items": [{"scene": SCENE, "steps": [{"step": "potential"}]}]}
    assert client.put(f"/api/classes/{code}/assignment", json=items, headers=bearer(teacher)).status_code == 200
    student = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()["student_key"]
    verdict = client.post(f"/api/classes/{code}/check", json={"scene": SCENE, "step": "potential",
                                                              "answer": SWAPPED_U}, headers=bearer(student)).json()
    said = verdict["mistake"]["name"]
    assert "your term" in said  # the student is spoken to

    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    [named] = summary["mistakes"]
    assert named["name"] == said.replace("your term", "the term")
    assert "your" not in named["name"] and "you " not in named["name"]
    [step] = [s for s in summary["steps"] if s["step"] == "potential"]
    assert list(step["mistake_names"].values()) == [named["name"]]

    exported = client.get(f"/api/classes/{code}/export", headers=bearer(teacher))
    rows = list(csv.DictReader(io.StringIO(exported.content.decode("utf-8-sig"))))
    assert [r["mistake"] for r in rows] == [named["name"]]


def test_the_answers_file_says_what_counts_and_why(client, classes):
    """Each answer: its time to the second in UTC, the step in words, the verdict in words, typed after "Show this
    step" or not, late or not, and whether it counts toward the grade; a byte-order mark for a spreadsheet."""
    made = client.post("/api/classes", json={"title": "Mechanics"}).json()
    code, teacher = made["code"], made["teacher_key"]
    class_id = store.access(classes.db, code, teacher).class_id
    steps = [{"step": s, "coordinate": None} for s in ("kinetic", "potential", "hamiltonian")]
    store.add_assignment(classes.db, class_id, "Due", now() + timedelta(days=7),
                         [{"item": SCENE, "system": None, "parameters": {}, "steps": steps}])
    store.add_assignment(classes.db, class_id, "Past", now() - timedelta(minutes=1),
                         [{"item": SCENE, "system": None, "parameters": {}, "steps": steps[:1]}])
    ada, bo = (client.post(f"/api/classes/{code}/join", json={"name": n}).json()["student_key"] for n in ("Ada", "Bo"))

    def answer(key, step, typed, assignment):
        r = client.post(f"/api/classes/{code}/check", headers=bearer(key),
                        json={"scene": SCENE, "step": step, "answer": typed, "assignment": assignment})
        assert r.status_code == 200, r.text
        return r.json()["verdict"]

    assert answer(ada, "kinetic", RIGHT_T, 1) == "correct"
    assert answer(ada, "potential", "-m*g*R*cos(theta)", 1) == "equivalent"  # another zero of height
    assert answer(ada, "hamiltonian", "m*R**2*theta_dot**2/2 + m*g*R*(1 - cos(theta))", 1) == "correct"
    assert answer(ada, "kinetic", RIGHT_T, 2) == "correct"  # after the due time of assignment 2
    assert client.post(f"/api/classes/{code}/shown", json={"scene": SCENE, "step": "kinetic", "assignment": 1},
                       headers=bearer(bo)).status_code == 200
    assert answer(bo, "kinetic", RIGHT_T, 1) == "correct"  # typed after the step was shown

    raw = client.get(f"/api/classes/{code}/export", headers=bearer(teacher)).content
    assert raw.startswith(b"\xef\xbb\xbf")
    rows = list(csv.DictReader(io.StringIO(raw.decode("utf-8-sig"))))
    assert [(r["student"], r["assignment"], r["step"], r["verdict"], r["after shown"], r["late"], r["counted"])
            for r in rows] == [
        ("Ada", "1. Due", "Kinetic energy T", "right", "no", "no", "yes"),
        ("Ada", "1. Due", "Potential energy U", "right, in an equivalent form", "no", "no", "yes"),
        ("Ada", "1. Due", "Energy function h", "right", "no", "no", "yes"),
        ("Ada", "2. Past", "Kinetic energy T", "right", "no", "yes", "no: after the due time"),
        ("Bo", "1. Due", "Kinetic energy T", "right", "yes", "no", "no: typed after the step was shown")]
    assert all(re.fullmatch(r"\d{4}-\d\d-\d\d \d\d:\d\d:\d\d", r["time (UTC)"]) for r in rows)
    # the grade follows the same rule: Ada's late answer and Bo's shown one do not count
    book = client.get(f"/api/classes/{code}/grades", headers=bearer(teacher)).json()
    assert {s["name"]: [g["score"] for g in s["grades"]] for s in book["students"]} == {
        "Ada": [100.0, 0.0], "Bo": [0.0, 0.0]}  # Bo: 1 of 3 tried
