"""A worker's check jobs: answers typed differently that build to one expression are judged once, with the
verdict each would get on its own; different answers, refusals and follow-up replies are never mixed up."""

from __future__ import annotations

import orjson
import pytest

from app.engine.tutor.answer_sides import read_answer
from app.engine.tutor.check import judge, judge_follow_up, verdict
from app.service.tutor import check_jobs
from app.service.tutor.check_jobs import check_job, pickled, verdict_job
from app.service.users.user_checks import InvalidSystem
from tests.engine.tutor.test_check_slips import step_problem

INCLINE_T = "M*X_dot**2/2 + m*D_dot**2/2"


@pytest.fixture(autouse=True)
def fresh_worker(monkeypatch):
    """A worker with nothing unpickled and no verdict remembered; the engine's judging counted."""
    monkeypatch.setattr(check_jobs, "_problems", type(check_jobs._problems)())
    monkeypatch.setattr(check_jobs, "_verdicts", type(check_jobs._verdicts)())
    calls = {"judge_of": 0, "verdict_of": 0, "follow_up_of": 0}
    for name in calls:
        real = getattr(check_jobs, name)

        def counted(*args, _real=real, _name=name):
            calls[_name] += 1
            return _real(*args)

        monkeypatch.setattr(check_jobs, name, counted)
    return calls


def job(scene: str, step: str, coordinate: str | None):
    """(the job's problem key, its pickle, the problem) as the web process sends them."""
    pb = step_problem(scene, step, coordinate)
    return f"scene-problem:{scene}:{step}:{coordinate}", pickled(pb), pb


def read(pb, text: str):
    return read_answer(text, pb.step, pb.coordinate, pb.kinds)[0]


@pytest.mark.slow
@pytest.mark.parametrize(
    "spellings",
    [
        # right: the order of the factors, and a term that is nothing
        ("m*R**2*theta_dot**2/2", "R**2*m*theta_dot**2/2", "m*R**2*theta_dot**2/2 + 0*17", "m R^2 θ'^2/2"),
        # wrong (the half left out), in three spellings
        ("m*R**2*theta_dot**2", "theta_dot**2*R**2*m", "m*R**2*theta_dot**2 + 0*4"),
    ],
)
def test_one_expression_in_many_spellings_is_judged_once_with_each_ones_own_verdict(fresh_worker, spellings):
    key, blob, pb = job("simple-pendulum", "kinetic", None)
    for text in spellings:
        found = orjson.loads(check_job(key, blob, read(pb, text)))
        assert found == judge(pb, text), text  # what the engine says of this spelling on its own
    assert fresh_worker["judge_of"] == 1


@pytest.mark.slow
def test_different_answers_are_judged_apart(fresh_worker):
    key, blob, pb = job("simple-pendulum", "kinetic", None)
    right = orjson.loads(check_job(key, blob, read(pb, "m*R**2*theta_dot**2/2")))
    wrong = orjson.loads(check_job(key, blob, read(pb, "m*R**2*theta_dot**2")))
    assert (right["verdict"], wrong["verdict"]) == ("correct", "incorrect")
    # the same text against another step's problem is that problem's verdict, judged there
    other_key, other_blob, other = job("simple-pendulum", "lagrangian", None)
    there = orjson.loads(check_job(other_key, other_blob, read(other, "m*R**2*theta_dot**2/2")))
    assert there == judge(other, "m*R**2*theta_dot**2/2") and there["verdict"] == "incorrect"
    assert fresh_worker["judge_of"] == 3


@pytest.mark.slow
def test_the_first_verdict_from_the_truth_alone_is_shared_too(fresh_worker):
    key, blob, pb = job("simple-pendulum", "potential", None)
    for text in ("m*g*R*(1 - cos(theta))", "g*m*R*(1 - cos(theta)) + 0*3", "m*g*R - m*g*R*cos(theta)"):
        found = verdict_job(key + ":truth", blob, read(pb, text))
        assert orjson.loads(found) == verdict(pb, text)
    # the first two are one expression; the third (expanded) is another
    assert fresh_worker["verdict_of"] == 2
    assert verdict_job(key + ":truth", blob, read(pb, "2*m*g*R")) == check_jobs.WRONG


def test_a_refusal_is_said_in_each_texts_own_words_and_never_remembered(fresh_worker):
    key, blob, pb = job("simple-pendulum", "kinetic", None)
    for text in ("m*R**2*theta_dot**2/2 + sqrt(-1 - R**2)", "sqrt(-1 - R**2) + m*R**2*theta_dot**2/2"):
        with pytest.raises(InvalidSystem) as refused:
            check_job(key, blob, read(pb, text))
        # the worker's reading of this very text, quoted as typed
        assert f"answer: {text} is not a real number anywhere" in str(refused.value), str(refused.value)
    assert fresh_worker["judge_of"] == 0 and not check_jobs._verdicts


@pytest.mark.slow
def test_a_follow_up_reply_is_shared_by_its_spellings_and_kept_apart_from_the_step(fresh_worker):
    key, blob, pb = job("movable-incline", "kinetic", None)
    mistake = orjson.loads(check_job(key, blob, read(pb, INCLINE_T)))["follow_up"]["key"]
    for text in ("X_dot", "X_dot + 0*2"):
        found = orjson.loads(check_job(key, blob, text, mistake))
        assert found == judge_follow_up(pb, mistake, text) and found["verdict"] == "correct"
    assert fresh_worker["follow_up_of"] == 1
    # the same expression as an answer to the step itself is judged as one
    assert orjson.loads(check_job(key, blob, read(pb, "X_dot")))["verdict"] == "incorrect"
    assert fresh_worker["judge_of"] == 2


@pytest.mark.slow
def test_a_worker_remembers_at_most_its_bound(fresh_worker, monkeypatch):
    monkeypatch.setattr(check_jobs, "MAX_WORKER_VERDICTS", 2)
    key, blob, pb = job("simple-pendulum", "kinetic", None)
    for k in range(1, 5):
        check_job(key, blob, read(pb, f"{k}*m*R**2*theta_dot**2"))
    assert len(check_jobs._verdicts) == 2
    check_job(key, blob, read(pb, "1*m*R**2*theta_dot**2"))  # forgotten: judged again
    assert fresh_worker["judge_of"] == 5
