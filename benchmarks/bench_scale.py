"""Systems as large as a course needs, measured in one run.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_scale [N_MAX]   (N_MAX = 0: the simulations only)

1. The N-link planar pendulum declared as particles (as the playground and the API invite it), N = 1..N_MAX
   (8 by default): the whole document through ``POST /api/derive`` (the app in-process, its worker pool as
   served; a parameter value differs in every request, so no cache answers), the first stage (T, the
   Euler-Lagrange equations, M and f: ``accelerations_only``) in this process, and
   ``sympy.physics.mechanics.LagrangesMethod`` (``form_lagranges_equations`` + ``rhs``) on the same chain,
   each after clearing SymPy's cache.  Prints each time, the ratios to LagrangesMethod, and what the document
   left out (``skipped``).
2. A warm user simulation of the 5-link pendulum (``POST /api/simulate``, the system compiled by an earlier
   request, new initial values each time so no answer is cached) against the scene simulation of the double
   pendulum (``POST /api/scenes/double-pendulum/simulate``), best of five each.
"""

from __future__ import annotations

import os

# no background warm-up of the chapter's pages beside the measurement (its threads share the two cores)
os.environ.setdefault("LAGRANGE_WARM", "0")

import sys
import time
from concurrent.futures import ThreadPoolExecutor

import sympy as sp
import sympy.physics.mechanics as me
from fastapi.testclient import TestClient
from sympy.core.cache import clear_cache

from app.engine.derivation.derive import accelerations_only
from app.main import app
from app.service.users.user_systems import UserSystems
from app.settings import Settings
from app.web.api.deps import user_systems_service
from tests.chains import chain_request


def lagranges_method(n: int) -> float:
    """Seconds for LagrangesMethod's equations and right-hand side of the n-link chain."""
    clear_cache()
    start = time.perf_counter()
    q = me.dynamicsymbols(f"q1:{n + 1}")
    m, lengths, g = sp.symbols(f"m1:{n + 1}"), sp.symbols(f"l1:{n + 1}"), sp.Symbol("g")
    frame = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(frame, 0)
    point, particles = origin, []
    for i in range(n):
        point = point.locatenew(f"P{i}", lengths[i] * sp.sin(q[i]) * frame.x - lengths[i] * sp.cos(q[i]) * frame.y)
        point.set_vel(frame, point.pos_from(origin).dt(frame))
        particle = me.Particle(f"p{i}", point, m[i])
        particle.potential_energy = m[i] * g * point.pos_from(origin).dot(frame.y)
        particles.append(particle)
    method = me.LagrangesMethod(me.Lagrangian(frame, *particles), q)
    method.form_lagranges_equations()
    method.rhs()
    return time.perf_counter() - start


def first_stage(n: int) -> float:
    """Seconds for the engine's first stage (T, equations, M and f) on the same chain, in this process."""
    from app.engine.parser.user_system import UserSystem

    system = UserSystem.of(chain_request(n)).system()
    clear_cache()
    start = time.perf_counter()
    accelerations_only(system)
    return time.perf_counter() - start


def derive_scaling(client: TestClient, n_max: int) -> None:
    print("N-link pendulum as particles: POST /api/derive (whole document, uncached) vs LagrangesMethod")
    print(" N | document s | first stage s | LagrangesMethod s | document/LM | first/LM | skipped")
    for n in range(1, n_max + 1):
        body = chain_request(n, g=9.81 + n * 1e-6 + time.time() % 1 * 1e-9)
        start = time.perf_counter()
        response = client.post("/api/derive", json=body)
        document = time.perf_counter() - start
        lm = lagranges_method(n)
        first = first_stage(n)
        if response.status_code != 200:
            print(f"{n:2d} | refused {response.status_code} after {document:.2f} s: {response.text[:200]}")
            continue
        skipped = ", ".join(s["member"] for s in response.json().get("skipped", [])) or "-"
        print(
            f"{n:2d} | {document:10.3f} | {first:13.3f} | {lm:17.3f} | {document / lm:11.2f} | {first / lm:8.2f} | "
            f"{skipped}"
        )


def best(call, rounds: int = 5) -> float:
    times = []
    for i in range(rounds):
        start = time.perf_counter()
        call(i)
        times.append(time.perf_counter() - start)
    return min(times)


def warm_simulation(client: TestClient) -> None:
    five = chain_request(5)

    def user(i: int) -> None:
        body = {**five, "initial": {"q1": 0.5 + 0.01 * i, "q3": -0.2}, "t_end": 10.0, "samples": 200}
        response = client.post("/api/simulate", json=body)
        assert response.status_code == 200, response.text[:300]

    def scene(i: int) -> None:
        body = {"initial": {"theta1": 1.0 + 0.01 * i, "theta2": 2.0}, "t_end": 10.0, "samples": 200}
        response = client.post("/api/scenes/double-pendulum/simulate", json=body)
        assert response.status_code == 200, response.text[:300]

    # the first requests derive and compile (numba's, in the background); then both are warm
    for i in range(3):
        user(100 + i)
        scene(100 + i)
    time.sleep(5.0)
    user(200)
    five_link = best(lambda i: user(300 + i))
    double = best(lambda i: scene(300 + i))
    print(
        f"warm simulation: 5-link user system {five_link * 1e3:.1f} ms, double-pendulum scene {double * 1e3:.1f} ms, "
        f"ratio {five_link / double:.2f} (best of 5 each, 10 s, 200 samples)"
    )


SPRING = {  # the warm-up: a system that shares no expression with the chain, so no worker's memory answers for it
    "coordinates": ["x"],
    "parameters": [{"name": "m", "value": 1.0, "min": 0.01}, {"name": "k", "value": 2.0, "min": 0.01}],
    "kinetic": "m*x_dot**2/2",
    "potential": "k*x**2/2",
}


def warm_up(client: TestClient, workers: int) -> None:
    """Start every worker of the pool (imports, first simplification) with requests sent together."""
    with ThreadPoolExecutor(workers) as pool:
        for response in pool.map(lambda i: client.post("/api/derive", json=SPRING), range(workers)):
            assert response.status_code == 200, response.text[:300]


def main() -> None:
    if any(a in ("-h", "--help") for a in sys.argv[1:]):
        print(__doc__)
        return
    n_max = int(sys.argv[1]) if len(sys.argv) > 1 else 8
    with open("/proc/loadavg") as f:
        print("load average at start:", f.read().strip())
    with TestClient(app) as client:
        service = client.app_state["services"].users
        # the derive limit as served; a fresh service so that no result cache from the app's warm-up answers
        app.dependency_overrides[user_systems_service] = lambda: UserSystems(service.pool, config=Settings())
        try:
            warm_up(client, service.pool.workers)
            derive_scaling(client, n_max)
            warm_simulation(client)
        finally:
            app.dependency_overrides.pop(user_systems_service)
    with open("/proc/loadavg") as f:
        print("load average at end:", f.read().strip())


if __name__ == "__main__":
    main()
