"""A lecture behind a real load balancer: two replicas behind Debian's nginx (round robin, no affinity),
sharing PostgreSQL for the classes and Redis for the rate windows.

Sixty students join from one address within a minute and answer; one replica is killed mid-class and
started again; every acknowledged attempt is in the record exactly once, and both replicas report the same
summary; a session cookie made by one replica is honoured by the other; a student who floods is limited
once, not once per replica.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import tempfile
import threading
import time
import uuid
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import ExitStack, contextmanager

import httpx2 as httpx
import pytest

from tests.postgres import postgres_server  # noqa: F401 - the session fixture
from tests.redis import redis_server  # noqa: F401 - the session fixture
from tests.web.api.test_classes_processes import RIGHT_T, ROOT, SCENE, _exported, _free_port, bearer, server

pytestmark = pytest.mark.slow
STUDENTS = 60
WRONG_T = "m*R**2*theta_dot**2"
FLOOD_LIMIT = 6  # one student's checks per minute in this test


@contextmanager
def balancer(upstreams: list[str]) -> Iterator[str]:
    """Debian's nginx in front of ``upstreams``, configured as deploy/compose/nginx.conf (round robin; a POST
    that cannot reach a replica goes to the next one, safe because a check carries its attempt id)."""
    nginx = shutil.which("nginx") or "/usr/sbin/nginx"
    if not os.path.exists(nginx):
        if os.environ.get("CI"):
            pytest.fail("nginx is not installed (scripts/test.sh installs Debian's nginx)")
        pytest.skip("nginx is not installed: apt-get install -y nginx (scripts/test.sh does)")
    root = tempfile.mkdtemp(prefix="lagrange-nginx-")
    os.chmod(root, 0o755)
    port = _free_port()
    # the shipped configuration (deploy/compose/nginx.conf), with this test's replicas and port
    shipped = (ROOT / "deploy" / "compose" / "nginx.conf").read_text()
    servers = "\n".join(f"server {u.removeprefix('http://')} max_fails=0;" for u in upstreams)
    site = re.sub(r"(upstream lagrange \{)[^}]*\}", lambda m: f"{m.group(1)}\n{servers}\n}}", shipped)
    site = site.replace("listen 80;", f"listen 127.0.0.1:{port};")
    assert site.count("max_fails=0;") == len(upstreams) and f"127.0.0.1:{port}" in site
    user = "user root;" if os.geteuid() == 0 else ""
    conf = f"""
{user}
worker_processes 1;
pid {root}/nginx.pid;
error_log {root}/error.log warn;
events {{ worker_connections 512; }}
http {{
  access_log off;
  client_body_temp_path {root}/body;
  proxy_temp_path {root}/proxy;
  {site}
}}
"""
    with open(f"{root}/nginx.conf", "w") as f:
        f.write(conf)
    process = subprocess.Popen([nginx, "-p", root, "-c", f"{root}/nginx.conf", "-g", "daemon off;"])
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 20
        while True:
            try:
                httpx.get(f"{url}/healthz", timeout=2)
                break
            except httpx.HTTPError:
                if time.monotonic() > deadline or process.poll() is not None:
                    raise RuntimeError("nginx did not start") from None
                time.sleep(0.1)
        yield url
    finally:
        process.terminate()
        process.wait(10)
        shutil.rmtree(root, ignore_errors=True)


def test_a_lecture_behind_a_balancer_on_two_replicas(request, tmp_path):
    env = {
        "LAGRANGE_DATABASE_URL": request.getfixturevalue("postgres_server")(),
        "LAGRANGE_SHARED_STORE_URL": request.getfixturevalue("redis_server"),
        "LAGRANGE_SESSION_SECRET": uuid.uuid4().hex,
        "LAGRANGE_REPLICAS": "2",
        "LAGRANGE_PROXY_HEADER": "X-Forwarded-For",
        "LAGRANGE_STUDENT_CHECKS_PER_MINUTE": str(FLOOD_LIMIT),
    }
    with ExitStack() as stack:
        replicas = [stack.enter_context(server({**env, "LAGRANGE_DATA_DIR": str(tmp_path / str(i))})) for i in range(2)]
        (a, _), (b, process_b) = replicas
        lb = stack.enter_context(balancer([a, b]))
        made = httpx.post(f"{lb}/api/classes", json={"title": "a lecture"}).json()
        code, teacher = made["code"], made["teacher_key"]

        # sixty students from one address (the balancer's), each joining once, ten at a time
        started = time.monotonic()

        def join(i: int) -> str:
            r = httpx.post(f"{lb}/api/classes/{code}/join", json={"name": f"student {i:02d}"}, timeout=60)
            assert r.status_code == 200, r.text
            return r.json()["student_key"]

        with ThreadPoolExecutor(10) as pool:
            keys = list(pool.map(join, range(STUDENTS)))
        took = time.monotonic() - started
        assert took < 60, f"sixty joins took {took:.1f} s"

        acknowledged: dict[str, str] = {}  # attempt id -> verdict
        lock = threading.Lock()

        def answer(i: int) -> None:
            key = keys[i]
            for n, text in enumerate((WRONG_T, RIGHT_T)):
                attempt = f"s{i:02d}a{n}{uuid.uuid4().hex[:8]}"
                body = {"scene": SCENE, "step": "kinetic", "answer": text, "attempt": attempt}
                for _ in range(5):  # a press retried with its id, as the page does, until acknowledged
                    try:
                        r = httpx.post(f"{lb}/api/classes/{code}/check", json=body, headers=bearer(key), timeout=60)
                    except httpx.HTTPError:
                        continue
                    if r.status_code == 200:
                        with lock:
                            acknowledged[attempt] = r.json()["verdict"]
                        break
                    assert r.status_code in (502, 503), r.text

        with ThreadPoolExecutor(10) as pool:
            first_half = [pool.submit(answer, i) for i in range(STUDENTS // 2)]
            time.sleep(1.0)
            process_b.send_signal(signal.SIGKILL)  # a replica dies mid-class; the balancer sends on to the other
            rest = [pool.submit(answer, i) for i in range(STUDENTS // 2, STUDENTS)]
            for f in (*first_half, *rest):
                f.result()
        process_b.wait()
        assert len(acknowledged) == 2 * STUDENTS  # every press acknowledged, through the surviving replica

        # the replica started again on its old port serves the same class
        b_env = {**env, "LAGRANGE_DATA_DIR": str(tmp_path / "1b")}
        b_again, _ = stack.enter_context(server(b_env, port=int(b.rsplit(":", 1)[1])))
        summaries = [
            httpx.get(f"{url}/api/classes/{code}/summary", headers=bearer(teacher), timeout=30).json()
            for url in (a, b_again, lb, lb)
        ]
        assert all(s == summaries[0] for s in summaries)
        assert summaries[0]["students"] == STUDENTS and summaries[0]["attempts"] == 2 * STUDENTS
        rows = _exported(lb, code, teacher)
        assert len(rows) == 2 * STUDENTS  # each acknowledged attempt recorded exactly once

        # a session cookie made by one replica is honoured by the other: no new cookie comes back
        practice = {"step": "kinetic", "answer": RIGHT_T}
        made = httpx.post(f"{a}/api/scenes/{SCENE}/check", json=practice, timeout=60)
        cookie = made.cookies.get("lagrange_session")
        assert cookie
        honoured = httpx.post(f"{b_again}/api/scenes/{SCENE}/check", json=practice, timeout=60,
                              cookies={"lagrange_session": cookie})
        assert honoured.status_code == 200 and "lagrange_session" not in honoured.cookies

        # a student flooding through the balancer is limited once: FLOOD_LIMIT checks a minute in all,
        # not FLOOD_LIMIT per replica (the windows are counted in the shared Redis)
        flooder = httpx.post(f"{lb}/api/classes/{code}/join", json={"name": "flooder"}).json()["student_key"]
        statuses = [
            httpx.post(f"{lb}/api/classes/{code}/check", headers=bearer(flooder), timeout=60,
                       json={"scene": SCENE, "step": "kinetic", "answer": WRONG_T}).status_code
            for _ in range(2 * FLOOD_LIMIT)
        ]
        assert statuses == [200] * FLOOD_LIMIT + [429] * FLOOD_LIMIT
