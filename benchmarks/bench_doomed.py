"""How much a doomed request delays another session's small derivation (at most 2 s).

The scenario of tests/service/runtime/test_doomed_session.py (the service path: cache, fair-share gate, a pool of
two workers): session A sends a twelve-link chain that runs into its hard limit; one second into it, session
B derives a one-link pendulum no cache holds.  Printed: B's derivation alone and beside the doomed job, and
the difference (the delay), for each of REPEATS fresh pools, with the load average.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_doomed
"""

from __future__ import annotations

import statistics

from tests.service.runtime.test_doomed_session import beside_doomed

REPEATS = 3


def main() -> None:
    delays = []
    for _ in range(REPEATS):
        seen = beside_doomed()
        delays.append(float(seen["beside"]) - float(seen["alone"]))
        print(f"alone {seen['alone']:.2f} s, beside the doomed job {seen['beside']:.2f} s, "
              f"doomed still running when answered: {seen['doomed_running']}")  # fmt: skip
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    print(f"delay (beside - alone): median {statistics.median(delays):+.2f} s, worst {max(delays):+.2f} s "
          f"(load average {load}; the issue's bound: 2 s)")  # fmt: skip


if __name__ == "__main__":
    main()
