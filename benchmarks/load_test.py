"""Classroom load test on loopback: students, a few hostile clients, and a soak.

Starts the app with uvicorn (``--workers``, as in the image) on a free loopback
port, then runs bounded asyncio clients:

* a student arrives within the first ``--ramp`` seconds and opens a scene page and
  its assets (once, gzip accepted, as a browser caches them),
  reads the derivation and the work-precision report, then every few seconds
  changes a parameter and re-simulates; now and then derives a system of their own;
* a hostile client (``--hostile N``) sends expensive jobs back to back: a
  simulation at the limits and a derivation built to hit the worker's time limit;
* a hostile flood (``--flood N``): N sessions from this one address (a
  classroom's NAT) send derivations built to hit the time limit back to back,
  and 4N clients send heavy scene simulations back to back, while an honest
  session derives a new small system every few seconds (retrying after
  ``Retry-After``: its wait is timed until the answer) and a probe asks
  /healthz five times a second.  The probe runs in a process of its own, as a
  kubelet's does ("healthz (own process)"); the same probe inside this client's
  event loop ("healthz (in the load's loop)") also counts the delays of the sixty
  clients sharing that loop, so it reads higher than the server's own latency.

Every run is bounded in time (``--seconds``) and requests; it prints, per level,
throughput, p50/p99 per endpoint, the error rate (5xx counted apart) and the
server's memory (RSS of all its processes).  ``--soak`` samples memory over a
long run and reports its growth after warm-up.

    .venv/bin/python -m benchmarks.load_test --students 30 100 150 --seconds 60
    .venv/bin/python -m benchmarks.load_test --students 100 --hostile 4 --seconds 60
    .venv/bin/python -m benchmarks.load_test --students 100 --soak --seconds 600
    .venv/bin/python -m benchmarks.load_test --students 10 --flood 10 --seconds 60 --settle 20
"""

from __future__ import annotations

import argparse
import asyncio
import multiprocessing
import os
import random
import signal
import socket
import statistics
import subprocess
import sys
import time
from collections import defaultdict
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import httpx2 as httpx

ROOT = Path(__file__).resolve().parents[1]
ASSETS = (
    "/static/vendor/katex/katex.min.css",
    "/static/vendor/katex/katex.min.js",
    "/static/vendor/katex/contrib/auto-render.min.js",
    "/static/vendor/plotly/plotly.min.js",
)
CUSTOM_SYSTEM = {
    "coordinates": ["x"],
    "parameters": [{"name": "k", "value": 1.0}, {"name": "m", "value": 1.0}],
    "kinetic": "m*x_dot**2/2",
    "potential": "k*x**2/2 + x**4/4",
}
# A derivation that is legal but too much work: the worker's time limit ends it.
HOSTILE_SYSTEM = {
    "coordinates": ["a", "b", "c", "d"],
    "parameters": ["k"],
    "lagrangian": (
        "(a_dot + b_dot*cos(a - b) + c_dot*cos(a - c) + d_dot*cos(a - d))**2 + "
        "(b_dot + c_dot*cos(b - c) + d_dot*cos(b - d))**2 + (c_dot + d_dot*cos(c - d))**2 + "
        "a_dot**2 + b_dot**2 + c_dot**2 + d_dot**2 - k*cos(a)*cos(b)*cos(c)*cos(d)"
    ),
}


class Recorder:
    def __init__(self) -> None:
        self.times: dict[str, list[float]] = defaultdict(list)
        self.status: dict[str, dict[int, int]] = defaultdict(lambda: defaultdict(int))
        self.slowest_probes: list[tuple[float, float, int]] = []

    async def call(self, client: httpx.AsyncClient, name: str, method: str, url: str, **kw) -> httpx.Response | None:
        start = time.perf_counter()
        try:
            response = await client.request(method, url, **kw)
            code = response.status_code
        except httpx.HTTPError:
            response, code = None, 599
        self.times[name].append(time.perf_counter() - start)
        self.status[name][code] += 1
        return response


async def student(base: str, scenes: list[dict], rec: Recorder, stop: float, rng: random.Random, ramp: float) -> None:
    scene = rng.choice(scenes)
    sid = scene["id"]
    # students open the page over the first `ramp` seconds, not all in one millisecond
    await asyncio.sleep(rng.uniform(0.0, ramp))
    async with httpx.AsyncClient(base_url=base, timeout=30) as c:
        await rec.call(c, "page", "GET", f"/scenes/{sid}")
        for asset in ASSETS:
            await rec.call(c, "asset", "GET", asset)
        await rec.call(c, "derivation", "GET", f"/api/scenes/{sid}/derivation")
        await rec.call(c, "work-precision", "GET", f"/api/scenes/{sid}/work-precision")
        while time.monotonic() < stop:
            await asyncio.sleep(rng.uniform(2.0, 5.0))
            if time.monotonic() >= stop:
                break
            if rng.random() < 0.03:
                await rec.call(c, "derive (custom)", "POST", "/api/derive", json=CUSTOM_SYSTEM)
                continue
            params = {}
            for name, info in scene["parameters"].items():
                low = info["min"] if info["min"] is not None else info["default"] * 0.5
                high = info["max"] if info["max"] is not None else info["default"] * 2
                params[name] = min(high, max(low, info["default"] * rng.uniform(0.8, 1.2)))
            body = {"parameters": params, "initial": scene["initial"], "t_end": scene["t_end"], "samples": 400}
            await rec.call(c, "simulate", "POST", f"/api/scenes/{sid}/simulate", json=body)


async def hostile(base: str, scenes: list[dict], rec: Recorder, stop: float) -> None:
    scene = scenes[0]
    heavy = {"initial": scene["initial"], "t_end": 1e4, "samples": 5000, "rtol": 1e-12, "method": "Radau"}
    async with httpx.AsyncClient(base_url=base, timeout=60) as c:
        while time.monotonic() < stop:
            await rec.call(c, "hostile derive", "POST", "/api/derive", json=HOSTILE_SYSTEM)
            await rec.call(c, "hostile simulate", "POST", f"/api/scenes/{scene['id']}/simulate", json=heavy)


async def flooder(base: str, rec: Recorder, stop: float) -> None:
    """One of the flood's sessions: a job built to run out of time, again as soon as it may."""
    async with httpx.AsyncClient(base_url=base, timeout=90) as c:  # keeps the session cookie it is given
        while time.monotonic() < stop:
            answer = await rec.call(c, "flood derive", "POST", "/api/derive", json=HOSTILE_SYSTEM)
            if answer is not None and answer.status_code in (429, 503):
                await asyncio.sleep(0.2)  # a flood does not wait its Retry-After


async def simulation_flood(base: str, scenes: list[dict], rec: Recorder, stop: float) -> None:
    scene = scenes[0]
    heavy = {"initial": scene["initial"], "t_end": 1e5, "rtol": 1e-12}
    async with httpx.AsyncClient(base_url=base, timeout=60) as c:
        while time.monotonic() < stop:
            await rec.call(c, "flood simulate", "POST", f"/api/scenes/{scene['id']}/simulate", json=heavy)


async def honest_session(base: str, rec: Recorder, stop: float) -> None:
    """A student deriving a new small system every few seconds; the time until each answer is recorded."""
    async with httpx.AsyncClient(base_url=base, timeout=90) as c:
        n = 0
        while time.monotonic() < stop:
            n += 1
            system = {**CUSTOM_SYSTEM, "potential": f"k*x**2/2 + x**4/{n + 3}"}  # new each time: no cached answer
            started = time.perf_counter()
            while True:
                answer = await rec.call(c, "honest derive (each try)", "POST", "/api/derive", json=system)
                if answer is None or answer.status_code not in (429, 503):
                    break
                await asyncio.sleep(float(answer.headers.get("Retry-After", "1")))
            rec.times["honest derive (until answered)"].append(time.perf_counter() - started)
            rec.status["honest derive (until answered)"][answer.status_code if answer is not None else 599] += 1
            await asyncio.sleep(3.0)


async def health_probe(base: str, rec: Recorder, stop: float) -> None:
    async with httpx.AsyncClient(base_url=base, timeout=30) as c:
        while time.monotonic() < stop:
            await rec.call(c, "healthz (in the load's loop)", "GET", "/healthz")
            await asyncio.sleep(0.2)


def probe_alone(base: str, seconds: float) -> list[tuple[float, float, int]]:
    """/healthz five times a second from a process of its own: (seconds into the run, latency in s,
    status; 599 for no answer)."""
    answers = []
    begun = time.monotonic()
    stop = begun + seconds
    with httpx.Client(base_url=base, timeout=30) as c:
        while time.monotonic() < stop:
            started = time.perf_counter()
            try:
                status = c.get("/healthz").status_code
            except httpx.HTTPError:
                status = 599
            answers.append((time.monotonic() - begun, time.perf_counter() - started, status))
            time.sleep(0.2)
    return answers


async def health_probe_alone(base: str, rec: Recorder, seconds: float) -> None:
    with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as one:
        answers = await asyncio.get_running_loop().run_in_executor(one, probe_alone, base, seconds)
    for _, latency, status in answers:
        rec.times["healthz (own process)"].append(latency)
        rec.status["healthz (own process)"][status] += 1
    # when the slowest answers came (a pause at the server's start, or spread over the flood)
    rec.slowest_probes = sorted(answers, key=lambda a: -a[1])[:3]


def server_rss_mb(pid: int) -> float:
    """Resident memory of the server and all its children (uvicorn workers, pool workers)."""
    pids, frontier = {pid}, [pid]
    while frontier:
        p = frontier.pop()
        try:
            children = Path(f"/proc/{p}/task/{p}/children").read_text().split()
        except OSError:
            continue
        for child in map(int, children):
            if child not in pids:
                pids.add(child)
                frontier.append(child)
    total = 0
    for p in pids:
        try:
            for line in Path(f"/proc/{p}/status").read_text().splitlines():
                if line.startswith("VmRSS:"):
                    total += int(line.split()[1])
        except OSError:
            pass
    return total / 1024


def start_server(workers: int) -> tuple[subprocess.Popen, str]:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    # serve.sh runs `python`: the one of this interpreter's environment (the venv)
    path = f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"
    env = {**os.environ, "PATH": path, "PORT": str(port), "HOST": "127.0.0.1", "WORKERS": str(workers)}
    # LOAD_TEST_SERVER_LOG=path keeps the server's output (its log and any traceback) in that file
    log = open(os.environ["LOAD_TEST_SERVER_LOG"], "wb") if os.environ.get("LOAD_TEST_SERVER_LOG") else None  # noqa: SIM115
    proc = subprocess.Popen(
        [str(ROOT / "scripts" / "serve.sh")],
        cwd=ROOT,
        env=env,
        stdout=log or subprocess.DEVNULL,
        stderr=log or subprocess.DEVNULL,
        start_new_session=True,
    )
    base = f"http://127.0.0.1:{port}"
    for _ in range(240):
        try:
            if httpx.get(base + "/healthz", timeout=1).status_code == 200:
                return proc, base
        except httpx.HTTPError:
            pass
        time.sleep(0.25)
    proc.kill()
    raise SystemExit("the server did not start")


def report(level: str, rec: Recorder, seconds: float, rss: tuple[float, float]) -> None:
    total = sum(len(v) for v in rec.times.values())
    server_errors = sum(n for s in rec.status.values() for code, n in s.items() if code >= 500)
    print(
        f"\n## {level}: {total} requests in {seconds:.0f} s = {total / seconds:.1f} req/s; "
        f"5xx/transport errors: {server_errors}; server RSS {rss[0]:.0f} -> {rss[1]:.0f} MB"
    )
    print("| endpoint | requests | p50 ms | p99 ms | statuses |")
    print("|---|---|---|---|---|")
    for name in sorted(rec.times):
        t = sorted(rec.times[name])
        p99 = t[min(len(t) - 1, int(0.99 * len(t)))]
        codes = ", ".join(f"{code}: {n}" for code, n in sorted(rec.status[name].items()))
        print(f"| {name} | {len(t)} | {statistics.median(t) * 1e3:.0f} | {p99 * 1e3:.0f} | {codes} |")
    if rec.slowest_probes:
        slowest = ", ".join(f"{latency * 1e3:.0f} ms at {at:.1f} s" for at, latency, _ in rec.slowest_probes)
        print(f"slowest own-process /healthz answers: {slowest}")


async def run_level(
    base: str, pid: int, students: int, hostiles: int, seconds: float, soak: bool, ramp: float, flood: int = 0
) -> None:
    async with httpx.AsyncClient(base_url=base, timeout=30) as c:
        scenes = (await c.get("/api/scenes")).json()
    rec = Recorder()
    rng = random.Random(students)
    stop = time.monotonic() + seconds
    before = server_rss_mb(pid)
    samples: list[tuple[float, float]] = []

    async def sample_memory() -> None:
        while time.monotonic() < stop:
            samples.append((seconds - (stop - time.monotonic()), server_rss_mb(pid)))
            await asyncio.sleep(min(30.0, seconds / 10))

    tasks = [student(base, scenes, rec, stop, random.Random(rng.random()), ramp) for _ in range(students)]
    tasks += [hostile(base, scenes, rec, stop) for _ in range(hostiles)]
    if flood:
        tasks += [flooder(base, rec, stop) for _ in range(flood)]
        tasks += [simulation_flood(base, scenes, rec, stop) for _ in range(4 * flood)]
        tasks += [honest_session(base, rec, stop), health_probe(base, rec, stop)]
        tasks += [health_probe_alone(base, rec, seconds)]
    started = time.monotonic()
    await asyncio.gather(sample_memory(), *tasks)
    elapsed = time.monotonic() - started
    label = f"{students} students" + (f" + {hostiles} hostile clients" if hostiles else "")
    label += f" + a flood of {flood} sessions and {4 * flood} simulation clients" if flood else ""
    report(label, rec, elapsed, (before, server_rss_mb(pid)))
    if soak and len(samples) > 2:
        warm = samples[1][1]
        peak_late = max(m for _, m in samples[len(samples) // 2 :])
        print("memory samples (s, MB): " + ", ".join(f"{t:.0f}:{m:.0f}" for t, m in samples))
        print(f"soak growth after warm-up: {100 * (peak_late - warm) / warm:.1f} % (goal < 20 %)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--students", type=int, nargs="+", default=[30, 100, 150])
    parser.add_argument("--hostile", type=int, default=0)
    parser.add_argument("--flood", type=int, default=0, help="flooding sessions (and 4x as many simulation clients)")
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--soak", action="store_true")
    parser.add_argument("--ramp", type=float, default=10.0, help="seconds over which students arrive")
    parser.add_argument(
        "--settle",
        type=float,
        default=0.0,
        help="seconds between the server's first answer and the load (its own warm-up ends meanwhile), "
        "as a liveness probe waits behind the start-up probe (deploy/kubernetes.yaml)",
    )
    parser.add_argument(
        "--no-warm", action="store_true", help="skip `python -m app.web.warm` (the image runs it at build)"
    )
    args = parser.parse_args()
    if args.seconds > 1800:
        sys.exit("--seconds is capped at 1800")
    if not args.no_warm:
        subprocess.run([sys.executable, "-m", "app.web.warm"], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    proc, base = start_server(args.workers)
    try:
        print(
            f"server: {args.workers} uvicorn workers at {base}; client and server share this machine "
            f"({os.cpu_count()} cores)"
            + (f"; the load starts {args.settle:g} s after its first answer" if args.settle else "")
        )
        time.sleep(args.settle)
        for n in args.students:
            level = run_level(base, proc.pid, min(n, 500), args.hostile, args.seconds, args.soak, args.ramp, args.flood)
            asyncio.run(level)
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(timeout=30)


if __name__ == "__main__":
    main()
