"""The tutor through the API: a named mistake, what else is right, and its follow-up question answered."""

from __future__ import annotations

import pytest

from tests.engine.check_corpus import CART_PENDULUM


@pytest.mark.slow
def test_a_scene_mistake_is_named_and_its_follow_up_is_checked(client):
    url = "/api/scenes/spherical-pendulum/check"
    wrong = client.post(url, json={"step": "kinetic", "answer": "m*R**2*theta_dot**2/2"})
    assert wrong.status_code == 200, wrong.text
    body = wrong.json()
    assert body["mistake"]["key"] == "kinetic.velocity_part.ball.phi"
    # the slip is named in words; the missing piece itself waits under "Show this step" (reveal)
    assert "φ̇" in body["mistake"]["name"] and body["mistake"]["latex"] == ""
    assert r"\dot{\varphi}" in body["reveal"]["piece"]
    # one typed term: "everything else is right" would say nothing
    assert body["partial"] is None
    question = body["follow_up"]
    assert question["key"] == body["mistake"]["key"] and "speed" in question["question"]
    # the follow-up, answered wrongly then rightly (either sign of a speed is its size)
    again = {"step": "kinetic", "follow_up": question["key"]}
    no = client.post(url, json={**again, "answer": "R*phi_dot"}).json()
    assert no["verdict"] == "incorrect" and no["follow_up"]["key"] == question["key"]
    yes = client.post(url, json={**again, "answer": "-R*sin(theta)*phi_dot"}).json()
    assert yes["verdict"] == "correct", yes
    right = client.post(url, json={"step": "kinetic", "answer": "m*R**2*(theta_dot**2 + sin(theta)**2*phi_dot**2)/2"})
    assert right.json()["verdict"] == "correct"


def test_an_unknown_follow_up_is_refused_naming_the_field(client):
    response = client.post(
        "/api/scenes/simple-pendulum/check", json={"step": "kinetic", "follow_up": "nonsense", "answer": "1"}
    )
    assert response.status_code == 422
    assert response.json()["loc"] == ["body", "follow_up"] and "nonsense" in response.json()["detail"]


@pytest.mark.slow
def test_a_declared_system_gets_the_same_tutor(client):
    wrong = client.post(
        "/api/check",
        json={"system": CART_PENDULUM, "step": "kinetic", "answer": "M*x_dot**2/2 + m*l**2*phi_dot**2/2"},
    )
    assert wrong.status_code == 200, wrong.text
    body = wrong.json()
    assert body["mistake"]["key"] == "kinetic.velocity_part.bob.x" and body["follow_up"]
    answer = client.post(
        "/api/check",
        json={"system": CART_PENDULUM, "step": "kinetic", "follow_up": body["follow_up"]["key"], "answer": "x_dot"},
    )
    assert answer.status_code == 200, answer.text
    assert answer.json()["verdict"] == "correct"


@pytest.mark.slow
def test_an_unmatched_answer_says_which_parts_agree(client):
    body = client.post(
        "/api/scenes/spherical-pendulum/check",
        json={"step": "kinetic", "answer": "m*R**2*theta_dot**2/2 + 5*m*R**2*cos(theta)*phi_dot**2"},
    ).json()
    assert body["mistake"] is None
    assert body["partial"]["agree"] == ["the θ̇² terms"] and body["partial"]["differ"] == ["the φ̇² terms"]
