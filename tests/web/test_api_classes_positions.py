"""A class assigns a scene's positions (one step per Cartesian component) and records each component apart."""

from __future__ import annotations

from tests.web.test_api_classes import bearer, join, new_class

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
