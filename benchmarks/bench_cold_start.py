"""Cold start and restart of the server: how long until each scene's first simulation and work-precision report.

Fills an empty cache folder as set-up does (``python -m app.web.warm``: derivations,
numba's compiled kernels, work-precision reports, playground examples), then starts uvicorn (one worker) on a
free loopback port on it (a fresh clone after set-up), waits for /healthz, asks every
scene for its default simulation (one after the other, as a class opening the pages
would) and two scenes for their work-precision reports, timing each request and noting
which path answered (``stats.path``: scipy while the kernels compile, compiled after).
Then stops the server and starts it again on the same cache (a restart).

    .venv/bin/python -m benchmarks.bench_cold_start            # set-up, first start, restart
    .venv/bin/python -m benchmarks.bench_cold_start --empty    # first a start on an empty cache (set-up skipped)
    .venv/bin/python -m benchmarks.bench_cold_start --cache DIR  # restarts only, on a cache set-up filled
"""

from __future__ import annotations

import argparse
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
        raw = response.read()
        is_json = response.headers.get_content_type() == "application/json"
    return time.perf_counter() - start, json.loads(raw) if is_json else {}


def _env(cache: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(LAGRANGE_CACHE_DIR=str(cache), PYTHONPATH=str(ROOT))
    return env


def _load() -> str:
    return " ".join(f"{x:.1f}" for x in os.getloadavg())


def set_up(cache: Path) -> None:
    """What scripts/setup.sh runs after installing: fill the caches."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "app.web.warm"], cwd=ROOT, env=_env(cache), check=True)
    print(f"\nset-up's warm step (python -m app.web.warm): {time.perf_counter() - start:.1f} s")


def run_server(cache: Path, label: str) -> None:
    port = _port()
    env = _env(cache)
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
        print(f"\n### {label} (load average {_load()})\n")
        print(f"/healthz answered {ready - spawned:.2f} s after the process started\n")
        print("| request | latency s | since /healthz s | path |")
        print("|---|---|---|---|")
        for page in ("/", f"/scenes/{next(iter(SCENES))}"):
            latency, _ = _request(base + page)
            print(f"| page {page} | {latency:.2f} | {time.perf_counter() - ready:.2f} | |")
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
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--empty", action="store_true", help="first start on an empty cache (set-up skipped)")
    parser.add_argument("--cache", type=Path, help="a cache folder set-up filled: restarts only, the folder is kept")
    args = parser.parse_args()
    print(f"load average at the start: {_load()}")
    if args.cache:
        run_server(args.cache, "start on the given cache")
        run_server(args.cache, "restart")
        return
    cache = Path(tempfile.mkdtemp(prefix="lagrange-cold-"))
    try:
        if args.empty:
            run_server(cache, "empty cache (a fresh clone that skipped set-up's warm step)")
        else:
            set_up(cache)
            run_server(cache, "first start after set-up")
        run_server(cache, "restart")
    finally:
        shutil.rmtree(cache, ignore_errors=True)


if __name__ == "__main__":
    main()
