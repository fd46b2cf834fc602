"""What reading a user system's text costs in one POST /api/derive of a double pendulum (docs/parsing.md).

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_parse_once

Through the app in-process (TestClient) with the real worker pool: after one derivation has started the
pool (the forkserver imports the engine), each round derives a double pendulum that no cache holds (its l2
differs every round), and the median wall time of the rounds is printed.  Then, in this process, the same
request's stages as CPU time (``time.process_time``: on a shared machine far steadier than wall time),
each with SymPy's cache cleared first, as a worker meeting a new system has it: the web process's check
(``checked``); in the worker, from the checked system to T, U and L (``user_jobs.build_system`` then
``build_mechanics``: every reading and building of the text there is) and the worker's whole job
(``user_jobs.derive_job``: derivation and document); each a median, and the first's share of the second.
Last, what carrying the read expressions to the worker costs: a pickle round trip of the checked system,
with its compact trees, with nothing read, and with the same expressions as Python ``ast`` trees instead.
"""

from __future__ import annotations

import ast
import dataclasses
import pickle
import statistics
import time

from fastapi.testclient import TestClient
from sympy.core.cache import clear_cache

from app.engine.equations.mechanics import build_mechanics
from app.main import app
from app.service.users import user_jobs
from app.service.users.user_checks import checked
from app.web.api.examples_user import DOUBLE_PENDULUM, SPINNING_HOOP
from app.web.schemas.user import SystemSpec

ROUNDS = 5


def pendulum(i: int) -> dict:
    """The example double pendulum with l2 = 1 + i/1000 m: a request no cache holds."""
    return {
        **DOUBLE_PENDULUM,
        "parameters": [{**p, "value": 1 + i / 1000} if p["name"] == "l2" else p for p in DOUBLE_PENDULUM["parameters"]],
    }


def median_seconds(call, rounds: int = ROUNDS, clock=time.perf_counter, fresh: bool = False) -> float:
    """The median time of ``call(i)`` for i in range(rounds), by ``clock``; ``fresh``: SymPy's cache cleared first."""
    times = []
    for i in range(rounds):
        if fresh:
            clear_cache()
        start = clock()
        call(i)
        times.append(clock() - start)
    return statistics.median(times)


def main() -> None:
    with open("/proc/loadavg") as f:
        print("load average:", f.read().split()[:3])
    with TestClient(app) as client:
        assert client.post("/api/derive", json=SPINNING_HOOP).status_code == 200  # starts the pool

        def post(i: int) -> None:
            response = client.post("/api/derive", json=pendulum(100 + i))
            assert response.status_code == 200, response.text

        whole = median_seconds(post)
    print(f"POST /api/derive, double pendulum, uncached, pool warm: median {whole * 1000:.0f} ms of {ROUNDS}")

    spec = SystemSpec.model_validate(pendulum(0)).to_spec()
    cpu = time.process_time
    check = median_seconds(lambda i: checked(spec), 50, cpu)
    users = [checked(SystemSpec.model_validate(pendulum(200 + i)).to_spec()) for i in range(40)]
    to_mechanics = median_seconds(lambda i: build_mechanics(user_jobs.build_system(users[i])), 40, cpu, True)
    job = median_seconds(lambda i: user_jobs.derive_job(users[i]), 5, cpu, True)
    print(f"web process, checked(): median {check * 1000:.2f} ms CPU")
    print(f"worker, build_mechanics(build_system()): median {to_mechanics * 1000:.1f} ms CPU")
    print(
        f"worker, derive_job(): median {job * 1000:.0f} ms CPU (reading and building the text: {to_mechanics / job:.1%})"
    )

    user = users[0]
    if getattr(user, "parsed", None) is None:
        return  # the code before docs/parsing.md: nothing read is carried
    bare = dataclasses.replace(user, parsed=None)
    trees = {loc: ast.parse(text.strip(), mode="eval") for loc, text, _ in user.expressions()}
    for what, value in (("compact trees", user), ("nothing read", bare), ("ast trees", (bare, trees))):
        seconds = median_seconds(lambda i, value=value: pickle.loads(pickle.dumps(value)), 2000)
        print(
            f"pickle round trip, checked system with {what}: {len(pickle.dumps(value))} bytes, {seconds * 1e6:.0f} us"
        )


if __name__ == "__main__":
    main()
