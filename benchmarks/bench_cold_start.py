"""Cold start and restart of the server: how long until each scene's first simulation and work-precision report.

Starts uvicorn (one worker) on a free loopback port with an empty cache folder
(no derivations, no numba cache, no work-precision reports), waits for
/healthz, then asks every scene for its default simulation (one after the
other, as a class opening the pages would) and two scenes for their
work-precision reports, timing each request and noting which path answered
(``stats.path``: scipy while the kernels compile, compiled after).  Then stops
the server and starts it again on the now-filled cache (a restart).

    .venv/bin/python -m benchmarks.bench_cold_start
"""

from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from pathlib import Path

from app.scenes import SCENES

ROOT = Path(__file__).resolve().parents[1]
REPORTS = ("simple-pendulum", "spherical-pendulum")
SETTLE_SECONDS = 30.0  # after every scene answers compiled: the symplectic kernels compile last


def _port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _request(url: str, body: dict | None = None, timeout: float = 120.0) -> tuple[float, dict]:
    data = None if body is None else json.dumps(body).encode()
    req = urllib.request.Request(url, data=data, headers={"Content-Type": "application/json"})
    start = time.perf_counter()
    with urllib.request.urlopen(req, timeout=timeout) as response:
        payload = json.loads(response.read())
    return time.perf_counter() - start, payload


def run_server(cache: Path, label: str) -> None:
    port = _port()
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(LAGRANGE_CACHE_DIR=str(cache), PYTHONPATH=str(ROOT))
    spawned = time.perf_counter()
    server = subprocess.Popen(
        [sys.executable, "-m", "uvicorn", "app.main:app", "--port", str(port), "--log-level", "warning"],
        cwd=ROOT,
        env=env,
    )
    base = f"http://127.0.0.1:{port}"
    try:
        while True:
            try:
                _request(f"{base}/healthz", timeout=1.0)
                break
            except OSError:
                time.sleep(0.05)
        ready = time.perf_counter()
        print(f"\n### {label}\n\n/healthz answered {ready - spawned:.2f} s after the process started\n")
        print("| request | latency s | since /healthz s | path |")
        print("|---|---|---|---|")
        for sid in SCENES:
            latency, doc = _request(f"{base}/api/scenes/{sid}/simulate", {"initial": {}})
            path = f"{doc['stats']['path']} ({doc['stats']['method']})"
            print(f"| simulate {sid} | {latency:.2f} | {time.perf_counter() - ready:.2f} | {path} |")
        for sid in REPORTS:
            start = time.perf_counter()
            try:
                latency, _ = _request(f"{base}/api/scenes/{sid}/work-precision", timeout=600.0)
                note = ""
            except urllib.error.HTTPError as exc:
                latency, note = time.perf_counter() - start, f"HTTP {exc.code}: {exc.read()[:200].decode()}"
            print(f"| work-precision {sid} | {latency:.2f} | {time.perf_counter() - ready:.2f} | {note} |")
        pending = list(SCENES)
        while pending:
            latency, doc = _request(f"{base}/api/scenes/{pending[0]}/simulate", {"initial": {}})
            if doc["stats"]["path"] == "scipy-fallback":
                time.sleep(0.5)
            else:
                pending.pop(0)
        print(f"\nevery scene answered by its compiled path {time.perf_counter() - ready:.1f} s after /healthz")
        time.sleep(SETTLE_SECONDS)
    finally:
        server.terminate()
        server.wait(timeout=30)


def main() -> None:
    cache = Path(tempfile.mkdtemp(prefix="lagrange-cold-"))
    try:
        run_server(cache, "empty cache (a fresh clone that skipped set-up's warm step)")
        run_server(cache, "restart on the cache the first run filled")
    finally:
        shutil.rmtree(cache, ignore_errors=True)


if __name__ == "__main__":
    main()
