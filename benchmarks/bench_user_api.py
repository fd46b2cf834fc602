"""The user-system API measured in one run: refusals, derivations, simulations, recovery after a kill.

    .venv/bin/python -m benchmarks.bench_user_api

Prints how long every refusal of the hostile corpora takes, sent to the app
served by uvicorn on a loopback port (the probes of tests/web/test_hostile_corpus.py
that expect a 4xx, and tests/web/api/test_api_user_hostile.py's corpus): p50, p99
and max, with the slowest probes named.  Then, through the app in-process
(TestClient): each example system's first (uncached) and repeated (cached)
derivation, its simulation, and how long the pool takes to answer again after a
job is killed at its time limit -- each also as a ratio to a cached answer in
the same run.
"""

from __future__ import annotations

import json
import threading
import time

from fastapi.testclient import TestClient

from app.main import app
from app.service.users import user_systems
from app.settings import Settings
from app.web.api import examples_user
from app.web.api.deps import user_systems_service
from tests.web.api.test_api_user_hostile import CORPUS, _body
from tests.web.test_hostile_corpus import PROBES, lagrangian, send


def timed(call) -> tuple[float, object]:
    start = time.perf_counter()
    result = call()
    return time.perf_counter() - start, result


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


def refusals() -> None:
    """Every refusal of both corpora, timed end to end through a real server."""
    import uvicorn

    from tests.browser.conftest import _free_port

    config = uvicorn.Config(app, host="127.0.0.1", port=_free_port(), log_level="warning", lifespan="on")
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    while not server.started:
        time.sleep(0.05)
    base = f"http://127.0.0.1:{config.port}"
    json_headers = [(b"content-type", b"application/json")]
    send(base, "POST", "/api/derive", json.dumps(lagrangian("x_dot**2/2")).encode(), json_headers)  # start the pool
    requests = [
        (
            p.id,
            p.method,
            p.path,
            json.dumps(p.json).encode() if p.json is not None else p.content,
            json_headers + p.headers if p.json is not None else p.headers,
        )
        for p in PROBES
        if min(p.expect) >= 400
    ] + [(name, "POST", "/api/derive", _body(raw, "/nonexistent/canary"), json_headers) for name, raw in CORPUS]
    times = []
    for name, method, path, body, headers in requests:
        answer = send(base, method, path, body, headers)
        assert 400 <= answer.status < 500, (name, answer.status)
        times.append((answer.seconds, name))
    seconds = [t for t, _ in times]
    slowest = ", ".join(f"{name} {t * 1e3:.0f} ms" for t, name in sorted(times, reverse=True)[:3])
    print(
        f"refusals ({len(times)} probes, real server): p50 {percentile(seconds, 0.5) * 1e3:.1f} ms, "
        f"p99 {percentile(seconds, 0.99) * 1e3:.1f} ms, max {max(seconds) * 1e3:.1f} ms (slowest: {slowest})"
    )
    server.should_exit = True
    thread.join(timeout=10)


def main() -> None:
    refusals()
    with TestClient(app) as client:
        client.post("/api/derive", json=examples_user.SPINNING_HOOP)  # start the worker pool
        service = client.app_state["services"].users
        cached, _ = timed(lambda: client.post("/api/derive", json=examples_user.SPINNING_HOOP))
        print(f"cached derivation (baseline): {cached * 1e3:.2f} ms")

        print("| system | first derivation s | cached ms | simulation s |")
        print("|---|---|---|---|")
        for name, example in examples_user.SIMULATE_EXAMPLES.items():
            spec = {k: v for k, v in example["value"].items() if k not in ("initial", "t_end", "samples")}
            service.derivations = user_systems.ResultCache()
            first, _ = timed(lambda spec=spec: client.post("/api/derive", json=spec))
            again, _ = timed(lambda spec=spec: client.post("/api/derive", json=spec))
            service.simulations = user_systems.ResultCache()
            run, response = timed(lambda example=example: client.post("/api/simulate", json=example["value"]))
            assert response.status_code == 200, response.text[:200]
            print(f"| {name} | {first:.2f} | {again * 1e3:.2f} | {run:.2f} |")

        # a service of its own with a 1 s limit (no cached answer), on the app's worker pool
        short = user_systems.UserSystems(service.pool, config=Settings(derive_seconds=1.0))
        app.dependency_overrides[user_systems_service] = lambda: short
        try:
            killed, answer = timed(lambda: client.post("/api/derive", json=examples_user.DOUBLE_PENDULUM).json())
        finally:
            app.dependency_overrides.pop(user_systems_service)
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
