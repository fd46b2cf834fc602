"""POST /api/typeset: answers typeset by the checker's parser, refused with the checker's own words."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.main import app
from app.service.tutor import checking
from app.web.api.deps import checking_service

CORPUS = json.loads((Path(__file__).parents[2] / "data" / "expressions.json").read_text())
SCENE = {"scene": CORPUS["scene"], "step": CORPUS["step"]}


def typeset(client, text: str, **context):
    return client.post("/api/typeset", json={"text": text, **(context or SCENE)})


@pytest.mark.slow
def test_the_corpus_is_accepted_and_refused_as_the_checker_does(client):
    for text in CORPUS["accepted"]:
        response = typeset(client, text)
        assert response.status_code == 200, (text, response.text)
        assert response.json()["latex"]
    for case in CORPUS["refused"]:
        response = typeset(client, case["text"])
        assert response.status_code == 422, (case, response.text)
        refusal = response.json()
        assert case["says"] in refusal["detail"] and refusal["loc"] == ["body", "text"], case


@pytest.mark.slow
def test_a_refusal_is_word_for_word_the_checkers(client):
    url = f"/api/scenes/{CORPUS['scene']}/check"
    for case in CORPUS["refused"]:
        typeset_says = typeset(client, case["text"]).json()
        check_says = client.post(url, json={"step": CORPUS["step"], "answer": case["text"]}).json()
        assert typeset_says["detail"] == check_says["detail"], case
        assert (typeset_says.get("start"), typeset_says.get("end")) == (check_says.get("start"), check_says.get("end"))


def test_a_declared_systems_answer_is_read_with_its_names(client):
    context = {"step": "kinetic", "coordinates": ["x"], "parameters": ["m", "k"]}
    right = typeset(client, "m*x_dot**2/2", **context)
    assert right.status_code == 200 and right.json() == {"latex": r"\frac{m \dot{x}^{2}}{2}"}
    wrong = typeset(client, "k*x_dot**2/2", **{**context, "step": "potential"}).json()
    assert wrong["detail"].startswith("answer: U depends on positions only") and wrong["part"] == "x_dot", wrong


@pytest.mark.parametrize(
    ("body", "status", "says"),
    [
        ({"text": "1", "step": "kinetic"}, 422, "give either scene, or coordinates"),
        ({"text": "1", "step": "kinetic", "scene": "simple-pendulum", "coordinates": ["x"]}, 422, "give either"),
        ({"text": "1", "step": "jerk", "scene": "simple-pendulum"}, 422, "'kinetic', 'potential'"),
        ({"text": "", "step": "kinetic", "scene": "simple-pendulum"}, 422, "at least 1 character"),
        ({"text": "1", "step": "kinetic", "scene": "nope"}, 404, "simple-pendulum"),
        ({"text": "1", "step": "acceleration", "scene": "simple-pendulum", "coordinate": "x"}, 422,
         "'x' is not a coordinate here; the coordinates are: theta"),
    ],
)
def test_a_bad_request_says_what_was_wrong(client, body, status, says):
    response = client.post("/api/typeset", json=body)
    assert response.status_code == status, response.text
    assert says in response.text


class SpyPool:
    """Stands for the user systems' pool: records the jobs, answers with LaTeX."""

    def __init__(self):
        self.submitted = []

    async def run_job(self, cache, key, *args):
        self.submitted.append(args)
        found = cache.get(key)
        if found is None:
            found = b'{"latex": "x"}'
            cache.put(key, found)
        return found


def test_hostile_text_runs_no_job_and_a_text_typeset_once_is_answered_from_the_cache(client):
    spy = SpyPool()
    service = checking.Checking(users=spy)
    app.dependency_overrides[checking_service] = lambda: service
    try:
        for text in ("__import__('os').system('x')", "(lambda: 1)()", "sin.__globals__", "exp(exp(exp(exp(3))))"):
            response = typeset(client, text)
            assert response.status_code == 422 and response.json()["part"] in text, text
        assert spy.submitted == []
        for _ in range(2):
            assert typeset(client, "m1*g").json() == {"latex": "x"}
        assert len(spy.submitted) == 2  # the spy counts calls; the route's key is the same both times
        assert service.typesetter.results.get(spy_key(service)) is not None
    finally:
        app.dependency_overrides.clear()


def spy_key(service):
    from app.service.users.user_checks import spec_key

    kinds, _absent = service.typesetter._scenes[CORPUS["scene"]]  # (names and kinds, names absent with why)
    return spec_key("typeset", CORPUS["step"], kinds, "m1*g")


def test_a_busy_server_turns_new_texts_away_as_it_does_every_job(client, services):
    known = "m1*g*l1 + m2*g*l2"
    assert typeset(client, known).status_code == 200
    gate = services.users.gate
    tickets = [gate.admit(f"other{i}", f"10.0.0.{i}") for i in range(gate.capacity)]
    try:
        busy = typeset(client, "m1*g*l1 + 3*m2*g*l2")  # a new text needs a job: the pool is full
        assert busy.status_code == 503 and int(busy.headers["Retry-After"]) >= 1
        assert typeset(client, known).status_code == 200  # typeset before: from the LRU, no job
        assert typeset(client, "1/2m1").status_code == 422  # refused in the web process (read two ways), no job
    finally:
        for ticket in tickets:
            ticket.release()


def test_an_acceleration_typed_with_another_left_side_names_the_boxs_own(client):
    # student-e, 15: the preview said "q_ddot" where the box asks for θ̈
    context = {"scene": "simple-pendulum", "step": "acceleration", "coordinate": "theta"}
    refused = typeset(client, "R*theta_ddot = -g*sin(theta)", **context)
    assert refused.status_code == 422
    assert "the left of '=' must be the acceleration θ̈ (type theta_ddot)" in refused.json()["detail"], refused.text
    assert typeset(client, "theta_ddot = -g/R*sin(theta)", **context).status_code == 200


def test_a_position_steps_component_is_not_taken_for_a_coordinate(client):
    # student-g, 1: the position box of x of the bob previewed "'x' is not a coordinate here" beside "Correct"
    for scene, component in (("simple-pendulum", "x"), ("pulley", "z3"), ("double-pendulum", "z2")):
        response = typeset(client, "R*sin(theta)" if scene == "simple-pendulum" else "1", scene=scene,
                           step="position", coordinate=component)
        assert response.status_code == 200, (scene, response.text)
        assert response.json()["latex"]


def test_a_quotient_by_one_name_before_a_spaced_factor_is_previewed_as_a_textbooks_coefficient(client):
    # issue 41, item 1: -g/R θ was refused while -g/R sin(θ) was read; the preview shows −(g/R) θ
    context = {"scene": "simple-pendulum", "step": "equation", "coordinate": "theta"}
    read = typeset(client, "θ'' = -g/R θ", **context)
    assert read.status_code == 200, read.text
    assert read.json()["latex"] == r"\ddot{\theta} = -\frac{g}{R} \theta"
    glued = typeset(client, "θ'' = -g/Rθ", **context)
    assert glued.status_code == 422 and glued.json()["readings"] == ["(-g/R) θ", "-g/(R θ)"]
