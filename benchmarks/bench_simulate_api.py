"""Warm scene simulations through the API, as ratios against GET /healthz in the same run.

Each scene's default simulation (POST /api/scenes/{id}/simulate with
``{"initial": {}}``: the scene's defaults, full precision) is requested through
the ASGI app in process (Starlette's TestClient, which accepts zstd and gzip
as Chromium does, so the answers come in zstd), interleaved with /healthz so a slow moment of the shared
machine hits both alike.  Also the same request at ``"precision": "display"``
(what the pages ask for) and the bytes on the wire.  Target: every scene's p50
at most 3x the /healthz p50.  Then the same through a real socket (uvicorn in a
process of its own, ``http.client`` with keep-alive, Chromium's Accept-Encoding)
for two scenes: there /healthz makes no thread hop, so the ratio is harsher, and
the absolute time is what a browser waits for.  Then, for the slowest scene, where one request's
time goes, in process (best of 40): the simulation with its error estimate, the
JSON encoding the route uses, and each coding at the API's level.

    .venv/bin/python -m benchmarks.bench_simulate_api
"""

from __future__ import annotations

import http.client
import json
import os
import socket
import statistics
import subprocess
import sys
import time
from pathlib import Path

from fastapi.testclient import TestClient

from app.main import app
from app.scenes import SCENES
from app.service.chapter.derivations import PROCESS_SCENES
from app.service.runtime.encoding import dumps
from app.service.simulations import simulation
from app.web.http.compression import CODINGS, compress
from app.web.schemas.simulate import SimulateRequest

ROUNDS = 60
WARMUP = 5


def main() -> None:
    print(f"load average at the start: {os.getloadavg()[0]:.2f}")
    with TestClient(app) as client:
        requests = [("GET", "/healthz", None, "")]
        for sid in SCENES:
            url = f"/api/scenes/{sid}/simulate"
            requests.append(("POST", url, {"initial": {}}, sid))
            requests.append(("POST", url, {"initial": {}, "precision": "display"}, f"{sid} (display)"))
        times: dict[str, list[float]] = {label or url: [] for _, url, _, label in requests}
        sizes: dict[str, tuple[int, int]] = {}
        codings: set[str] = set()
        for round_ in range(WARMUP + ROUNDS):
            for verb, url, body, label in requests:
                start = time.perf_counter()
                response = client.request(verb, url, json=body)
                elapsed = time.perf_counter() - start
                assert response.status_code == 200, (url, response.text[:200])
                if round_ >= WARMUP:
                    times[label or url].append(elapsed)
                if round_ == 0 and body is not None:
                    wire = int(response.headers.get("content-length", len(response.content)))
                    sizes[label] = (len(response.content), wire)
                    codings.add(response.headers.get("content-encoding", "none"))
        print(f"load average at the end: {os.getloadavg()[0]:.2f}")
        base = statistics.median(times["/healthz"])
        print(f"{ROUNDS} interleaved rounds after {WARMUP} warm-up; GET /healthz p50 = {base * 1e3:.2f} ms\n")
        print(f"content coding of the answers: {', '.join(sorted(codings))}\n")
        print("| request | p50 ms | p50 / healthz | JSON kB | on the wire kB |")
        print("|---|---|---|---|---|")
        worst = 0.0
        for _, _, _, label in requests[1:]:
            p50 = statistics.median(times[label])
            if "display" not in label:
                worst = max(worst, p50 / base)
            raw, wire = sizes[label]
            print(f"| {label} | {p50 * 1e3:.2f} | {p50 / base:.1f} | {raw / 1024:.0f} | {wire / 1024:.0f} |")
        print(f"\nslowest scene at full precision: {worst:.1f}x /healthz (target <= 3x)")
        slowest = max(SCENES, key=lambda sid: statistics.median(times[sid]))
        breakdown(slowest)
    over_a_socket(["simple-pendulum", slowest])


def best_ms(work, repeats: int = 40) -> float:
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        work()
        best = min(best, time.perf_counter() - start)
    return best * 1e3


def breakdown(scene_id: str) -> None:
    request = SimulateRequest.model_validate({"initial": {}})
    gates = simulation.Gates()  # a script's: in line, compiled first
    document = simulation.simulate_scene(scene_id, request, gates, PROCESS_SCENES)
    body = dumps(document)
    packed = {name: best_ms(lambda name=name: compress(body, name)) for name in CODINGS}
    sizes = ", ".join(f"{name} {len(compress(body, name) or body) / 1024:.0f} kB" for name in CODINGS)
    print(
        f"{scene_id} in process, best of 40: simulation with its estimate "
        f"{best_ms(lambda: simulation.simulate_scene(scene_id, request, gates, PROCESS_SCENES)):.2f} ms, "
        f"JSON encoding {best_ms(lambda: dumps(document)):.2f} ms, "
        + ", ".join(f"{name} {ms:.2f} ms" for name, ms in packed.items())
        + f" ({len(body) / 1024:.0f} kB of JSON -> {sizes})"
    )


def over_a_socket(scene_ids: list[str]) -> None:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    env = {**os.environ, "LAGRANGE_WARM": "0"}  # no background warm-up beside the measurement
    server = subprocess.Popen(
        [sys.executable, "-m", "uvicorn", "app.main:app", "--host", "127.0.0.1", "--port", str(port)],
        cwd=Path(__file__).resolve().parents[1],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        connection = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
        headers = {"content-type": "application/json", "accept-encoding": "gzip, deflate, br, zstd"}

        def request(verb: str, url: str, body: str | None) -> float:
            start = time.perf_counter()
            connection.request(verb, url, body=body, headers=headers)
            response = connection.getresponse()
            response.read()
            elapsed = time.perf_counter() - start
            assert response.status == 200, (url, response.status)
            return elapsed

        for _ in range(200):
            try:
                request("GET", "/healthz", None)
                break
            except (ConnectionError, http.client.HTTPException):
                connection.close()
                time.sleep(0.1)
        requests = [("GET", "/healthz", None, "GET /healthz")]
        for sid in scene_ids:
            url = f"/api/scenes/{sid}/simulate"
            requests.append(("POST", url, json.dumps({"initial": {}}), sid))
            requests.append(("POST", url, json.dumps({"initial": {}, "precision": "display"}), f"{sid} (display)"))
        times: dict[str, list[float]] = {label: [] for *_, label in requests}
        for round_ in range(WARMUP + ROUNDS):
            for verb, url, body, label in requests:
                elapsed = request(verb, url, body)
                if round_ >= WARMUP:
                    times[label].append(elapsed)
    finally:
        server.terminate()
        server.wait(timeout=30)
    base = statistics.median(times["GET /healthz"])
    print(f"\nover a real socket ({ROUNDS} interleaved rounds after {WARMUP} warm-up)")
    print("| request | p50 ms | p50 / healthz |")
    print("|---|---|---|")
    for label, values in times.items():
        print(f"| {label} | {statistics.median(values) * 1e3:.2f} | {statistics.median(values) / base:.1f} |")


if __name__ == "__main__":
    main()
