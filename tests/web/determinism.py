"""A fixed set of requests and the means to answer them from a fresh server, idle or under load (issue 43).

Used by tests/web/test_determinism.py; runnable alone to see which bodies differ:
``PYTHONPATH=$PWD .venv/bin/python -m tests.web.determinism``.

Each server is a fresh uvicorn process with its own empty cache and data folders (``LAGRANGE_`` settings) and
no warm-up, so nothing it answers comes from an earlier run.  Load is busy-loop processes, each in its own
session: this kernel shares CPU between sessions (autogroup), so hogs inside the server's session, or in one
shared session, would not load it the way other programs on the machine do (docs/scale.md).
"""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import httpx2 as httpx

ROOT = Path(__file__).resolve().parents[2]
NUMBA_CACHE = Path(tempfile.gettempdir()) / "lagrange-determinism-numba"

# Fields that are timings by definition (their value is the clock's, not the answer's).
TIMING_FIELDS = frozenset({"wall_time_s", "compile_time_s", "elapsed", "seconds", "took"})


def chain(links: int) -> dict[str, Any]:
    """A pendulum of ``links`` equal links, each bob a particle at the end of its link."""
    x = [" + ".join(f"l*sin(q{j})" for j in range(1, i + 1)) for i in range(1, links + 1)]
    z = [" + ".join(f"l*cos(q{j})" for j in range(1, i + 1)) for i in range(1, links + 1)]
    return {
        "coordinates": [f"q{i}" for i in range(1, links + 1)],
        "parameters": ["m", "l", "g"],
        "particles": [{"mass": "m", "position": [xi, "0", f"-({zi})"]} for xi, zi in zip(x, z, strict=True)],
        "potential": " + ".join(f"-m*g*({zi})" for zi in z),
    }


SPHERICAL = {
    "coordinates": ["theta", "phi"],
    "parameters": ["m", "l", "g"],
    "kinetic": "m*l**2*(theta_dot**2 + sin(theta)**2*phi_dot**2)/2",
    "potential": "-m*g*l*cos(theta)",
}
HOOP = {
    "coordinates": ["theta"],
    "parameters": ["m", "R", "g", "w"],
    "lagrangian": "m*R**2*(theta_dot**2 + w**2*sin(theta)**2)/2 + m*g*R*cos(theta)",
}
# A triple pendulum's T with the θ̇₁θ̇₃ term doubled: the feedback compares it part by part.
TRIPLE_WRONG_T = (
    "m*l**2*(3*q1_dot**2 + 2*q2_dot**2 + q3_dot**2 + 4*q1_dot*q2_dot*cos(q1 - q2)"
    " + 4*q1_dot*q3_dot*cos(q1 - q3) + 2*q2_dot*q3_dot*cos(q2 - q3))/2"
)
# The double pendulum scene's T with its cross term's cosine wrong: feedback part by part.
DOUBLE_WRONG_T = (
    "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2"
    " + m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 + theta2)"
)
# A uniform rod pivoted at one end, typed with T and U (tests/engine/slip_corpus.py's rod-pendulum).
ROD = {
    "coordinates": ["theta"],
    "parameters": [{"name": "m", "value": 1.0, "min": 0.1, "unit": "kg"}, {"name": "l", "value": 1.0, "min": 0.1, "unit": "m"},
                   {"name": "g", "value": 9.81, "min": 0.1, "unit": "m/s²"}],
    "kinetic": "m*l**2*theta_dot**2/6",
    "potential": "-m*g*l*cos(theta)/2",
}  # fmt: skip
DOUBLE = {
    **chain(2),
    "parameters": [{"name": "m", "value": 1.0}, {"name": "l", "value": 1.0}, {"name": "g", "value": 9.81}],
}

# (name, method, path, body): the fixed set of requests, answered in this order.
REQUESTS: list[tuple[str, str, str, Any]] = [
    *[(f"derive-chain-{n}", "POST", "/api/derive", chain(n)) for n in (1, 2, 3)],
    *[(f"equations-chain-{n}", "POST", "/api/derive/equations", chain(n)) for n in (3, 4)],
    ("derive-spherical", "POST", "/api/derive", SPHERICAL),
    ("derive-hoop", "POST", "/api/derive", HOOP),
    ("check-triple-T", "POST", "/api/check", {"system": chain(3), "step": "kinetic", "answer": TRIPLE_WRONG_T}),
    ("check-hoop-omega", "POST", "/api/check",
     {"system": HOOP, "step": "omega_squared", "answer": "w**2 - g/R"}),
    ("scene-check-double-T", "POST", "/api/scenes/double-pendulum/check", {"step": "kinetic", "answer": DOUBLE_WRONG_T}),
    # the backward diagnosis (issue 41): gravity counted twice, the wedge held still, the wedge's x left out of the
    # block's position, the pulley moving as far as the masses, a rod typed with T and U taken as a point mass
    ("scene-check-pendulum-twice", "POST", "/api/scenes/simple-pendulum/check",
     {"step": "equation", "coordinate": "theta", "answer": "m*R**2*theta_ddot + 2*m*g*R*sin(theta)"}),
    ("scene-check-wedge-held", "POST", "/api/scenes/movable-incline/check",
     {"step": "acceleration", "coordinate": "D", "answer": "g*sin(alpha)"}),
    ("scene-check-wedge-position", "POST", "/api/scenes/movable-incline/check",
     {"step": "position", "coordinate": "x2", "answer": "D*cos(alpha)"}),
    ("scene-check-pulley-T", "POST", "/api/scenes/pulley/check",
     {"step": "kinetic", "answer": "m1*y1_dot**2/2 + m2*y2_dot**2/2 + M*(y1_dot + y2_dot)**2/2"}),
    ("check-rod-T", "POST", "/api/check", {"system": ROD, "step": "kinetic", "answer": "m*l**2*theta_dot**2/2"}),
    *[(f"scene-{s}", "GET", f"/api/scenes/{s}/derivation", None)
      for s in ("spherical-pendulum", "rotating-parabola", "double-pendulum")],
    ("modes-at-coupled", "POST", "/api/scenes/coupled-oscillators/modes-at", {"parameters": {"kappa": 0.37}}),
    ("modes-user-spherical", "POST", "/api/modes", SPHERICAL),
    ("simulate-user-double", "POST", "/api/simulate",
     {**DOUBLE, "initial": {"q1": 1.0, "q2": 0.5}, "t_end": 5.0, "samples": 50}),
]  # fmt: skip


def without_timings(value: Any) -> Any:
    """The body with every timing field dropped (at any depth)."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in TIMING_FIELDS}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@contextmanager
def fresh_server() -> Iterator[str]:
    """A new web process with empty cache and data folders and no warm-up, until the block ends.

    The server runs in a session of its own, as a deployed server does: the load it meets is that of other
    programs, not a share of this one's.

    Only numba's cache of compiled kernels (machine code, not answers) is shared between the servers of a run,
    so that each does not spend a minute compiling the same integrators."""
    with tempfile.TemporaryDirectory(prefix="i43-") as folder:
        port = _free_port()
        env = {**os.environ, "PYTHONPATH": str(ROOT), "LAGRANGE_WARM": "0", "LAGRANGE_WORKERS": "1",
               "LAGRANGE_CACHE_DIR": f"{folder}/cache", "LAGRANGE_DATA_DIR": f"{folder}/data",
               "LAGRANGE_STUDENT_CHECKS_PER_MINUTE": "100000", "LAGRANGE_DERIVE_SECONDS": "120",
               "LAGRANGE_SIMULATE_SECONDS": "120", "LAGRANGE_CHECK_SECONDS": "120", "LAGRANGE_QUEUE_SECONDS": "300",
               "NUMBA_CACHE_DIR": str(NUMBA_CACHE)}  # fmt: skip
        process = subprocess.Popen(
            [sys.executable, "-m", "uvicorn", "app.main:app", "--host", "127.0.0.1", "--port", str(port),
             "--log-level", "warning"], cwd=ROOT, env=env, start_new_session=True)  # fmt: skip
        url = f"http://127.0.0.1:{port}"
        try:
            deadline = time.monotonic() + 120
            while True:
                try:
                    if httpx.get(f"{url}/healthz", timeout=2).status_code == 200:
                        break
                except httpx.HTTPError:
                    pass
                if time.monotonic() > deadline or process.poll() is not None:
                    raise RuntimeError("the server did not start")
                time.sleep(0.2)
            yield url
        finally:
            process.terminate()
            try:
                process.wait(20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


@contextmanager
def busy(per_core: int) -> Iterator[None]:
    """``per_core`` busy-loop processes per core, each in its own session, until the block ends."""
    hogs = [
        subprocess.Popen([sys.executable, "-c", "while True: pass"], start_new_session=True)
        for _ in range(per_core * (os.cpu_count() or 1))
    ]
    try:
        yield
    finally:
        for hog in hogs:
            hog.kill()
        for hog in hogs:
            hog.wait()


def answers(url: str, requests: list[tuple[str, str, str, Any]] = REQUESTS) -> dict[str, tuple[int, Any]]:
    """Each request's status and body (minus timings), and the seconds each took (printed)."""
    found: dict[str, tuple[int, Any]] = {}
    with httpx.Client(base_url=url, timeout=600) as client:
        for name, method, path, body in requests:
            started = time.monotonic()
            r = client.request(method, path, json=body)
            try:
                content: Any = without_timings(r.json())
            except ValueError:
                content = r.text
            found[name] = (r.status_code, content)
            print(f"{name}: {r.status_code} in {time.monotonic() - started:.2f} s", flush=True)
    return found


def differences(a: dict[str, tuple[int, Any]], b: dict[str, tuple[int, Any]]) -> list[str]:
    """The names of the requests whose status or body differ."""
    return [name for name in a if json.dumps(a[name], sort_keys=True) != json.dumps(b.get(name), sort_keys=True)]


def three_runs(per_core: int = 4) -> tuple[dict[str, Any], dict[str, Any], dict[str, Any]]:
    """The answers of a fresh idle server; of a fresh server under load; of that server again after the load."""
    with fresh_server() as url:
        idle = answers(url)
    with fresh_server() as url:
        with busy(per_core):
            loaded = answers(url)
        after = answers(url)
    return idle, loaded, after


if __name__ == "__main__":
    idle, loaded, after = three_runs()
    print("loaded differs:", differences(idle, loaded))
    print("after the load differs:", differences(idle, after))
    out = Path(tempfile.gettempdir()) / "i43-determinism.json"
    out.write_text(json.dumps({"idle": idle, "loaded": loaded, "after": after}, indent=1, sort_keys=True))
    print("bodies in", out)
