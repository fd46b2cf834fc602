"""Warm server time of the pages, as ratios against /healthz measured in the same run.

Every page is requested through the ASGI app in process (Starlette's
TestClient), after a warm-up that fills the derivation and page-model caches.
The baseline is GET /healthz through the same client, so the ratio is the
page's own cost (template rendering) in units of the framework's fixed cost
per request.  Goal: a scene page's p50 under 20 ms.

Also compares the size of the animation data the page receives (the simulate
response: compact arrays, frames built in the browser) with the size the same
animation would have as one Plotly frame object per sample.

    .venv/bin/python -m benchmarks.bench_pages
"""

from __future__ import annotations

import json
import statistics
import time

from fastapi.testclient import TestClient

from app.main import app
from app.scenes import SCENES

ROUNDS = 200
WARMUP = 10


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def measure(client: TestClient, urls: list[str]) -> dict[str, list[float]]:
    times: dict[str, list[float]] = {u: [] for u in urls}
    for _ in range(WARMUP):
        for u in urls:
            client.get(u)
    # interleave the URLs so a slow moment of the machine hits all of them alike
    for _ in range(ROUNDS):
        for u in urls:
            start = time.perf_counter()
            response = client.get(u)
            times[u].append(time.perf_counter() - start)
            assert response.status_code in (200, 404), (u, response.status_code)
    return times


def frames_size(result: dict, scene_id: str) -> tuple[int, int]:
    """Bytes of the compact response against one Plotly frame per sample (positions of every body per frame)."""
    compact = len(json.dumps(result, separators=(",", ":")))
    n = len(result["t"])
    coordinates = list(SCENES[scene_id].system.coordinates)
    # a frame per sample would carry, for each body, its x and y and a trail of recent points
    trail = 60
    frames = [
        {
            "name": f"{result['t'][i]:.4f}",
            "data": [
                {"x": result["state"][q][max(0, i - trail) : i + 1], "y": result["state"][q][max(0, i - trail) : i + 1]}
                for q in coordinates
            ],
        }
        for i in range(n)
    ]
    return compact, len(json.dumps(frames, separators=(",", ":")))


def main() -> None:
    scenes = [f"/scenes/{sid}" for sid in SCENES]
    urls = ["/healthz", "/", *scenes, "/scenes/no-such-scene"]
    with TestClient(app) as client:
        times = measure(client, urls)
        base = statistics.median(times["/healthz"])
        print(
            f"{ROUNDS} requests per page after {WARMUP} warm-up rounds; baseline GET /healthz p50 = {base * 1e3:.2f} ms\n"
        )
        print("| page | p50 ms | p95 ms | p50 / healthz | HTML kB |")
        print("|---|---|---|---|---|")
        for u in urls[1:]:
            size = len(client.get(u).content) / 1024
            p50 = statistics.median(times[u])
            print(f"| {u} | {p50 * 1e3:.2f} | {percentile(times[u], 0.95) * 1e3:.2f} | {p50 / base:.1f} | {size:.0f} |")
        scene_p50 = [statistics.median(times[u]) for u in scenes]
        print(f"\nslowest scene page p50: {max(scene_p50) * 1e3:.2f} ms (goal < 20 ms)")

        body = {"initial": {}, "samples": 600}
        result = client.post("/api/scenes/simple-pendulum/simulate", json=body)
        if result.status_code == 200:
            compact, framed = frames_size(result.json(), "simple-pendulum")
            print(
                f"animation data, simple pendulum, 600 samples: {compact / 1024:.0f} kB as arrays "
                f"(the whole simulate response) against {framed / 1024:.0f} kB as one Plotly frame per sample "
                f"({framed / compact:.1f}x larger)"
            )


if __name__ == "__main__":
    main()
