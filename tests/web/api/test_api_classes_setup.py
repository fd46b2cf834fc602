"""A typed system assigned to a class has a set-up (issue 45): the instructor's words for its coordinates and the
zero of U, required and refused in words when missing; students get it with the system's defining data typeset,
without what an assigned step asks for."""

from __future__ import annotations

import pytest

from tests.web.api.test_api_classes import bearer, new_class

SPRING = {"coordinates": ["x"], "parameters": ["m", "k"], "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}
SETUP = "x is the stretch of the spring from its natural length, positive to the right.\nU = 0 at x = 0."
PENDULUM = {"coordinates": ["theta"], "parameters": ["m", "l", "g", "b"],
            "particles": [{"mass": "m", "position": ["l sin θ", "-l cos(theta)"], "label": "bob"}],
            "potential": "-m g l cos θ", "forces": {"theta": "-b theta_dot"}}


def assign(client, code, teacher, item):
    return client.post(f"/api/classes/{code}/assignments", json={"title": "Week 1", "items": [item]},
                       headers=bearer(teacher))


@pytest.mark.parametrize("setup", [None, "", "   \n  "])
def test_a_typed_system_without_its_set_up_is_refused_with_what_to_write(client, classes, setup):
    code, teacher = new_class(client)
    item = {"system": SPRING, "name": "spring", "steps": [{"step": "kinetic"}]}
    r = assign(client, code, teacher, item if setup is None else item | {"setup": setup})
    assert r.status_code == 422, r.text
    body = r.json()
    assert body["loc"] == ["body", "items", "0", "setup"]
    assert body["detail"] == ("items.0.setup: a system you type needs its set-up: say what each coordinate is, where "
                              "it is measured from and where U = 0 (for example: x is the stretch of the spring from "
                              "its natural length; U = 0 at x = 0); students read it above the boxes")


def test_a_set_up_is_for_a_typed_system_and_has_bounds(client, classes):
    code, teacher = new_class(client)
    r = assign(client, code, teacher, {"scene": "simple-pendulum", "setup": "θ from the downward vertical"})
    assert r.status_code == 422 and r.json()["loc"] == ["body", "items", "0", "setup"]
    assert "a scene's page sets it up" in r.json()["detail"]
    long = assign(client, code, teacher, {"system": SPRING, "name": "spring", "steps": [{"step": "kinetic"}],
                                          "setup": "x" * 1001})
    assert long.status_code == 422 and "1000" in long.text


@pytest.mark.parametrize(
    ("steps", "given"),
    [
        # equations only: T and U both shown
        ([{"step": "acceleration", "coordinate": "x"}], [r"T = \frac{m \dot{x}^{2}}{2}", r"U = \frac{k x^{2}}{2}"]),
        ([{"step": "kinetic"}], [r"U = \frac{k x^{2}}{2}"]),  # T is the answer asked for: not shown
        ([{"step": "potential"}, {"step": "equation", "coordinate": "x"}], [r"T = \frac{m \dot{x}^{2}}{2}"]),
        ([{"step": "lagrangian"}], []),  # L = T - U: neither shown
    ],
)
def test_students_see_the_set_up_and_what_the_system_is_defined_by(client, classes, steps, given):
    code, teacher = new_class(client)
    r = assign(client, code, teacher, {"system": SPRING, "name": "spring", "steps": steps, "setup": f"  {SETUP} "})
    assert r.status_code == 201, r.text
    joined = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()
    (item,) = joined["assignments"][0]["items"]
    assert item["setup"] == SETUP  # kept as written, line break and all, without the spaces around it
    assert [g["latex"] for g in item["given"]] == given and all(g["label"] == "" for g in item["given"])
    mine = client.get(f"/api/classes/{code}/me", headers=bearer(joined["student_key"])).json()
    assert mine["assignments"][0]["items"][0]["given"] == item["given"]


@pytest.mark.slow
def test_particles_and_forces_are_typeset_as_typed(client, classes):
    code, teacher = new_class(client)
    setup = "θ is the angle of the rod from the downward vertical; U = 0 at the pivot's height."
    r = assign(client, code, teacher, {"system": PENDULUM, "name": "damped pendulum", "setup": setup,
                                       "steps": [{"step": "equation", "coordinate": "theta"}]})
    assert r.status_code == 201, r.text
    (item,) = client.post(f"/api/classes/{code}/join", json={"name": "Ada"}).json()["assignments"][0]["items"]
    assert item["given"] == [
        {"label": "Particle 1, bob",
         "latex": r"\text{mass } m,\quad (x,\ y) = \left(l \sin \theta,\ -l \cos \theta\right)"},
        {"label": "", "latex": r"U = -m g l \cos \theta"},
        {"label": "Generalized force", "latex": r"Q_{\theta} = -b \dot{\theta}"},
    ]
