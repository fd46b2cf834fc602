"""The summary is one snapshot: read back to back for as long as answers and students arrive (and at least 200
times), on SQLite and on PostgreSQL, it never fails and its figures always add up.

Writers record answers straight into the class's store (as a check does after its verdict), several at once:
right and wrong ones, named mistakes, and steps never answered before (a new coordinate each time), while new
students join.  Each summary must then agree with itself: the steps' answers total ``attempts``; a step's
students done are at most its right answers; done and stuck students of a step are at most the class; named
mistakes are at most the wrong answers; and nothing recorded disappears from one read to the next.
"""

from __future__ import annotations

import threading

import pytest

from app.main import app
from app.service.classroom import store
from app.web.api.classes import classroom as classroom_dep
from tests.classes import BACKENDS, classroom
from tests.postgres import postgres_server  # noqa: F401 - the session fixture

pytestmark = pytest.mark.slow

POLLS = 200  # at least: the reads go on until the last writer is done
WRITERS = 3
STUDENTS_EACH = 60  # each writer's students (a lecture hall in all), their answers spread over the polls
PACE = 0.1  # seconds between one writer's students
SCENE = "double-pendulum"


def _adds_up(summary: dict) -> list[str]:
    """What does not add up in one summary (nothing, for a consistent one)."""
    wrong = []
    if sum(s["correct"] + s["incorrect"] + s["not_read"] for s in summary["steps"]) != summary["attempts"]:
        wrong.append("the steps' answers do not total the attempts")
    for s in summary["steps"]:
        if s["students_done"] > s["correct"]:
            wrong.append(f"{s['step']} {s['coordinate']}: more students done than right answers")
        if s["students_done"] + s["stuck"] > summary["students"]:
            wrong.append(f"{s['step']} {s['coordinate']}: more students done or stuck than in the class")
        if sum(s["mistakes"].values()) > s["incorrect"]:
            wrong.append(f"{s['step']} {s['coordinate']}: more named mistakes than wrong answers")
    if sum(m["count"] for m in summary["mistakes"]) != sum(sum(s["mistakes"].values()) for s in summary["steps"]):
        wrong.append("the totalled mistakes do not match the steps'")
    return wrong


@pytest.mark.parametrize("backend", BACKENDS)
def test_the_summary_adds_up_while_answers_arrive(client, services, tmp_path, request, backend):
    postgres = request.getfixturevalue("postgres_server") if backend == "postgresql" else None
    room = classroom(services.checking, backend, tmp_path, postgres)
    app.dependency_overrides[classroom_dep] = lambda: room
    stop = threading.Event()
    failures: list[BaseException] = []
    try:
        code, teacher, _recovery = store.create_class(room.db, "Snapshots")
        headers = {"Authorization": f"Bearer {teacher}"}

        def write(w: int) -> None:
            try:
                for n in range(STUDENTS_EACH):
                    if stop.wait(PACE):
                        return
                    _, who, _code = store.join(room.db, code, f"writer {w} student {n}")
                    new_step = f"q{w}_{n}"  # a step no one answered before
                    store.record(room.db, who, SCENE, "equation", new_step, "correct", None, "0")
                    store.record(room.db, who, SCENE, "kinetic", None, "incorrect", "missing_half", "T", "the ½ left out")
                    store.record(room.db, who, SCENE, "kinetic", None, "correct", None, "T")
                    store.record(room.db, who, SCENE, "potential", None, "incorrect", "sign", "U", "the sign of U")
            except BaseException as exc:  # noqa: BLE001 - reported by the test
                failures.append(exc)

        writers = [threading.Thread(target=write, args=(w,), daemon=True) for w in range(WRITERS)]
        for thread in writers:
            thread.start()
        statuses: dict[int, int] = {}
        broken: list[tuple[int, list[str]]] = []
        last = (0, 0)
        states: set[tuple[int, int]] = set()
        i = 0
        # every read while the writers write (a read after they stop sees one state, and checks nothing more)
        while i < POLLS or any(thread.is_alive() for thread in writers):
            i += 1
            r = client.get(f"/api/classes/{code}/summary", headers=headers)
            statuses[r.status_code] = statuses.get(r.status_code, 0) + 1
            if r.status_code != 200:
                continue
            summary = r.json()
            if problems := _adds_up(summary):
                broken.append((i, problems))
            seen = (summary["students"], summary["attempts"])
            if seen < last:
                broken.append((i, [f"went back from {last} to {seen}"]))
            last = max(last, seen)
            states.add(seen)
        stop.set()
        for thread in writers:
            thread.join(30)
        assert not failures, failures
        assert statuses == {200: i} and i >= POLLS, statuses
        assert not broken, broken[:5]
        assert len(states) > 50  # the answers did arrive during the polls: the summaries saw many states
        final = client.get(f"/api/classes/{code}/summary", headers=headers).json()
        assert not _adds_up(final)
        assert final["mistakes"][0]["count"] == final["students"]  # each student's one mistake of each kind, totalled
    finally:
        stop.set()
        app.dependency_overrides.pop(classroom_dep, None)
        room.stop()
