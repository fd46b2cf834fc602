"""The classes across processes: two web processes sharing PostgreSQL see each other's attempts, and a
server killed with SIGKILL in the middle of a class loses no attempt it acknowledged (SQLite and PostgreSQL)."""

from __future__ import annotations

import csv
import io
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import httpx2 as httpx
import pytest

from tests.postgres import postgres_server  # noqa: F401 - the session fixture

ROOT = Path(__file__).resolve().parents[3]
SCENE = "simple-pendulum"
RIGHT_T = "m*R**2*theta_dot**2/2"
pytestmark = pytest.mark.slow


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@contextmanager
def server(env: dict[str, str], port: int | None = None) -> Iterator[tuple[str, subprocess.Popen]]:
    """One web process (uvicorn) with these settings, on ``port`` (else a free one), until the block ends (or
    the test kills it)."""
    port = port or _free_port()
    environment = {**os.environ, "PYTHONPATH": str(ROOT), "LAGRANGE_WARM": "0", "LAGRANGE_WORKERS": "1",
                   "LAGRANGE_STUDENT_CHECKS_PER_MINUTE": "100000", **env}
    process = subprocess.Popen(
        [sys.executable, "-m", "uvicorn", "app.main:app", "--host", "127.0.0.1", "--port", str(port),
         "--log-level", "warning"], cwd=ROOT, env=environment,
        start_new_session=True)  # its own group: nothing it does to "its group" reaches the tests
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 60
        while True:
            try:
                if httpx.get(f"{url}/healthz", timeout=2).status_code == 200:
                    break
            except httpx.HTTPError:
                pass
            if time.monotonic() > deadline or process.poll() is not None:
                raise RuntimeError("the server did not start")
            time.sleep(0.2)
        yield url, process
    finally:
        if process.poll() is None:
            process.terminate()
            try:
                process.wait(20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


def bearer(key: str) -> dict[str, str]:
    return {"Authorization": f"Bearer {key}"}


def _class(url: str) -> tuple[str, str]:
    created = httpx.post(f"{url}/api/classes", json={"title": "across processes"}).json()
    return created["code"], created["teacher_key"]


def _join(url: str, code: str, name: str) -> str:
    r = httpx.post(f"{url}/api/classes/{code}/join", json={"name": name})
    assert r.status_code == 200, r.text
    return r.json()["student_key"]


def _check(client: httpx.Client, url: str, code: str, key: str, answer: str) -> httpx.Response:
    return client.post(f"{url}/api/classes/{code}/check", headers=bearer(key), timeout=60,
                       json={"scene": SCENE, "step": "kinetic", "answer": answer})


def _exported(url: str, code: str, teacher: str) -> list[dict[str, str]]:
    r = httpx.get(f"{url}/api/classes/{code}/export?format=csv", headers=bearer(teacher), timeout=30)
    assert r.status_code == 200, r.text
    return list(csv.DictReader(io.StringIO(r.content.decode("utf-8-sig"))))


def test_two_web_processes_sharing_postgresql_see_each_others_attempts(postgres_server):  # noqa: F811
    env = {"LAGRANGE_DATABASE_URL": postgres_server()}
    with server(env) as (a, _), server(env) as (b, _), httpx.Client() as client:
        code, teacher = _class(a)
        ada, bo = _join(b, code, "Ada"), _join(a, code, "Bo")  # each joins through the other process
        assert _check(client, b, code, ada, RIGHT_T).json()["verdict"] == "correct"
        assert _check(client, a, code, bo, "m*R**2*theta_dot**2").json()["verdict"] == "incorrect"
        for url in (a, b):
            summary = httpx.get(f"{url}/api/classes/{code}/summary", headers=bearer(teacher)).json()
            assert (summary["students"], summary["attempts"]) == (2, 2)
            assert summary["steps"][0]["mistakes"] == {"missing_half": 1}
        assert httpx.delete(f"{b}/api/classes/{code}", headers=bearer(teacher)).status_code == 204
        assert httpx.get(f"{a}/api/classes/{code}/summary", headers=bearer(teacher)).status_code == 403


@pytest.mark.parametrize("backend", ["sqlite", "postgresql"])
def test_a_killed_server_loses_no_acknowledged_attempt(backend, request, tmp_path):
    env = {"LAGRANGE_DATA_DIR": str(tmp_path)}
    if backend == "postgresql":
        env["LAGRANGE_DATABASE_URL"] = request.getfixturevalue("postgres_server")()
    acknowledged: list[str] = []
    lock = threading.Lock()
    with server(env) as (url, process):
        code, teacher = _class(url)
        students = [_join(url, code, f"student {i}") for i in range(4)]
        with httpx.Client() as client:
            assert _check(client, url, code, students[0], RIGHT_T).status_code == 200  # the worker started

        def answer(n: int, key: str) -> None:
            with httpx.Client() as client:
                for i in range(10_000):
                    # a different text each time: judged in the worker, then recorded
                    text = f"{RIGHT_T} + {n}*{i} - {n * i}"
                    try:
                        r = _check(client, url, code, key, text)
                    except httpx.HTTPError:
                        return  # the server is gone
                    if r.status_code == 200:
                        with lock:
                            acknowledged.append(text)

        threads = [threading.Thread(target=answer, args=(n, k), daemon=True) for n, k in enumerate(students)]
        for t in threads:
            t.start()
        deadline = time.monotonic() + 60
        while len(acknowledged) < 30 and time.monotonic() < deadline:
            time.sleep(0.05)
        process.send_signal(signal.SIGKILL)  # in the middle of the class: requests in flight
        process.wait()
        for t in threads:
            t.join(30)
    assert len(acknowledged) >= 30
    with server(env) as (url, _):
        recorded = {row["answer"] for row in _exported(url, code, teacher)}
    missing = [a for a in acknowledged if a not in recorded]
    assert not missing, f"{len(missing)} of {len(acknowledged)} acknowledged attempts lost"
