"""The scene problems of the checker: built ahead, in the background, once each (app/service/checking.py)."""

from __future__ import annotations

import threading

from app.service import checking
from app.service.checking import Checking


def test_opening_a_scenes_steps_builds_each_problem_once_ahead_of_its_check(monkeypatch):
    built: list[tuple[str, str | None]] = []
    first = threading.Event()
    release = threading.Event()
    real = checking.problem

    def counted(d, step, coordinate):
        built.append((step, coordinate))
        if len(built) == 1:
            first.set()
            release.wait()  # the background build of the first step is under way while a check asks for it
        return real(d, step, coordinate)

    monkeypatch.setattr(checking, "problem", counted)
    checker = Checking(users=None)  # type: ignore[arg-type]  # no job is run: only the problems are built
    checker.scene_exercises("simple-pendulum")
    assert first.wait(60)
    answer: list = []
    asking = threading.Thread(target=lambda: answer.append(checker.scene_problem("simple-pendulum", "kinetic", None)))
    asking.start()
    release.set()
    asking.join(120)
    assert answer and answer[0].step == "kinetic"
    # every step is queued, in the chapter's order, and the check waited for the build under way
    for step, coordinate in [("potential", None), ("omega_squared", None), ("equation", "theta")]:
        assert checker.scene_problem("simple-pendulum", step, coordinate).step == step
    assert built[0] == ("kinetic", None) and built.count(("kinetic", None)) == 1
    assert len(built) == len(set(built))
