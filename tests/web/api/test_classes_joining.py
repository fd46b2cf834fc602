"""A lecture hall behind one network address joins in one go (issue 44, item 1).

Against the real server (uvicorn on a loopback port): sixty students, each its own HTTP client, all sending
from one loopback address that no other test uses (httpx's ``local_address``), join one class within a minute
and none is refused: those that open /join first (it hands out the browser's session) and those that send no
cookie at all (they count against their network's bound, ``class_joins_per_minute``, not against one
client's).  A single session still has its own bound.
"""

from __future__ import annotations

import itertools
import time
from concurrent.futures import ThreadPoolExecutor

import httpx2 as httpx
import pytest

from app.main import app
from app.service.classroom.service import Classroom
from app.settings import Settings
from app.web.api.classes import classroom as classroom_dep
from app.web.api.deps import ServicesDep
from tests.browser.conftest import live_server  # noqa: F401  (the session's uvicorn server)

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

STUDENTS = 60
AT_ONCE = 10
# a loopback address per test, so no other test's joins or sessions count against it
ADDRESSES = (f"127.0.44.{n}" for n in itertools.count(10))


@pytest.fixture
def classes(tmp_path):
    made: list[Classroom] = []

    async def own(running: ServicesDep) -> Classroom:
        if not made:
            made.append(Classroom(running.checking, Settings(data_dir=tmp_path)))
        return made[0]

    app.dependency_overrides[classroom_dep] = own
    yield made
    app.dependency_overrides.pop(classroom_dep, None)
    for room in made:
        room.stop()


def _client(base: str, address: str) -> httpx.Client:
    return httpx.Client(base_url=base, timeout=60, transport=httpx.HTTPTransport(local_address=address))


def _hall(base: str, address: str, code: str, page_first: bool) -> tuple[list[int], float]:
    """Sixty students from ``address`` join ``code``, ten at a time: each join's status, and the seconds it took."""

    def student(i: int) -> int:
        with _client(base, address) as http:
            if page_first:
                page = http.get(f"/join?code={code}")
                assert page.status_code == 200 and http.cookies.get("lagrange_session")
            return http.post(f"/api/classes/{code}/join", json={"name": f"student {i}"}).status_code

    started = time.monotonic()
    with ThreadPoolExecutor(AT_ONCE) as pool:
        statuses = list(pool.map(student, range(STUDENTS)))
    return statuses, time.monotonic() - started


@pytest.mark.parametrize("page_first", [True, False], ids=["from-the-page", "without-a-cookie"])
def test_sixty_students_behind_one_address_join_within_a_minute(live_server, classes, page_first):  # noqa: F811
    address = next(ADDRESSES)
    with _client(live_server, address) as teacher:
        created = teacher.post("/api/classes", json={"title": "Lecture hall"}).json()
    statuses, seconds = _hall(live_server, address, created["code"], page_first)
    assert statuses == [200] * STUDENTS, {s: statuses.count(s) for s in set(statuses)}
    assert seconds < 60
    with _client(live_server, address) as teacher:
        summary = teacher.get(f"/api/classes/{created['code']}/summary",
                              headers={"Authorization": f"Bearer {created['teacher_key']}"}).json()
    assert summary["students"] == STUDENTS


def test_one_session_keeps_its_own_bound(live_server, classes):  # noqa: F811
    address = next(ADDRESSES)
    with _client(live_server, address) as http:
        code = http.post("/api/classes", json={"title": "One browser"}).json()["code"]
        assert http.get("/join").status_code == 200 and http.cookies.get("lagrange_session")
        limit = Settings().client_joins_per_minute
        statuses = [http.post(f"/api/classes/{code}/join", json={"name": f"n{i}"}).status_code for i in range(limit + 1)]
    assert statuses[:limit] == [200] * limit
    assert statuses[limit] == 429
