"""First-compile cost of the compiled path, and the cost once numba's disk cache is filled.

Each measurement runs in a fresh Python process with an empty cache folder (cold), then again in
another fresh process on the filled cache (warm).  Kernels are compiled once for every system (they
take the right-hand side as a first-class function); each new system only compiles its small
generated right-hand sides.

    .venv/bin/python -m benchmarks.bench_numerics_compile
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile

PROBE = r"""
import json, time
t0 = time.perf_counter()
import numba  # noqa: F401
from app.numerics.kernels import common  # noqa: F401
timings = {"numba import + shared helpers": time.perf_counter() - t0}
for name in ("vern8", "dop853", "composition", "gauss"):  # auto's default first, as the server warms up
    t = time.perf_counter()
    __import__(f"app.numerics.kernels.{name}")
    timings[f"kernel {name}"] = time.perf_counter() - t
from app.engine.derivation.derive import derive
from app.numerics.system import numeric_system
from app.scenes import SCENES
for scene in ("simple-pendulum", "spherical-pendulum"):
    s = numeric_system(derive(SCENES[scene].system))
    t = time.perf_counter()
    s.compiled()
    timings[f"generated rhs + ham, {scene}"] = time.perf_counter() - t
print(json.dumps(timings))
"""


def measure(cache: str) -> dict[str, float]:
    env = {**os.environ, "LAGRANGE_CACHE_DIR": cache}
    env.pop("NUMBA_CACHE_DIR", None)
    out = subprocess.run([sys.executable, "-c", PROBE], env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    with tempfile.TemporaryDirectory() as cache:
        cold = measure(cache)
        warm = measure(cache)
    print("| step | cold (empty cache) s | warm (disk cache) s |")
    print("|---|---|---|")
    for key in cold:
        print(f"| {key} | {cold[key]:.2f} | {warm[key]:.2f} |")
    print(f"| total | {sum(cold.values()):.2f} | {sum(warm.values()):.2f} |")


if __name__ == "__main__":
    main()
