"""How big one replica is: its memory and CPU idle after warm-up and while a lecture hall checks its answers.

Starts one replica as the Kubernetes manifest runs it (scripts/serve.sh with ``WORKERS`` web processes,
2 by default as in deploy/kubernetes.yaml, the start-up warm-up on, the chapter's caches already on disk
as in the image, the classes' SQLite in a fresh data directory) and measures the whole process tree (the
uvicorn master, its web processes, their forkservers and pool workers and the scenes' worker):

* start-up: seconds from launching the server to its first ``/healthz`` answer (what the readiness probe
  waits for), and to the end of the warm-up (the first ``--quiet`` seconds in which the tree used less than
  a tenth of a CPU; at most 300 s, else "nan");
* idle: the summed resident memory (VmRSS; and PSS, which counts a page shared by several processes once, as
  the container's memory cgroup does) and the CPU used over ``--quiet`` seconds;
* under load: benchmarks/bench_classroom's lecture hall (``--students`` behind one address, every answer
  distinct, ``--hall`` checking at a time) while the tree is sampled every ``--every`` seconds: the peak summed
  RSS and PSS, the CPU seconds used and the busiest ``WINDOW`` seconds in cores, the slowest answers of
  ``/healthz`` asked once a second as a kubelet's probe asks (what its ``timeoutSeconds`` must allow), and the
  hall's own report (answers by status, p50/p95/p99 of a recorded check).

The CPU a replica can use is what the machine gives it: on a shared machine, read the load average printed
beside the figures.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_replica_size --students 60 --hall 20
"""

from __future__ import annotations

import argparse
import asyncio
import os
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

import httpx2 as httpx

from benchmarks.bench_classroom import hall, percentile, report_hall, start_server

TICK = os.sysconf("SC_CLK_TCK")
WINDOW = 5.0  # seconds over which the busiest CPU use is reported
MB = 1024.0


def tree(root: int) -> list[int]:
    """``root`` and every process below it."""
    found, todo = [], [root]
    while todo:
        pid = todo.pop()
        found.append(pid)
        try:
            todo += [int(c) for t in os.listdir(f"/proc/{pid}/task")
                     for c in Path(f"/proc/{pid}/task/{t}/children").read_text().split()]
        except OSError:
            continue
    return found


def memory_mb(pid: int) -> tuple[float, float]:
    """(RSS, PSS) of one process in MB, zeros once it is gone."""
    try:
        rollup = Path(f"/proc/{pid}/smaps_rollup").read_text().splitlines()
    except OSError:
        return 0.0, 0.0
    fields = {line.split(":")[0]: line.split()[1] for line in rollup[1:] if ":" in line}
    return int(fields.get("Rss", 0)) / MB, int(fields.get("Pss", 0)) / MB


def cpu_seconds(pid: int) -> float | None:
    """User plus system CPU time of one process so far (fields 14 and 15 of /proc/PID/stat)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    after = stat[stat.rindex(")") + 2:].split()  # the command name may hold spaces
    return (int(after[11]) + int(after[12])) / TICK


@dataclass
class Sampler:
    """The tree's summed memory and CPU time, sampled every ``every`` seconds in a thread of its own."""

    root: int
    every: float
    cpu: dict[int, float] = field(default_factory=dict)  # each process's last CPU time seen (a replaced worker's stays)
    points: list[tuple[float, float, float, float]] = field(default_factory=list)  # (time, RSS, PSS, CPU so far)
    url: str = ""  # the server whose /healthz is asked at each sample, as a probe asks
    probes: list[float] = field(default_factory=list)  # seconds to each /healthz answer (inf: none within 10 s)
    stop: threading.Event = field(default_factory=threading.Event)

    def sample(self) -> tuple[float, float, float, float]:
        rss = pss = 0.0
        for pid in tree(self.root):
            r, p = memory_mb(pid)
            rss, pss = rss + r, pss + p
            if (used := cpu_seconds(pid)) is not None:
                self.cpu[pid] = used
        point = (time.monotonic(), rss, pss, sum(self.cpu.values()))
        self.points.append(point)
        return point

    def probe(self) -> None:
        started = time.perf_counter()
        try:
            answered = httpx.get(f"{self.url}/healthz", timeout=10).status_code == 200
        except httpx.HTTPError:
            answered = False
        self.probes.append(time.perf_counter() - started if answered else float("inf"))

    def run(self) -> None:
        while not self.stop.wait(self.every):
            self.sample()
            if self.url:
                self.probe()

    def __enter__(self) -> Sampler:
        self.points.clear()
        self.probes.clear()
        self.sample()
        self._thread = threading.Thread(target=self.run, daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop.set()
        self._thread.join()
        self.sample()
        self.stop.clear()

    def peak(self) -> tuple[float, float]:
        return max(p[1] for p in self.points), max(p[2] for p in self.points)

    def cores(self) -> tuple[float, float, float]:
        """(CPU seconds, mean cores, busiest WINDOW s in cores) over the sampled span."""
        (t0, *_, c0), (t1, *_, c1) = self.points[0], self.points[-1]
        busiest = 0.0
        for i, (ta, *_, ca) in enumerate(self.points):
            later = [p for p in self.points[i:] if p[0] - ta >= WINDOW]
            if later:
                busiest = max(busiest, (later[0][3] - ca) / (later[0][0] - ta))
        return c1 - c0, (c1 - c0) / max(t1 - t0, 1e-9), busiest


def load() -> str:
    return " ".join(Path("/proc/loadavg").read_text().split()[:3])


def until_quiet(sampler: Sampler, quiet: float, limit: float) -> float:
    """Seconds until the tree has used under a tenth of a CPU for ``quiet`` seconds (at most ``limit``)."""
    started = time.monotonic()
    while time.monotonic() - started < limit:
        t0, *_, c0 = sampler.sample()
        time.sleep(quiet)
        t1, *_, c1 = sampler.sample()
        if (c1 - c0) / (t1 - t0) < 0.1:
            return t0 - started
    return float("nan")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--workers", type=int, default=2, help="web processes (deploy/kubernetes.yaml's WORKERS)")
    parser.add_argument("--students", type=int, default=60)
    parser.add_argument("--hall", type=int, default=20, metavar="AT_ONCE", help="students checking at a time")
    parser.add_argument("--quiet", type=float, default=10.0, help="seconds of quiet that end the warm-up")
    parser.add_argument("--every", type=float, default=1.0, help="seconds between samples")
    args = parser.parse_args()
    print(f"load average before: {load()} (1, 5, 15 min; {os.cpu_count()} CPUs)")
    with tempfile.TemporaryDirectory() as data:
        launched = time.monotonic()
        process, url = start_server(data, workers=args.workers, warm=True, limit=600)
        ready = time.monotonic() - launched
        try:
            sampler = Sampler(process.pid, args.every, url=url)
            warmed = ready + until_quiet(sampler, args.quiet, 300)
            with sampler:
                time.sleep(args.quiet)
            idle_rss, idle_pss = sampler.peak()
            _, idle_cores, _ = sampler.cores()
            processes = len(tree(process.pid))
            with sampler:
                out = asyncio.run(hall(url, args.students, args.hall))
            busy_rss, busy_pss = sampler.peak()
            probes = sampler.probes
            seconds, mean, busiest = sampler.cores()
            span = sampler.points[-1][0] - sampler.points[0][0]  # the hall with its warm-up checks
            after = load()
        finally:
            process.terminate()
            process.wait(30)
    print(f"one replica: {args.workers} web processes, {processes} processes in all once warm")
    print(f"start-up: /healthz answered {ready:.1f} s after launch; warm-up over (quiet) after {warmed:.0f} s")
    print(f"idle after warm-up: RSS {idle_rss:.0f} MB summed, PSS {idle_pss:.0f} MB; {idle_cores:.2f} cores")
    print(f"lecture hall: peak RSS {busy_rss:.0f} MB summed, peak PSS {busy_pss:.0f} MB; {seconds:.0f} CPU s in "
          f"{span:.0f} s sampled (the hall's timed part: {out['seconds']:.0f} s): mean {mean:.2f} cores, busiest {WINDOW:g} s {busiest:.2f} cores")
    print(f"/healthz asked every {args.every:g} s during the hall: {len(probes)} answers, p50 "
          f"{1000 * percentile(probes, 0.5):.0f} ms, p99 {1000 * percentile(probes, 0.99):.0f} ms, "
          f"slowest {1000 * max(probes):.0f} ms")
    print(f"load average at the end: {after}")
    report_hall(out, args.students, args.hall)


if __name__ == "__main__":
    main()
