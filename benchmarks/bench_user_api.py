"""The user-system API measured in one run: refusals, derivations, simulations, recovery after a kill.

    .venv/bin/python -m benchmarks.bench_user_api

Prints, through the app in-process (TestClient): how long the hostile corpus of
tests/web/test_api_user_hostile.py takes to be refused (median and worst), each
example system's first (uncached) and repeated (cached) derivation, its
simulation, and how long the pool takes to answer again after a job is killed
at its time limit -- each also as a ratio to a cached answer in the same run.
"""

from __future__ import annotations

import statistics
import time

from fastapi.testclient import TestClient

from app.main import app
from app.service import user_systems
from app.web import examples_user
from tests.web.test_api_user_hostile import CORPUS, _body


def timed(call) -> tuple[float, object]:
    start = time.perf_counter()
    result = call()
    return time.perf_counter() - start, result


def main() -> None:
    with TestClient(app) as client:
        client.post("/api/derive", json=examples_user.SPINNING_HOOP)  # start the worker pool
        cached, _ = timed(lambda: client.post("/api/derive", json=examples_user.SPINNING_HOOP))
        print(f"cached derivation (baseline): {cached * 1e3:.2f} ms")

        times = []
        for _, raw in CORPUS:
            client.cookies.clear()
            seconds, response = timed(
                lambda raw=raw: client.post(
                    "/api/derive",
                    content=_body(raw, "/nonexistent/canary"),
                    headers={"content-type": "application/json"},
                )
            )
            assert 400 <= response.status_code < 500
            times.append(seconds)
        print(
            f"hostile corpus ({len(times)} inputs): median {statistics.median(times) * 1e3:.1f} ms "
            f"({statistics.median(times) / cached:.1f}x cached), worst {max(times) * 1e3:.1f} ms "
            f"({max(times) / cached:.1f}x cached)"
        )

        print("| system | first derivation s | cached ms | simulation s |")
        print("|---|---|---|---|")
        for name, example in examples_user.SIMULATE_EXAMPLES.items():
            spec = {k: v for k, v in example["value"].items() if k not in ("initial", "t_end", "samples")}
            user_systems.service.derivations = user_systems.ResultCache()
            first, _ = timed(lambda spec=spec: client.post("/api/derive", json=spec))
            again, _ = timed(lambda spec=spec: client.post("/api/derive", json=spec))
            user_systems.service.simulations = user_systems.ResultCache()
            run, response = timed(lambda example=example: client.post("/api/simulate", json=example["value"]))
            assert response.status_code == 200, response.text[:200]
            print(f"| {name} | {first:.2f} | {again * 1e3:.2f} | {run:.2f} |")

        killed, answer = timed(lambda: examples_user.answer_with_time_limit(client, 1.0))
        assert answer["kind"] == "timeout"
        after, response = timed(
            lambda: client.post("/api/derive", json={"coordinates": ["q"], "lagrangian": "q_dot**2"})
        )
        assert response.status_code == 200
        print(
            f"job killed at a 1 s limit answered in {killed:.2f} s; the next (uncached) derivation took "
            f"{after * 1e3:.0f} ms ({after / cached:.0f}x cached)"
        )


if __name__ == "__main__":
    main()
