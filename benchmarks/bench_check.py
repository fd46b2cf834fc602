"""The step checker's response time on a warm server, against GET /healthz in the same run.

For every scene and every step of its practice exercises, four answers go to
POST /api/scenes/{id}/check: the engine's own step (correct), twice it
(incorrect: the difference is typeset and every mistake of the step's catalogue
is tried, the slowest path), it plus one (equivalent for U, L and h, incorrect
elsewhere) and, where the step has one, the first mistake generated from the
scene's derivation (named, with its piece typeset and what else is right). Each
answer text is made unique with a harmless ``+ 0*pi*k``, so no answer is served
from the cache: every request parses, judges and typesets in the worker pool,
as a class of students typing their own answers would make it. The realistic slips
and the correct answers in unusual forms of the tutor's corpus (tests/engine/slip_corpus.py,
the twelve scenes' entries) go with them. A warm-up round first fills the scene problems and
starts the workers. Goal: p95 at most 300 ms. The catalogues of mistakes are the ones set-up keeps on disk
(``python -m app.service.warm``; built here first where missing).

    .venv/bin/python -m benchmarks.bench_check
"""

from __future__ import annotations

import statistics
import time
from collections import defaultdict

from fastapi.testclient import TestClient

from app.main import app
from app.scenes import SCENES
from app.service.tutor.check_jobs import scene_problem
from tests.engine.slip_corpus import CORRECT, SLIPS

ROUNDS = 2
HEALTH_ROUNDS = 200


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def answers(client: TestClient, scene_id: str) -> list[tuple[dict, str]]:
    """(request without the answer's suffix, which verdict kind) for every step of a scene."""
    doc = client.get(f"/api/scenes/{scene_id}/practice").json()
    out = []
    for e in doc["exercises"]:
        base = {"step": e["step"], **({"coordinate": e["coordinate"]} if e["coordinate"] else {})}
        truth = e["answer"]["sympy"]
        out += [
            ({**base, "answer": truth}, "engine's own"),
            ({**base, "answer": f"2*({truth})"}, "twice it"),
            ({**base, "answer": f"{truth} + 1"}, "plus one"),
        ]
        named = [m for m, _, _ in scene_problem(scene_id, e["step"], e["coordinate"]).mistakes]
        if named and len(str(named[0].expr)) < 2000:
            out.append(({**base, "answer": str(named[0].expr)}, "a generated mistake"))
    for system, step, coordinate, answer, *_ in SLIPS:
        if system == scene_id:
            out.append(({"step": step, **({"coordinate": coordinate} if coordinate else {}), "answer": answer},
                        "a realistic slip"))  # fmt: skip
    for system, step, coordinate, answer in CORRECT:
        if system == scene_id:
            out.append(({"step": step, **({"coordinate": coordinate} if coordinate else {}), "answer": answer},
                        "a correct unusual form"))  # fmt: skip
    return out


def main() -> None:
    with TestClient(app) as client:
        work = {sid: answers(client, sid) for sid in SCENES}
        unique = iter(range(1, 10**9))
        for sid, items in work.items():  # warm-up: problems built, workers started and warm
            for body, _ in items:
                client.post(
                    f"/api/scenes/{sid}/check", json={**body, "answer": body["answer"] + f" + 0*pi*{next(unique)}"}
                )
        health = []
        for _ in range(HEALTH_ROUNDS):
            start = time.perf_counter()
            client.get("/healthz")
            health.append(time.perf_counter() - start)
        base = statistics.median(health)

        times: dict[str, list[float]] = defaultdict(list)
        kinds: dict[str, list[float]] = defaultdict(list)
        verdicts: dict[str, int] = defaultdict(int)
        for _ in range(ROUNDS):
            for sid, items in work.items():
                for body, kind in items:
                    request = {**body, "answer": body["answer"] + f" + 0*pi*{next(unique)}"}
                    start = time.perf_counter()
                    response = client.post(f"/api/scenes/{sid}/check", json=request)
                    elapsed = time.perf_counter() - start
                    if response.status_code == 503:  # the server said it is busy (past the check's hard limit)
                        verdicts["busy (503)"] += 1
                        continue
                    assert response.status_code == 200, (sid, request, response.text)
                    times[sid].append(elapsed)
                    kinds[kind].append(elapsed)
                    verdicts[response.json()["verdict"]] += 1

    every = [x for v in times.values() for x in v]
    print(f"{len(every)} uncached checks ({ROUNDS} rounds); baseline GET /healthz p50 = {base * 1e3:.2f} ms")
    print(f"verdicts: {dict(verdicts)}\n")
    print("| scene | checks | p50 ms | p95 ms | p50 / healthz |")
    print("|---|---|---|---|---|")
    for sid, values in times.items():
        p50 = statistics.median(values)
        print(f"| {sid} | {len(values)} | {p50 * 1e3:.0f} | {percentile(values, 0.95) * 1e3:.0f} | {p50 / base:.0f} |")
    print("\n| answer | p50 ms | p95 ms |")
    print("|---|---|---|")
    for kind, values in kinds.items():
        print(f"| {kind} | {statistics.median(values) * 1e3:.0f} | {percentile(values, 0.95) * 1e3:.0f} |")
    p95 = percentile(every, 0.95)
    print(
        f"\nall scenes: p50 {statistics.median(every) * 1e3:.0f} ms, p95 {p95 * 1e3:.0f} ms, "
        f"max {max(every) * 1e3:.0f} ms (goal: p95 <= 300 ms) -> {'met' if p95 <= 0.3 else 'NOT met'}"
    )


if __name__ == "__main__":
    main()
