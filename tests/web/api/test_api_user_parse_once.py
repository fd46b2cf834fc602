"""POST /api/derive reads each expression a user typed once (issue 30): the web process reads the text into a
checked tree, the worker builds SymPy from that tree once, and nothing downstream reads the text again.

The app is the real one (TestClient, the real route, checks, service and jobs); only the worker pool is
replaced by one in this process, so that the counters see the worker's work too.  Each job's arguments and
result still cross a pickle boundary, as they do on their way to a worker process and back.
"""

from collections import Counter

import pytest

from app.main import app
from app.service.runtime.fairness import Fairness
from app.service.users.user_checks import checked
from app.service.users.user_systems import UserSystems
from app.web.api.deps import user_systems_service
from app.web.api.examples_user import DOUBLE_PENDULUM
from app.web.schemas.user import SystemSpec
from tests.web.parse_counting import Counted, PicklingPool

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

# a double pendulum no cache holds (a worker keeps its last derivations, and this process is the worker here)
PENDULUM = {
    **DOUBLE_PENDULUM,
    "parameters": [{**p, "value": 1.25} if p["name"] == "l2" else p for p in DOUBLE_PENDULUM["parameters"]],
}


@pytest.fixture
def pool():
    pool = PicklingPool()
    service = UserSystems(pool=pool, gate=Fairness(capacity=8, workers=1))
    app.dependency_overrides[user_systems_service] = lambda: service
    yield pool
    app.dependency_overrides.pop(user_systems_service)
    pool.executor.shutdown()


@pytest.fixture
def counted(monkeypatch):
    return Counted(monkeypatch)


def test_each_expression_of_a_double_pendulum_is_read_once_per_derive(client, pool, counted):
    reads, builds, sympy_reads = counted.reads, counted.builds, counted.sympy_reads
    user = checked(SystemSpec.model_validate(PENDULUM).to_spec())
    texts = Counter(text.strip() for _, text, _ in user.expressions())
    assert len(texts) >= 6  # masses, positions and the potential (the two y = 0 are one text, given twice)
    counted.clear()

    response = client.post("/api/derive", json=PENDULUM)

    assert response.status_code == 200, response.text
    assert set(response.json()["accelerations"]) == {"theta1", "theta2"}
    assert pool.jobs == ["derive_job"]
    # read into a tree once (in the web process, before any job), built into SymPy once (in the worker)
    assert {text: reads[text] for text in texts} == texts
    assert {text: builds[text] for text in texts} == texts
    assert not any(sympy_reads[text] for text in texts)


def test_checking_a_step_of_a_declared_system_reads_the_system_once(client, pool, counted):
    """POST /api/check with a declared system shares the path: each expression read once, built once."""
    from app.service.tutor.checking import Checking
    from app.web.api.deps import checking_service

    reads, builds = counted.reads, counted.builds
    body = {**PENDULUM, "parameters": [{**p, "value": 2.5} if p["name"] == "m2" else p for p in PENDULUM["parameters"]]}
    texts = Counter(text.strip() for _, text, _ in checked(SystemSpec.model_validate(body).to_spec()).expressions())
    service = app.dependency_overrides[user_systems_service]()
    app.dependency_overrides[checking_service] = lambda: Checking(service)
    try:
        counted.clear()
        answer = "-(m1+m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)"  # not written as the declaration writes it
        response = client.post("/api/check", json={"system": body, "step": "potential", "answer": answer})
    finally:
        app.dependency_overrides.pop(checking_service)
    assert response.status_code == 200, response.text
    assert response.json()["verdict"] == "correct"
    # the verdict first: the step's truth (the system derived, once), then the right answer judged against it
    assert pool.jobs == ["system_problem_job", "verdict_job"]
    assert {text: reads[text] for text in texts} == texts
    assert {text: builds[text] for text in texts} == texts
    # the answer too: read in the web process, built in the worker, once each
    assert counted.reads_at[answer, "web"] == 1 and reads[answer] == 1
    assert counted.builds_at[answer, "worker"] == 1 and builds[answer] == 1
