"""What the teacher reads of a class speaks about the student, never to him: a named mistake on the dashboard's
summary and in the answers file is in the third person ("the term …"), while the student's own verdict keeps the
tutor's second person ("your term …")."""

from __future__ import annotations

import csv
import io

import pytest

from app.main import app
from app.web.api_classes import classroom as classroom_dep
from tests.classes import classroom

SCENE = "simple-pendulum"
SWAPPED_U = "m*g*R*sin(theta)"  # U = −m g R cos θ with sin for cos: a named mistake spoken as "your term …"


@pytest.fixture
def classes(services, tmp_path):
    room = classroom(services.checking, "sqlite", tmp_path, None)
    app.dependency_overrides[classroom_dep] = lambda: room
    yield room
    app.dependency_overrides.pop(classroom_dep, None)
    room.stop()


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
