"""Soak: mixed classroom traffic for a long while, and the resident size of each web process over it.

Starts the server as the image does (scripts/serve.sh, ``--workers`` web processes) and runs the
load test's clients (benchmarks/load_test.py) for ``--minutes`` (30 for the real soak; the default
is a quick run): students opening scene pages and their assets, simulating and deriving systems of
their own, and ``--hostile`` clients sending expensive jobs back to back.  Every ``--every`` seconds
it reads the resident size (VmRSS) of each web process on its own (the uvicorn master's children;
their forkservers and pool workers are counted apart, as the memory budget counts them), and at the
end reports, per web process, its size after warm-up (the second sample), at the end, its peak, and
the growth per hour fitted over the second half of the run (a least-squares slope), beside the
``web_process_mb`` the memory budget uses (app/settings.py).

    .venv/bin/python -m benchmarks.soak                   # a quick run (5 minutes)
    .venv/bin/python -m benchmarks.soak --minutes 30      # the soak
"""

from __future__ import annotations

import argparse
import asyncio
import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import httpx2 as httpx

from app.settings import settings
from benchmarks.load_test import ROOT, Recorder, hostile, start_server, student


def children(pid: int) -> list[int]:
    try:
        return [int(c) for c in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


def rss_mb(pid: int) -> float:
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    except OSError:
        pass
    return 0.0


def web_processes(master: int) -> list[int]:
    """The uvicorn master's web processes (its children that serve: not the resource tracker)."""
    found = []
    for child in children(master):
        try:
            command = Path(f"/proc/{child}/cmdline").read_bytes()
        except OSError:
            continue
        if b"resource_tracker" not in command:
            found.append(child)
    return found


def slope_per_hour(points: list[tuple[float, float]]) -> float:
    """Least-squares slope of (seconds, MB), in MB per hour."""
    if len(points) < 2:
        return 0.0
    n = len(points)
    mt = sum(t for t, _ in points) / n
    mm = sum(m for _, m in points) / n
    var = sum((t - mt) ** 2 for t, _ in points)
    return 3600 * sum((t - mt) * (m - mm) for t, m in points) / var if var else 0.0


async def soak(base: str, master: int, minutes: float, students: int, hostiles: int, every: float) -> None:
    async with httpx.AsyncClient(base_url=base, timeout=30) as c:
        scenes = (await c.get("/api/scenes")).json()
    seconds = 60 * minutes
    rec = Recorder()
    rng = random.Random(7)
    stop = time.monotonic() + seconds
    started = time.monotonic()
    samples: dict[int, list[tuple[float, float]]] = {}
    rest: list[tuple[float, float]] = []

    async def sample() -> None:
        while time.monotonic() < stop:
            now = time.monotonic() - started
            webs = web_processes(master)
            for pid in webs:
                samples.setdefault(pid, []).append((now, rss_mb(pid)))
            others = [p for w in webs for p in children(w)]
            others += [g for p in others for g in children(p)]
            rest.append((now, sum(rss_mb(p) for p in others)))
            await asyncio.sleep(every)

    tasks = [student(base, scenes, rec, stop, random.Random(rng.random()), 10.0) for _ in range(students)]
    tasks += [hostile(base, scenes, rec, stop) for _ in range(hostiles)]
    await asyncio.gather(sample(), *tasks)
    total = sum(len(v) for v in rec.times.values())
    errors = sum(n for s in rec.status.values() for code, n in s.items() if code >= 500)
    print(f"{total} requests in {seconds:.0f} s ({students} students, {hostiles} hostile); 5xx/transport: {errors}")
    print(f"budget's web_process_mb: {settings().web_process_mb} MB")
    print("| web process | after warm-up MB | end MB | peak MB | growth, 2nd half, MB/hour |")
    print("|---|---|---|---|---|")
    for pid, points in samples.items():
        warm = points[1][1] if len(points) > 1 else points[0][1]
        late = points[len(points) // 2 :]
        peak = max(m for _, m in points)
        print(f"| {pid} | {warm:.0f} | {points[-1][1]:.0f} | {peak:.0f} | {slope_per_hour(late):+.0f} |")
    print("samples (s: MB per web process): " + "; ".join(
        f"{t:.0f}: " + ", ".join(f"{dict(samples[p]).get(t, 0):.0f}" for p in samples) for t, _ in next(iter(samples.values()))
    ))  # fmt: skip
    if rest:
        print(f"forkservers and workers together: {rest[0][1]:.0f} -> {rest[-1][1]:.0f} MB")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--minutes", type=float, default=5.0, help="30 for the soak; at most 60")
    parser.add_argument("--students", type=int, default=30)
    parser.add_argument("--hostile", type=int, default=1)
    parser.add_argument("--workers", type=int, default=2, help="web processes")
    parser.add_argument("--every", type=float, default=15.0, help="seconds between memory samples")
    parser.add_argument("--no-warm", action="store_true", help="skip `python -m app.web.warm`")
    args = parser.parse_args()
    if not 0 < args.minutes <= 60:
        sys.exit("--minutes must be in (0, 60]")
    if not args.no_warm:
        subprocess.run([sys.executable, "-m", "app.web.warm"], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    proc, base = start_server(args.workers)
    try:
        print(f"server: {args.workers} web processes at {base}; load average {os.getloadavg()[0]:.2f} at start")
        asyncio.run(soak(base, proc.pid, args.minutes, args.students, args.hostile, args.every))
        print(f"load average at the end: {os.getloadavg()[0]:.2f}")
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(timeout=30)


if __name__ == "__main__":
    main()
