"""A class on one server: 150 students join and answer 10 steps each; recorded checks against unrecorded ones.

Starts one web process (scripts/serve.sh, WORKERS=1: the process count of a
2-core container, its worker pool sized from the CPUs) on a loopback port with
the classes' SQLite database in a temporary data directory.  An instructor
creates a class and assigns the double pendulum's ten steps; 150 students join
(each from an address of its own, 127.0.0.2 …, as on a campus network) and
answer every step twice, in a random order per step: once through the class's
POST /api/classes/{code}/check (judged, then recorded and committed before the
answer) and once through practice mode's POST /api/scenes/{id}/check (judged
only), under the same load at the same moment.  Every answer text is unique
(``+ 0*k``), so none comes from the answer cache: each is judged in the worker
pool, as a class typing its own answers would make it.  About one answer in
three is the engine's step doubled (for T, the named mistake ``missing_half``).
A student thinks 2-6 s between steps and honours ``Retry-After`` on a 429/503;
latency is timed on answered (200) requests.

Reports: the summary's counts against what the students were told (must be
exact), p50/p95 of each kind and the ratio of the p95s (goal: at most 1.5).

    .venv/bin/python -m benchmarks.bench_classroom [--students 150]

With ``--hall AT_ONCE`` it is a lecture hall instead: the students all behind one address (127.0.0.44), each
opening /join (its session) before joining, then checking every step once (recorded, with an attempt id),
every answer distinct, AT_ONCE students checking at a time.  Reports the answers by status (goal: no 429)
and p50/p95/p99 of a recorded check (goal: p95 ≤ 1 s), apart for the engine's step and the doubled one, and the
CPU seconds the server used meanwhile: its web process's and its workers', per recorded check.

    .venv/bin/python -m benchmarks.bench_classroom --students 60 --hall 20
"""

from __future__ import annotations

import argparse
import asyncio
import os
import random
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter
from pathlib import Path

import httpx2 as httpx

ROOT = Path(__file__).resolve().parents[1]
SCENE = "double-pendulum"
GOAL = 1.5


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(
    data_dir: str, workers: int = 1, warm: bool = False, limit: float = 90.0
) -> tuple[subprocess.Popen, str]:
    """scripts/serve.sh on a free loopback port with ``workers`` web processes, once /healthz answers (within
    ``limit`` seconds)."""
    port = free_port()
    env = {**os.environ, "PORT": str(port), "HOST": "127.0.0.1", "WORKERS": str(workers), "LAGRANGE_DATA_DIR": data_dir,
           "LAGRANGE_WARM": "1" if warm else "0", "PYTHONPATH": str(ROOT),
           "PATH": f"{Path(sys.executable).parent}:{os.environ['PATH']}"}
    # in a session of its own: its own share of the CPU (the kernel's autogroups), and killed as a group
    process = subprocess.Popen([str(ROOT / "scripts" / "serve.sh")], cwd=ROOT, env=env, start_new_session=True)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        try:
            if httpx.get(f"{url}/healthz", timeout=2).status_code == 200:
                return process, url
        except httpx.HTTPError:
            time.sleep(0.3)
    os.killpg(process.pid, signal.SIGKILL)  # the web processes and their workers with it
    process.wait()
    raise RuntimeError(f"the server did not start within {limit:g} s")


async def send(client: httpx.AsyncClient, url: str, body: dict, headers: dict, timings: list[float]) -> dict:
    """POST until answered (honouring Retry-After); the answered request's time goes to ``timings``."""
    while True:
        started = time.perf_counter()
        r = await client.post(url, json=body, headers=headers, timeout=120)
        elapsed = time.perf_counter() - started
        if r.status_code == 200:
            timings.append(elapsed)
            return r.json()
        if r.status_code in (429, 503):
            await asyncio.sleep(float(r.headers.get("Retry-After", "1")))
            continue
        raise RuntimeError(f"{url}: {r.status_code} {r.text[:300]}")


async def student(n: int, url: str, code: str, exercises: list[dict], out: dict, rng: random.Random) -> None:
    transport = httpx.AsyncHTTPTransport(local_address=f"127.0.{(n + 2) // 250}.{(n + 2) % 250 + 1}")
    async with httpx.AsyncClient(transport=transport, base_url=url) as client:
        await asyncio.sleep(rng.uniform(0, 10))  # arriving over ten seconds
        while True:
            r = await client.post(f"/api/classes/{code}/join", json={"name": f"student {n}"})
            if r.status_code == 200:
                break
            await asyncio.sleep(float(r.headers.get("Retry-After", "1")))
        key = {"Authorization": f"Bearer {r.json()['student_key']}"}
        for k, e in enumerate(exercises):
            await asyncio.sleep(rng.uniform(2, 6))
            base = e["answer"]["sympy"]
            wrong = rng.random() < 1 / 3
            texts = [f"{'2*(' + base + ')' if wrong else base} + 0*{n * 100 + k * 2 + i}" for i in range(2)]
            step = {"step": e["step"], **({"coordinate": e["coordinate"]} if e["coordinate"] else {})}
            kinds = ["recorded", "unrecorded"]
            rng.shuffle(kinds)
            for kind, text in zip(kinds, texts, strict=True):
                if kind == "recorded":
                    verdict = await send(client, f"/api/classes/{code}/check", {"scene": SCENE, **step, "answer": text},
                                         key, out["recorded"])
                    out["told"][(e["step"], e["coordinate"], verdict["verdict"] in ("correct", "equivalent"))] += 1
                else:
                    await send(client, f"/api/scenes/{SCENE}/check", {**step, "answer": text}, {}, out["unrecorded"])


async def run(url: str, students: int) -> dict:
    async with httpx.AsyncClient(base_url=url) as client:
        exercises = (await client.get(f"/api/scenes/{SCENE}/practice", timeout=120)).json()["exercises"][:10]
        created = (await client.post("/api/classes", json={"title": "benchmark"})).json()
        code, teacher = created["code"], {"Authorization": f"Bearer {created['teacher_key']}"}
        items = [{"scene": SCENE, "steps": [{"step": e["step"], "coordinate": e["coordinate"]} for e in exercises]}]
        assert (await client.put(f"/api/classes/{code}/assignment", json={"items": items}, headers=teacher)).status_code == 200
        # warm-up: each step's problem built and the workers started, outside the class
        for e in exercises:
            step = {"step": e["step"], **({"coordinate": e["coordinate"]} if e["coordinate"] else {})}
            await send(client, f"/api/scenes/{SCENE}/check", {**step, "answer": e["answer"]["sympy"]}, {}, [])
        out: dict = {"recorded": [], "unrecorded": [], "told": Counter()}
        rng = random.Random(33)
        started = time.perf_counter()
        await asyncio.gather(*(student(n, url, code, exercises, out, random.Random(rng.random())) for n in range(students)))
        out["seconds"] = time.perf_counter() - started
        out["summary"] = (await client.get(f"/api/classes/{code}/summary", headers=teacher)).json()
        out["exercises"] = exercises
        return out


HALL_ADDRESS = "127.0.0.44"  # the lecture hall's one network address
NO_ANSWER = 0  # the status counted for a check the server did not answer within the client's timeout


async def hall_student(n: int, url: str, code: str, exercises: list[dict], gate: asyncio.Semaphore, out: dict) -> None:
    """One student of the hall: opens /join (the session), joins, then checks every step once, recorded, with
    an answer no one else sends (right, or one in three doubled); at most ``gate`` students check at a time."""
    transport = httpx.AsyncHTTPTransport(local_address=HALL_ADDRESS)
    async with httpx.AsyncClient(transport=transport, base_url=url, timeout=120) as client:
        await client.get(f"/join?code={code}")
        r = await client.post(f"/api/classes/{code}/join", json={"name": f"student {n}"})
        out["statuses"][r.status_code] += 1
        if r.status_code != 200:
            return
        key = {"Authorization": f"Bearer {r.json()['student_key']}"}
        for k, e in enumerate(exercises):
            base = e["answer"]["sympy"]
            doubled = (n + k) % 3 == 0
            text = f"{'2*(' + base + ')' if doubled else base} + 0*{n * 100 + k}"
            step = {"step": e["step"], **({"coordinate": e["coordinate"]} if e["coordinate"] else {})}
            async with gate:
                started = time.perf_counter()
                try:
                    r = await client.post(f"/api/classes/{code}/check", json={"scene": SCENE, **step, "answer": text,
                                                                              "attempt": f"s{n}-step{k}-bench"},
                                          headers=key)
                except httpx.TimeoutException:  # no answer within the client's 120 s: counted, not fatal
                    out["statuses"][NO_ANSWER] += 1
                    continue
                out["statuses"][r.status_code] += 1
                if r.status_code == 200:
                    out["recorded"].append(time.perf_counter() - started)
                    out["doubled" if doubled else "engine's"].append(time.perf_counter() - started)


class TreeCPU:
    """The CPU seconds the server's processes use, the web process apart from its workers (the forkserver, the
    pool's workers, the scenes' worker), sampled every half second in a thread (a worker replaced meanwhile
    keeps the time it was last seen with)."""

    def __init__(self, root: int) -> None:
        from benchmarks.bench_replica_size import cpu_seconds, tree

        self.root, self._tree, self._cpu = root, tree, cpu_seconds
        self.seen: dict[int, float] = {}
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._sample, daemon=True)

    def snapshot(self) -> tuple[float, float]:
        """(the web process's CPU seconds so far, its workers')."""
        for pid in self._tree(self.root):
            if (used := self._cpu(pid)) is not None:
                self.seen[pid] = used
        web = self.seen.get(self.root, 0.0)
        return web, sum(self.seen.values()) - web

    def _sample(self) -> None:
        while not self._stop.wait(0.5):
            self.snapshot()

    def start(self) -> None:
        self._thread.start()

    def stop(self) -> None:
        self._stop.set()
        self._thread.join()


async def hall(url: str, students: int, at_once: int, cpu: TreeCPU | None = None) -> dict:
    async with httpx.AsyncClient(base_url=url) as client:
        exercises = (await client.get(f"/api/scenes/{SCENE}/practice", timeout=120)).json()["exercises"][:10]
        created = (await client.post("/api/classes", json={"title": "lecture hall"})).json()
        code, teacher = created["code"], {"Authorization": f"Bearer {created['teacher_key']}"}
        for e in exercises:  # warm-up: each step's problem built and the workers started, outside the class
            step = {"step": e["step"], **({"coordinate": e["coordinate"]} if e["coordinate"] else {})}
            await send(client, f"/api/scenes/{SCENE}/check", {**step, "answer": e["answer"]["sympy"]}, {}, [])
        out: dict = {"recorded": [], "engine's": [], "doubled": [], "statuses": Counter()}
        gate = asyncio.Semaphore(at_once)
        before = cpu.snapshot() if cpu else None
        started = time.perf_counter()
        await asyncio.gather(*(hall_student(n, url, code, exercises, gate, out) for n in range(students)))
        out["seconds"] = time.perf_counter() - started
        if cpu and before:
            out["cpu"] = tuple(b - a for a, b in zip(before, cpu.snapshot(), strict=True))
        out["summary"] = (await client.get(f"/api/classes/{code}/summary", headers=teacher)).json()
        out["exercises"] = exercises
        return out


def report_hall(out: dict, students: int, at_once: int) -> bool:
    t, statuses, summary = out["recorded"], out["statuses"], out["summary"]
    print(f"lecture hall: {students} students from {HALL_ADDRESS}, {len(out['exercises'])} steps each, "
          f"{at_once} checking at a time, in {out['seconds']:.0f} s; load average "
          f"{open('/proc/loadavg').read().split()[0]} (1 min) at the end")
    print(f"answers by status (0: none within 120 s): {dict(sorted(statuses.items()))}; summary: {summary['students']} students, "
          f"{summary['attempts']} attempts")
    p95 = percentile(t, 0.95) if t else float("inf")
    print(f"recorded checks: {len(t)} answered, p50 {1000 * statistics.median(t):.0f} ms, p95 {1000 * p95:.0f} ms "
          f"(goal ≤ 1000 ms), p99 {1000 * percentile(t, 0.99):.0f} ms")
    for kind in ("engine's", "doubled"):
        if out.get(kind):
            print(f"  of them the {kind} step: {len(out[kind])}, p50 {1000 * statistics.median(out[kind]):.0f} ms, "
                  f"p95 {1000 * percentile(out[kind], 0.95):.0f} ms")
    if "cpu" in out and t:
        web, workers = out["cpu"]
        print(f"server CPU in the hall: web process {web:.1f} s, its workers {workers:.1f} s; per recorded check "
              f"{1000 * web / len(t):.0f} ms + {1000 * workers / len(t):.0f} ms")
    return set(statuses) == {200} and summary["attempts"] == students * len(out["exercises"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=150)
    parser.add_argument("--hall", type=int, default=0, metavar="AT_ONCE",
                        help="a lecture hall instead: the students behind one address, AT_ONCE checking at a time")
    args = parser.parse_args()
    if args.hall:
        with tempfile.TemporaryDirectory() as data:
            process, url = start_server(data)
            cpu = TreeCPU(process.pid)
            cpu.start()
            try:
                out = asyncio.run(hall(url, args.students, args.hall, cpu))
            finally:
                cpu.stop()
                process.terminate()
                process.wait(30)
        sys.exit(0 if report_hall(out, args.students, args.hall) else 1)
    with tempfile.TemporaryDirectory() as data:
        process, url = start_server(data)
        try:
            out = asyncio.run(run(url, args.students))
        finally:
            process.terminate()
            process.wait(30)
    summary, told = out["summary"], out["told"]
    exact = summary["students"] == args.students and summary["attempts"] == args.students * len(out["exercises"])
    for entry in summary["steps"]:
        key = (entry["step"], entry["coordinate"])
        exact &= entry["correct"] == told[(*key, True)] and entry["incorrect"] == told[(*key, False)]
    print(f"{args.students} students × {len(out['exercises'])} steps in {out['seconds']:.0f} s; "
          f"load average {open('/proc/loadavg').read().split()[0]} (1 min) at the end")
    print(f"summary: {summary['students']} students, {summary['attempts']} attempts; "
          f"counts per step {'exact' if exact else 'NOT exact'}; missing_half named "
          f"{summary['steps'][0]['mistakes'].get('missing_half', 0)} times")
    for kind in ("recorded", "unrecorded"):
        t = out[kind]
        print(f"{kind:>10}: {len(t)} answered, p50 {1000 * statistics.median(t):.0f} ms, p95 {1000 * percentile(t, 0.95):.0f} ms")
    ratio = percentile(out["recorded"], 0.95) / percentile(out["unrecorded"], 0.95)
    print(f"p95 recorded / unrecorded = {ratio:.2f} (goal ≤ {GOAL}) {'ok' if ratio <= GOAL else 'MISSED'}")
    if not exact:
        sys.exit(1)


if __name__ == "__main__":
    main()
