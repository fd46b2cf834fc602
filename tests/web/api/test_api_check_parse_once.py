"""A student's answer is read once per POST /api/scenes/{id}/check and POST /api/typeset (issue 30): the web process
reads it into a checked tree (``check_answer``, pure Python), the worker builds SymPy from that tree once.

The app is the real one (TestClient, the real route, service and jobs); only the worker pool is replaced by one in
this process (tests/web/parse_counting.py), whose jobs' arguments and results still cross a pickle boundary.
"""

import pytest

from app.main import app
from app.service.chapter import derivations
from app.service.runtime.fairness import Fairness
from app.service.tutor.checking import Checking
from app.service.users.user_systems import UserSystems
from app.web.api.deps import checking_service, user_systems_service
from tests.engine.check_corpus import CART_PENDULUM
from tests.web.parse_counting import Counted, PicklingPool

URL = "/api/scenes/double-pendulum/check"
# T without the cross term and with the lower bob's speed as if only θ₂ moved: a named mistake with a question
WRONG_T = "m1*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2"


@pytest.fixture
def pool():
    """The worker pool in this process, behind a checking service of its own (no answer cached)."""
    # the scene's derivation first: deriving it reads the scene's own texts, one of which an answer repeats
    derivations.derivation("double-pendulum")
    pool = PicklingPool()
    service = UserSystems(pool=pool, gate=Fairness(capacity=8, workers=1))
    checker = Checking(service)
    app.dependency_overrides[user_systems_service] = lambda: service
    app.dependency_overrides[checking_service] = lambda: checker
    # the steps' catalogues of mistakes built first (app/service/tutor/checking.py): an answer's check is then one job
    for key in [("potential", None), ("kinetic", None), ("equation", "theta2")]:
        checker.catalogue_build(("double-pendulum", *key)).result(timeout=600)
    pool.jobs.clear()
    yield pool
    app.dependency_overrides.pop(checking_service)
    app.dependency_overrides.pop(user_systems_service)
    pool.executor.shutdown()


@pytest.fixture
def counted(monkeypatch):
    return Counted(monkeypatch)


def once_each(counted: Counted, text: str) -> None:
    """The text read once, in the web process; built into SymPy once, in the worker; never read by SymPy."""
    assert (counted.reads[text], counted.reads_at[text, "web"]) == (1, 1), counted.reads_at
    assert (counted.builds[text], counted.builds_at[text, "worker"]) == (1, 1), counted.builds_at
    assert counted.sympy_reads[text] == 0


@pytest.mark.slow
@pytest.mark.parametrize(
    ("step", "coordinate", "answer", "verdict"),
    [
        ("potential", None, "-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)", "correct"),
        ("kinetic", None, WRONG_T, "incorrect"),
        ("equation", "theta2", "m2*l2**2*theta2_ddot + m2*g*l2*sin(theta2)", "incorrect"),
    ],
)
def test_a_scene_answer_is_read_once_and_built_once(client, pool, counted, step, coordinate, answer, verdict):
    counted.clear()
    response = client.post(URL, json={"step": step, "coordinate": coordinate, "answer": f"  {answer}\t"})
    assert response.status_code == 200, response.text
    assert response.json()["verdict"] == verdict
    assert pool.jobs == ["check_job"]
    once_each(counted, answer)  # (the gates read the text without its surrounding spaces)


@pytest.mark.slow
def test_a_follow_up_answer_on_a_scene_is_read_once_and_built_once(client, pool, counted):
    question = client.post(URL, json={"step": "kinetic", "answer": WRONG_T}).json()["follow_up"]
    assert question is not None
    counted.clear()
    answer = "l2*theta2_dot"  # a speed, but not the one asked for
    response = client.post(URL, json={"step": "kinetic", "follow_up": question["key"], "answer": answer})
    assert response.status_code == 200, response.text
    assert response.json()["verdict"] == "incorrect"
    assert pool.jobs == ["check_job", "check_job"]
    once_each(counted, answer)


def test_a_refused_answer_is_read_once_and_no_job_runs(client, pool, counted):
    counted.clear()
    response = client.post(URL, json={"step": "kinetic", "answer": "m1*l1**2*theta1_dot**2/2 + sin"})
    assert response.status_code == 422 and "sin is a function" in response.json()["detail"]
    assert pool.jobs == []
    assert counted.reads_at["m1*l1**2*theta1_dot**2/2 + sin", "web"] == 1
    assert not counted.builds


def test_a_typeset_answer_is_read_once_and_built_once(client, pool, counted):
    counted.clear()
    answer = "m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2)"
    response = client.post("/api/typeset", json={"text": answer, "scene": "double-pendulum", "step": "lagrangian"})
    assert response.status_code == 200, response.text
    assert r"\dot{\theta}_{1}" in response.json()["latex"]
    assert pool.jobs == ["typeset_job"]
    once_each(counted, answer)


@pytest.mark.slow
def test_a_follow_up_on_a_declared_system_is_read_once_in_the_worker(client, pool, counted):
    """A declared system's mistakes (and so the names a follow-up's answer may use) are known only once it is
    derived: that answer is read in the worker, once, and built there once."""
    body = {"system": CART_PENDULUM, "step": "kinetic", "answer": "M*x_dot**2/2 + m*l**2*phi_dot**2/2"}
    question = client.post("/api/check", json=body).json()["follow_up"]
    counted.clear()
    response = client.post("/api/check", json={**body, "follow_up": question["key"], "answer": "x_dot"})
    assert response.status_code == 200, response.text
    assert response.json()["verdict"] == "correct"
    assert (counted.reads["x_dot"], counted.reads_at["x_dot", "worker"]) == (1, 1)
    assert (counted.builds["x_dot"], counted.builds_at["x_dot", "worker"]) == (1, 1)
