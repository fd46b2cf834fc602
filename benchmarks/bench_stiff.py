"""Stiff systems: the compiled Radau IIA against scipy's Radau and BDF at equal error, and ``auto`` under load.

Three linear systems from the engine (so the exact motion is exp(A t) y0, A = dF/dy, which is constant):

* the chain of masses 1e-9 and 1e9 kg between springs of 1e9 N/m (t_end 10 s, the light mass at rest
  where the springs balance it; the heavy one swings at 1.2 rad/s, the light one's mode is 1.4e9 rad/s);
* the stiff-soft chain, a 1 kg mass on a k = 1e8 spring coupled by k = 1 to a second one (t_end 5 s);
* an excited k/m = 1e8 spring, damped (b/m = 2e3), beside a k/m = 1 one (t_end 10 s): the fast mode
  rings down over the first milliseconds.

Each method runs over rtol = 10^(-k/2), k = 6 .. 20 (atol = rtol 1e-3), 201 samples; the error is the
largest deviation of a coordinate from exp(A t) y0 over the samples, divided by the coordinate's largest
|q|; the time is the best of ``REPEATS`` runs (every method on the same right-hand side: the engine's
generated function, compiled for ours, plain Python for scipy's, which calls back into Python at every
step anyway; scipy gets the engine's Jacobian too).  At each target error, a method's time is that of
its loosest tolerance reaching the target (as bench_cyrk does); the ratio is scipy's time over ours.

Then ``auto`` on each system with the server's wall-clock budget (8 s), alone and with ``--busy N``
busy processes per core (each in its own session, so the kernel's autogroup scheduling does not
lump them together): what it picked, whether it finished, its time.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_stiff [--busy 4]
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import time

import numpy as np

from app.engine.derivation.derive import derive
from app.engine.parser.user_system import UserSystem
from app.numerics.errors import TooMuchWork
from app.numerics.methods import METHODS, STIFF, Problem
from app.numerics.simulate import simulate
from app.numerics.system import NumericSystem, numeric_system
from tests.numerics.systems import LOPSIDED_CHAIN, STIFF_SOFT_CHAIN, TWO_MODES

OURS = STIFF
SCIPYS = ("Radau", "BDF")
RTOLS = [10.0 ** (-k / 2) for k in range(6, 19)]
TARGETS = (1e-4, 1e-6, 1e-8)
REPEATS = 3
GIVE_UP = 10.0  # seconds for one run
SAMPLES = 201


def user_case(body: dict) -> tuple[NumericSystem, np.ndarray, np.ndarray, float]:
    system = numeric_system(derive(UserSystem.of(body).system()))
    k = np.array([p["value"] for p in body["parameters"]])
    names = [*system.coordinates, *(f"{q}_dot" for q in system.coordinates)]
    y0 = np.array([float(body["initial"].get(name, 0.0)) for name in names])
    return system, k, y0, float(body["t_end"])


def cases() -> dict[str, tuple[NumericSystem, np.ndarray, np.ndarray, float]]:
    two = numeric_system(derive(TWO_MODES))
    return {
        "chain 1e-9 / 1e9 kg": user_case(LOPSIDED_CHAIN),
        "stiff-soft chain": user_case(STIFF_SOFT_CHAIN),
        "excited k/m = 1e8, damped": (
            two,
            np.array([p.default for p in TWO_MODES.parameters]),
            np.array([1.0, 1e-3, 0.0, 0.0]),
            10.0,
        ),
    }


def exact(system: NumericSystem, k: np.ndarray, y0: np.ndarray, t: np.ndarray) -> np.ndarray:
    """exp(A t) y0 on the evenly spaced samples t, in 60-digit arithmetic: y_{i+1} = exp(A dt) y_i.  (scipy's
    expm in double precision was off by 4e-8 at t = 10 s on the chain, whose A holds 1e18 beside 1.)"""
    import mpmath

    mpmath.mp.dps = 60
    # a linear system: F(y) = A y with A = dF/dy anywhere
    A = mpmath.matrix(system.jacobian(0.0, y0, k).tolist())
    step = mpmath.expm(A * mpmath.mpf(float(t[1] - t[0])))
    y = mpmath.matrix(y0.tolist())
    out = [y0.copy()]
    for _ in t[1:]:
        y = step * y
        out.append(np.array([float(v) for v in y]))
    return np.array(out)


def time_at(points: list[tuple[float, float]], target: float) -> float:
    """Seconds of the loosest tolerance whose error is at most ``target`` (the points are loose to tight);
    NaN when none reaches it."""
    for error, seconds in points:
        if error <= target:
            return seconds
    return math.nan


def work_precision() -> None:
    for label, (system, k, y0, t_end) in cases().items():
        t = np.linspace(0.0, t_end, SAMPLES)
        truth = exact(system, k, y0, t)
        scale = np.maximum(np.abs(truth[:, : system.n]).max(axis=0), 1e-300)
        METHODS[OURS].prepare(system)
        system.compiled()
        print(f"\n{label} (t_end {t_end:g} s)")
        print(f"  {'method':16} {'rtol':>8} {'steps':>7} {'error':>9} {'ms':>9}")
        curves: dict[str, list[tuple[float, float]]] = {}
        for name in (OURS, *SCIPYS):
            curve = []
            for rtol in RTOLS:
                best = math.inf
                trajectory = None
                for _ in range(REPEATS):
                    problem = Problem(
                        system, k, y0, t, rtol, np.full(y0.size, rtol * 1e-3), np.full(y0.size, 1e12),
                        time.perf_counter() + GIVE_UP, 10**7,
                    )  # fmt: skip
                    try:
                        trajectory = METHODS[name].integrate(problem)
                    except TooMuchWork:
                        trajectory = None
                        break
                    best = min(best, trajectory.wall_time_s)
                if trajectory is None or not trajectory.complete:
                    print(f"  {name:16} {rtol:8.1e} did not finish in {GIVE_UP:g} s")
                    break
                error = float((np.abs(trajectory.y[:, : system.n] - truth[:, : system.n]) / scale).max())
                curve.append((error, best))
                print(f"  {name:16} {rtol:8.1e} {trajectory.steps:7d} {error:9.2e} {best * 1e3:9.3f}")
            curves[name] = curve
        for target in TARGETS:
            ours = time_at(curves[OURS], target)
            ratios = []
            for name in SCIPYS:
                theirs = time_at(curves[name], target)
                ratios.append(f"{name} {theirs / ours:6.0f}x" if np.isfinite(theirs / ours) else f"{name}   (n/a)")
            print(f"  at error {target:.0e}: {OURS} {ours * 1e3:8.3f} ms; scipy's " + ", ".join(ratios) + " slower")


def hogs(per_core: int) -> list[subprocess.Popen]:
    """Busy loops, each in its own session (see docs/../recipes: autogroup scheduling)."""
    count = per_core * (os.cpu_count() or 1)
    return [
        subprocess.Popen([sys.executable, "-c", "while True: pass"], start_new_session=True) for _ in range(count)
    ]


def auto_under_load(per_core: int) -> None:
    started = hogs(per_core) if per_core else []
    try:
        time.sleep(2.0 if started else 0.0)
        print(f"\nauto with the server's budget (8 s), {per_core} busy processes per core, load {os.getloadavg()[0]:.1f}")
        for label, (system, k, y0, t_end) in cases().items():
            METHODS[OURS].prepare(system)
            METHODS["Vern8"].prepare(system)
            before = time.perf_counter()
            try:
                out = simulate(system, k, y0, t_end, 1000)
                what = (
                    f"{out.method}, {'complete' if out.trajectory.complete else 'incomplete'}, "
                    f"{out.trajectory.steps} steps, estimate {out.estimate.value if out.estimate else float('nan'):.2g}"
                )
            except TooMuchWork as exc:
                what = f"REFUSED: {exc}"
            print(f"  {label:28} {(time.perf_counter() - before) * 1e3:8.1f} ms  {what}")
    finally:
        for hog in started:
            hog.kill()
            hog.wait()


def main() -> None:
    if any(a in ("-h", "--help") for a in sys.argv[1:]):
        print(__doc__)
        return
    busy = int(sys.argv[sys.argv.index("--busy") + 1]) if "--busy" in sys.argv else 0
    print(f"load average at start: {os.getloadavg()[0]:.2f}")
    work_precision()
    auto_under_load(0)
    if busy:
        auto_under_load(busy)


if __name__ == "__main__":
    main()
