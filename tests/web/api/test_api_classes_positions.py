"""A class assigns a scene's positions (one step per Cartesian component) and records each component apart."""

from __future__ import annotations

import csv
import io

import pytest

from tests.web.api.test_api_classes import bearer, join, new_class

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

SCENE = "simple-pendulum"


def test_each_component_of_a_position_is_its_own_step(client, classes):
    code, teacher = new_class(client)
    steps = [{"step": "position", "coordinate": "x"}, {"step": "position", "coordinate": "z"}]
    r = client.put(f"/api/classes/{code}/assignment", json={"items": [{"scene": SCENE, "steps": steps}]},
                   headers=bearer(teacher))
    assert r.status_code == 200, r.text
    ada = join(client, code, "Ada")

    def check(component, answer):
        body = {"scene": SCENE, "step": "position", "coordinate": component, "answer": answer}
        return client.post(f"/api/classes/{code}/check", json=body, headers=bearer(ada))

    x = check("x", "R*sin(theta)")
    assert x.status_code == 200 and x.json()["verdict"] == "correct", x.text
    z = check("z", "R*sin(theta)")  # x's answer in z's box
    assert z.status_code == 200 and z.json()["verdict"] == "incorrect", z.text
    summary = client.get(f"/api/classes/{code}/summary", headers=bearer(teacher)).json()
    rows = {s["coordinate"]: s for s in summary["steps"]}
    assert set(rows) == {"x", "z"}
    assert rows["x"]["correct"] == 1 and rows["z"]["incorrect"] == 1


def test_a_component_that_is_not_one_is_refused_with_what_is_allowed(client, classes):
    code, teacher = new_class(client)
    steps = [{"step": "position", "coordinate": "w"}]
    r = client.put(f"/api/classes/{code}/assignment", json={"items": [{"scene": SCENE, "steps": steps}]},
                   headers=bearer(teacher))
    assert r.status_code == 422 and "position" in r.text

def test_the_answers_file_names_each_position_step_apart(client, classes):
    """The double pendulum's four position steps are four names in the answers' CSV (review inst-c 4), and every
    step's name is in sentence case there."""
    code, teacher = new_class(client)
    steps = [{"step": "position", "coordinate": c} for c in ("x1", "z1")] + [{"step": "kinetic"}]
    r = client.put(f"/api/classes/{code}/assignment",
                   json={"items": [{"scene": "double-pendulum", "steps": steps}]}, headers=bearer(teacher))
    assert r.status_code == 200, r.text
    jo = join(client, code, "Jo")
    for component, answer in (("x1", "l1*sin(theta1)"), ("z1", "-l1*cos(theta1)")):
        body = {"scene": "double-pendulum", "step": "position", "coordinate": component, "answer": answer}
        assert client.post(f"/api/classes/{code}/check", json=body, headers=bearer(jo)).json()["verdict"] == "correct"
    body = {"scene": "double-pendulum", "step": "kinetic", "answer": "m1*l1**2*theta1_dot**2/2"}
    assert client.post(f"/api/classes/{code}/check", json=body, headers=bearer(jo)).status_code == 200
    table = list(csv.DictReader(io.StringIO(
        client.get(f"/api/classes/{code}/export", headers=bearer(teacher)).content.decode("utf-8-sig"))))
    assert [r["step"] for r in table] == ["Position x₁", "Position z₁", "Kinetic energy T"]
