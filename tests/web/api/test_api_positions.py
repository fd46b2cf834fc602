"""The positions step through the API (issue 41, item 1): listed first, its axes and origin said on the step,
its slips named, another origin accepted, and a bad component refused with what is allowed."""

from __future__ import annotations

import pytest

from tests.engine.check_corpus import CART_PENDULUM


@pytest.mark.slow
def test_the_wedges_practice_starts_with_the_positions_and_says_the_axes(client):
    body = client.get("/api/scenes/movable-incline/practice").json()
    first = [(e["step"], e["coordinate"]) for e in body["exercises"][:4]]
    # the block moves across and down; nothing to derive in a constant component, nor in the wedge's x = X, which
    # the block's x holds (review prof-q 3)
    assert first == [("position", "x2"), ("position", "z2"), ("kinetic", None), ("potential", None)]
    block = body["exercises"][0]
    assert block["title"] == "Position: x of the block" and block["lhs"] == r"x_{\text{block}}"
    assert "x across" in block["note"] and "z up" in block["note"] and "another origin" in block["note"]
    assert "D_dot" not in block["names"] and {"X", "D", "alpha"} <= set(block["names"])
    assert body["exercises"][2].get("note") is None


@pytest.mark.slow
def test_the_cylinders_practice_asks_its_centre_where_the_wedges_motion_enters(client):
    body = client.get("/api/scenes/rolling-cylinder-wedge/practice").json()
    first = [(e["step"], e["coordinate"], e["title"]) for e in body["exercises"][:3]]
    assert first == [
        ("position", "x2", "Position: x of the cylinder's centre"),
        ("position", "z2", "Position: z of the cylinder's centre"),
        ("kinetic", None, "Kinetic energy T"),
    ]
    url = "/api/scenes/rolling-cylinder-wedge/check"
    wrong = client.post(url, json={"step": "position", "coordinate": "x2", "answer": "s*cos(alpha) + r*sin(alpha)"})
    assert wrong.json()["mistake"]["key"] == "position.x2.carried.1", wrong.text
    assert "the cylinder's centre moves with the wedge" in wrong.json()["hint"]
    right = client.post(url, json={"step": "position", "coordinate": "z2", "answer": "r*cos(alpha) - s*sin(alpha)"})
    assert right.json()["verdict"] == "correct", right.text


@pytest.mark.slow
def test_the_wedges_x_left_out_of_the_blocks_is_named(client):
    url = "/api/scenes/movable-incline/check"
    wrong = client.post(url, json={"step": "position", "coordinate": "x2", "answer": "D*cos(alpha)"})
    assert wrong.status_code == 200, wrong.text
    body = wrong.json()
    assert body["verdict"] == "incorrect" and body["mistake"]["key"] == "position.x2.carried.1"
    assert "the wedge's x left out" in body["mistake"]["name"]
    assert "the block moves with the wedge" in body["hint"]
    # the name never hands over the answer: X is only in the reveal
    assert "X" not in body["mistake"]["name"] and body["reveal"]["difference"]["sympy"] == "-X"
    sign = client.post(url, json={"step": "position", "coordinate": "z2", "answer": "D*sin(alpha)"}).json()
    assert sign["mistake"]["key"] == "position.z2.sign" and "z is measured upward" in sign["hint"]
    right = client.post(url, json={"step": "position", "coordinate": "x2", "answer": "X + D*cos(alpha)"}).json()
    assert right["verdict"] == "correct" and right["message"] == "Correct: this is the x of the block."


def test_another_origin_is_equivalent_and_says_so(client):
    body = client.post(
        "/api/scenes/simple-pendulum/check", json={"step": "position", "coordinate": "z", "answer": "-R*cos(theta)"}
    ).json()
    assert body["verdict"] == "equivalent"
    assert body["message"] == (
        "Equivalent: your z of the bob is the correct one plus the constant −R: another origin, which changes no "
        "velocity and no equation of motion."
    )


@pytest.mark.slow
def test_a_declared_system_with_particles_has_positions_and_the_same_tutor(client):
    listed = client.post("/api/practice", json=CART_PENDULUM)
    assert listed.status_code == 200, listed.text
    assert [e["coordinate"] for e in listed.json()["exercises"] if e["step"] == "position"] == ["x2", "z2"]
    body = client.post(
        "/api/check", json={"system": CART_PENDULUM, "step": "position", "coordinate": "x2", "answer": "l*sin(phi)"}
    ).json()
    assert body["mistake"]["key"] == "position.x2.carried.1" and "the cart's x left out" in body["mistake"]["name"]


def test_a_bad_component_or_a_velocity_is_refused_with_what_is_allowed(client):
    url = "/api/scenes/movable-incline/check"
    response = client.post(url, json={"step": "position", "coordinate": "y2", "answer": "0"})
    assert response.status_code == 422, response.text
    assert response.json()["loc"] == ["body", "coordinate"]
    assert "moving position components: x2, z2" in response.json()["detail"]
    missing = client.post(url, json={"step": "position", "answer": "X"})
    assert missing.status_code == 422 and missing.json()["loc"] == ["body", "coordinate"]
    velocity = client.post(url, json={"step": "position", "coordinate": "x2", "answer": "X_dot"})
    assert velocity.status_code == 422 and "not on the velocities" in velocity.json()["detail"]
    typed = client.post(
        "/api/check",
        json={"system": {"coordinates": ["x"], "parameters": ["m", "k"], "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"},
              "step": "position", "coordinate": "x", "answer": "x"},
    )  # fmt: skip
    assert typed.status_code == 422 and "given by its energies" in typed.json()["detail"]
