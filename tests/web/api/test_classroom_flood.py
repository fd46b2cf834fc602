"""A classroom behind one address keeps working while one of its machines floods (issue 34).

Against the real server (uvicorn on a loopback port, the real worker pool): twenty threads send
heavy derivations (a double pendulum, a new one each time so the cache cannot answer) from
127.0.0.1, each with a fresh session (the cookie is dropped after every request).  A student
at the same address opens the playground, then derives a harmonic oscillator (a new one each
time) every 1.5 s.  Every one of the student's requests is served, none waits more than 10 s,
and /healthz from that address answers within two seconds throughout (one probe aside).
"""

from __future__ import annotations

import threading
import time

import httpx2 as httpx
import pytest

from tests.browser.conftest import live_server  # noqa: F401  (the session's uvicorn server)

pytestmark = pytest.mark.slow

FLOODERS = 20
STUDENT_DERIVATIONS = 8
STUDENT_PERIOD = 1.5
FLOOD_LIMIT = 120.0  # seconds: a bound on the flood, whatever happens


def double_pendulum(i: int) -> dict:
    return {
        "coordinates": ["a", "b"],
        "parameters": ["m", "l", "g"],
        "particles": [
            {"mass": "m", "position": ["l*sin(a)", "-l*cos(a)"]},
            {"mass": "m", "position": ["l*sin(a)+l*sin(b)", "-l*cos(a)-l*cos(b)"]},
        ],
        "potential": f"-m*g*l*(2*cos(a)+cos(b)) + {i + 1}/100000*a**2",
    }


def oscillator(i: int) -> dict:
    return {"coordinates": ["x"], "parameters": ["k"], "kinetic": "x_dot**2/2", "potential": f"{i + 2}*k*x**2/2"}


def test_a_student_behind_a_flooding_address_is_served(live_server):  # noqa: F811
    stop = threading.Event()
    flood_statuses: list[int] = []
    counter = iter(range(10**6))
    lock = threading.Lock()

    def flood() -> None:
        with httpx.Client(base_url=live_server, timeout=60) as http:
            deadline = time.monotonic() + FLOOD_LIMIT
            while not stop.is_set() and time.monotonic() < deadline:
                with lock:
                    i = next(counter)
                try:
                    status = http.post("/api/derive", json=double_pendulum(i)).status_code
                except httpx.HTTPError:
                    status = 0
                http.cookies.clear()  # a fresh session for every request
                flood_statuses.append(status)

    health: list[float] = []

    def probe() -> None:
        with httpx.Client(base_url=live_server, timeout=30) as http:
            deadline = time.monotonic() + FLOOD_LIMIT
            while not stop.is_set() and time.monotonic() < deadline:
                started = time.monotonic()
                assert http.get("/healthz").status_code == 200
                health.append(time.monotonic() - started)
                stop.wait(0.5)

    with httpx.Client(base_url=live_server, timeout=60) as http:  # a server that has served before: its pool started
        assert http.post("/api/derive", json=oscillator(-1)).status_code == 200
    threads = [threading.Thread(target=flood, daemon=True) for _ in range(FLOODERS)]
    threads.append(threading.Thread(target=probe, daemon=True))
    for thread in threads:
        thread.start()
    student: list[tuple[int, float, str]] = []
    try:
        time.sleep(3)  # the flood is under way
        with httpx.Client(base_url=live_server, timeout=60) as http:
            page = http.get("/playground?new=1")  # the empty form: no derivation, a session
            assert page.status_code == 200 and http.cookies.get("lagrange_session")
            for i in range(STUDENT_DERIVATIONS):
                time.sleep(STUDENT_PERIOD)
                started = time.monotonic()
                answer = http.post("/api/derive", json=oscillator(i))
                student.append((answer.status_code, time.monotonic() - started, answer.text[:200]))
    finally:
        stop.set()
        for thread in threads:
            thread.join(90)
    waits = [round(w, 2) for _, w, _ in student]
    print(f"student waits {waits}; healthz max {max(health):.3f} s over {len(health)} probes; "
          f"flood: {flood_statuses.count(200)} served, {flood_statuses.count(429)} refused with 429, "
          f"{len(flood_statuses)} in all")  # fmt: skip
    assert [s for s, _, _ in student] == [200] * STUDENT_DERIVATIONS, student
    assert max(waits) <= 10.0, waits
    # the server stays responsive beside the flood: a stall of seconds fails here; the latency target itself
    # (p50 <= 100 ms, max <= 1 s) is measured by benchmarks/bench_flood.py, not asserted on a shared CI machine.
    # One probe may meet a pause of the machine itself (this process also holds the whole test session; a
    # fresh-clone rehearsal saw one of 36 probes take 3.0 s beside the other tests, where alone the slowest takes
    # 0.05-0.08 s); a server the flood holds up answers slowly probe after probe
    slow = [h for h in health if h >= 2.0]
    assert health and len(slow) <= 1 and max(health) < 5.0, health
    assert flood_statuses.count(429) > flood_statuses.count(200)  # it was a flood, and it was held to its share
