"""POST /api/derive reads each expression a user typed once (issue 30): the web process reads the text into a
checked tree, the worker builds SymPy from that tree once, and nothing downstream reads the text again.

The app is the real one (TestClient, the real route, checks, service and jobs); only the worker pool is
replaced by one in this process, so that the counters see the worker's work too.  Each job's arguments and
result still cross a pickle boundary, as they do on their way to a worker process and back.
"""

import ast
import asyncio
import pickle
from collections import Counter
from concurrent.futures import ThreadPoolExecutor

import pytest
from sympy.parsing import sympy_parser

from app.engine import parse_build
from app.main import app
from app.service.fairness import Fairness
from app.service.user_checks import checked
from app.service.user_systems import UserSystems
from app.web.deps import user_systems_service
from app.web.examples_user import DOUBLE_PENDULUM
from app.web.schemas_user import SystemSpec

# a double pendulum no cache holds (a worker keeps its last derivations, and this process is the worker here)
PENDULUM = {
    **DOUBLE_PENDULUM,
    "parameters": [{**p, "value": 1.25} if p["name"] == "l2" else p for p in DOUBLE_PENDULUM["parameters"]],
}


class PicklingPool:
    """The worker pool, in this process: a job's arguments and result are pickled as for a worker process."""

    workers = 1

    def __init__(self):
        self.executor = ThreadPoolExecutor(1)
        self.jobs: list[str] = []

    def submit(self, job, *args, timeout):
        sent = pickle.dumps((job, args))
        self.jobs.append(job.__name__)

        def run():
            function, arguments = pickle.loads(sent)
            return pickle.loads(pickle.dumps(function(*arguments)))

        return self.executor.submit(run)

    async def run_async(self, future, timeout):
        return await asyncio.wrap_future(future)


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
    """Every reading of text into a tree (``ast.parse``, which the parser's gates call), every construction of
    SymPy from a checked tree (the parser's gate 3) and every reading by SymPy's own parser, by text."""
    reads: Counter[str] = Counter()
    builds: Counter[str] = Counter()
    sympy_reads: Counter[str] = Counter()
    real_parse, real_init, real_parse_expr = ast.parse, parse_build.Builder.__init__, sympy_parser.parse_expr

    def reading(source, *args, **kwargs):
        reads[source] += 1
        return real_parse(source, *args, **kwargs)

    def building(self, text, *args, **kwargs):
        builds[text] += 1
        real_init(self, text, *args, **kwargs)

    def sympy_reading(text, *args, **kwargs):
        sympy_reads[text] += 1
        return real_parse_expr(text, *args, **kwargs)

    monkeypatch.setattr(ast, "parse", reading)
    monkeypatch.setattr(parse_build.Builder, "__init__", building)
    monkeypatch.setattr(sympy_parser, "parse_expr", sympy_reading)
    return reads, builds, sympy_reads


def test_each_expression_of_a_double_pendulum_is_read_once_per_derive(client, pool, counted):
    reads, builds, sympy_reads = counted
    user = checked(SystemSpec.model_validate(PENDULUM).to_spec())
    texts = Counter(text.strip() for _, text, _ in user.expressions())
    assert len(texts) >= 6  # masses, positions and the potential (the two y = 0 are one text, given twice)
    reads.clear()

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
    from app.service.checking import Checking
    from app.web.deps import checking_service

    reads, builds, _ = counted
    body = {**PENDULUM, "parameters": [{**p, "value": 2.5} if p["name"] == "m2" else p for p in PENDULUM["parameters"]]}
    texts = Counter(text.strip() for _, text, _ in checked(SystemSpec.model_validate(body).to_spec()).expressions())
    service = app.dependency_overrides[user_systems_service]()
    app.dependency_overrides[checking_service] = lambda: Checking(service)
    try:
        reads.clear()
        answer = "-(m1+m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)"  # not written as the declaration writes it
        response = client.post("/api/check", json={"system": body, "step": "potential", "answer": answer})
    finally:
        app.dependency_overrides.pop(checking_service)
    assert response.status_code == 200, response.text
    assert response.json()["verdict"] == "correct"
    assert pool.jobs == ["system_check_job"]
    assert {text: reads[text] for text in texts} == texts
    assert {text: builds[text] for text in texts} == texts
