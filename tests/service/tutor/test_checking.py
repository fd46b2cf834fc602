"""The checker's problems (app/service/tutor/checking.py): the verdict first, from the truth alone; each scene step's
catalogue of mistakes built once, in the worker pool, ahead of its checks; a check that cannot finish in its
limit says the server is busy, and nothing of it is cached."""

from __future__ import annotations

import asyncio
import json
import threading
from concurrent.futures import ThreadPoolExecutor

import pytest

from app.errors import OverCapacity
from app.service.runtime.fairness import Fairness
from app.service.tutor import check_jobs
from app.service.tutor.checking import BUSY, Checking
from app.service.users.user_systems import UserSystems
from app.settings import Settings
from tests.web.parse_counting import WORKER, PicklingPool

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

RIGHT_T = "m*R**2*theta_dot**2/2"
WRONG_T = "m*R**2*theta_dot**2"  # the ½ of ½ m v² left out: a named mistake


class HeldPool(PicklingPool):
    """The pool in this process, two workers."""

    workers = 2

    def __init__(self):
        super().__init__()
        self.executor.shutdown()
        self.executor = ThreadPoolExecutor(2, thread_name_prefix=WORKER)


@pytest.fixture
def release(monkeypatch, tmp_path):
    """Set it to let the catalogues' builds go on (each waits for it), on a disk of this test's own."""
    # no catalogue from an earlier run's disk: each is built here
    monkeypatch.setattr(check_jobs, "catalogue_path", lambda *key: tmp_path / "-".join(map(str, key)))
    event = threading.Event()
    real = check_jobs.scene_problem

    def held(scene_id, step, coordinate, catalogue=True):
        if catalogue:
            event.wait()
        return real(scene_id, step, coordinate, catalogue)

    monkeypatch.setattr(check_jobs, "scene_problem", held)
    yield event
    event.set()


@pytest.fixture
def pool(release):
    pool = HeldPool()
    yield pool
    release.set()
    pool.executor.shutdown()


def checker_of(pool: PicklingPool, seconds: float = 10.0) -> Checking:
    users = UserSystems(pool=pool, gate=Fairness(capacity=8, workers=pool.workers))  # type: ignore[arg-type]
    return Checking(users, Settings(check_seconds=seconds, derive_seconds=seconds))


def check(checker: Checking, answer: str) -> dict:
    body = asyncio.run(checker.check_scene("simple-pendulum", "kinetic", None, answer, "student", "127.0.0.1"))
    return json.loads(body)


def test_a_right_answer_is_judged_before_its_catalogue_is_built(pool, release):
    checker = checker_of(pool, seconds=0.5)
    # the catalogue's build is held: the right answer needs only the truth
    assert check(checker, RIGHT_T)["verdict"] == "correct"
    # a wrong answer's diagnosis needs the catalogue: past the check's limit the server is busy, and says what to do
    with pytest.raises(OverCapacity) as refused:
        check(checker, WRONG_T)
    assert str(refused.value) == BUSY and "press Check again" in BUSY
    # nothing of that check was kept: once the catalogue is built, the same answer gets its diagnosis
    release.set()
    checker.catalogue_build(("simple-pendulum", "kinetic", None)).result(timeout=120)
    judged = check(checker, WRONG_T)
    assert judged["verdict"] == "incorrect" and judged["mistake"]["key"] == "missing_half"
    assert pool.jobs.count("scene_problem_job") == 1


def test_opening_a_scenes_steps_builds_each_catalogue_once_in_the_pool(pool, release):
    checker = checker_of(pool)
    steps = [(e["step"], e["coordinate"]) for e in json.loads(checker.scene_exercises("simple-pendulum"))["exercises"]]
    release.set()
    for step, coordinate in steps:
        checker.catalogue_build(("simple-pendulum", step, coordinate)).result(timeout=120)
    # each step's catalogue built once, in the pool, and a check then finds it ready: one job, the answer's
    assert pool.jobs == ["scene_problem_job"] * len(steps)
    assert check(checker, WRONG_T)["mistake"]["key"] == "missing_half"
    assert pool.jobs[len(steps) :] == ["check_job"]
    # a second server (a restart) loads every catalogue from the disk: no build in its pool
    again = HeldPool()
    try:
        fresh = checker_of(again)
        fresh.scene_exercises("simple-pendulum")
        for step, coordinate in steps:
            fresh.catalogue_build(("simple-pendulum", step, coordinate)).result(timeout=120)
        assert again.jobs == []
    finally:
        again.executor.shutdown()
