"""Our compiled kernels and default path side by side with CyRK (Cython/C++ integrators), at equal error.

Each method runs at the loosest tolerance on the grid of bench_numerics (rtol =
10^(-k/4), atol = rtol/100) whose final-state error is at most 1e-8, on the
pendulum (θ0 = 2.5, 100 periods, exact reference) and the double pendulum
(θ1 = 1, θ2 = 0, 50 s, reference DOP853 at rtol 1e-13).  Every method calls the
same right-hand side: the engine's generated function compiled by numba (CyRK
through a numba cfunc wrapper).  The floor is the time of the same number of
bare right-hand-side calls through a function pointer in a compiled loop.
Times are the minimum of ``REPEATS`` rounds, each round running every path and
floor once in turn, all in one process (ratios within one run: the machine is
shared, absolute times drift; with 5 runs a busy machine moved single figures
by 30 % from run to run, and timing one path after another let a slow minute
fall on one of them).

    .venv/bin/python -m benchmarks.bench_cyrk
"""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable

import numpy as np
from CyRK import cyjit, nbsolve2_ivp
from numba import njit, types

from app.numerics import choose
from app.numerics.kernels.common import F64, I64, RHS, VEC, address
from app.numerics.methods import METHODS, Problem
from app.numerics.plan import plan
from app.numerics.simulate import simulate
from app.numerics.system import NumericSystem
from benchmarks.bench_numerics import GRID, TARGET, cases

OURS = ("DOP853-compiled", "Vern8")
CYRK = ("DOP853", "Vern7", "Vern8")
REPEATS = 25


@njit(types.void(RHS, F64, VEC, VEC, VEC, I64))
def bare_calls(f, t, y, k, out, count):
    for _ in range(count):
        f(t, address(y), address(k), address(out))
        y[0] += 1e-300 * out[0]  # a data dependence, so the calls cannot be hoisted


def cyrk_rhs(system: NumericSystem):
    # CyRK's callback takes raw pointers too (dy, t, y, args): the generated function is called as the kernels call it
    rhs = system.compiled().rhs

    @cyjit
    def f(dy, t, y, args):
        rhs(t, y, args, dy)

    return f


@njit
def cyrk_final(address, t_end, y0, method_id, args, rtol, atol):
    method = "DOP853" if method_id == 0 else ("Vern7" if method_id == 1 else "Vern8")
    sol = nbsolve2_ivp(address, (0.0, t_end), y0, method=method, args=args, rtol=rtol, atol=atol)
    y = sol.y
    last = y[:, y.shape[1] - 1].copy()
    steps = sol.steps_taken
    sol.free()
    return last, steps


def ours_problem(system, k, y0, t_end, rtol):
    m = y0.size
    return Problem(
        system, k, y0, np.array([0.0, t_end]), rtol, np.full(m, rtol / 100), np.full(m, 1e8), math.inf, 10**9
    )


def loosest(error_of) -> float:
    for rtol in GRID:
        if error_of(rtol) <= TARGET:
            return rtol
    raise RuntimeError("no tolerance on the grid reaches the target")


def interleaved_best(runs: dict[str, Callable[[], object]], rounds: int = REPEATS) -> dict[str, float]:
    """The minimum time of each callable over ``rounds`` rounds that run every one once, in turn: a slow
    moment of the shared machine hits every path alike (timed one path after another, a pendulum's
    CyRK Vern8 moved between 1.55 and 2.38 ms from run to run, and the ratios with it)."""
    for run in runs.values():
        run()  # warm-up
    best = dict.fromkeys(runs, math.inf)
    for _ in range(rounds):
        for name, run in runs.items():
            start = time.perf_counter()
            run()
            best[name] = min(best[name], time.perf_counter() - start)
    return best


def side_by_side(label, system, k, y0, t_end, reference) -> dict[str, float]:
    n = system.n
    rows = []  # path, rtol, final error, steps, evaluations (ours)
    runs: dict[str, Callable[[], object]] = {}
    out = np.empty(y0.size)
    rhs = system.bound("rhs")  # as the kernels get it

    def floor_of(evaluations: int) -> Callable[[], object]:
        return lambda: bare_calls(rhs, 0.0, y0.copy(), k, out, evaluations)

    for name in OURS:
        method = METHODS[name]
        rtol = loosest(
            lambda r, method=method: np.abs(
                method.integrate(ours_problem(system, k, y0, t_end, r)).y[-1, :n] - reference[:n]
            ).max()
        )
        run = method.integrate(ours_problem(system, k, y0, t_end, rtol))
        path = f"ours {name} (kernel from Python)"
        runs[path] = lambda rtol=rtol, method=method: method.integrate(ours_problem(system, k, y0, t_end, rtol))
        runs[f"floor of {path}"] = floor_of(run.rhs_evaluations)
        rows.append((path, rtol, np.abs(run.y[-1, :n] - reference[:n]).max(), run.steps, run.rhs_evaluations))

    def auto(r):
        return simulate(system, k, y0, t_end, 2, "auto", r, r / 100, wall_seconds=120, estimate=False)

    rtol = loosest(lambda r: np.abs(auto(r).trajectory.y[-1, :n] - reference[:n]).max())
    outcome = auto(rtol)
    tr = outcome.trajectory
    path = f"ours default path (auto → {outcome.method})"
    runs[path] = lambda rtol=rtol: auto(rtol)
    runs[f"floor of {path}"] = floor_of(tr.rhs_evaluations)
    rows.append((path, rtol, np.abs(tr.y[-1, :n] - reference[:n]).max(), tr.steps, tr.rhs_evaluations))

    address = cyrk_rhs(system).address
    for method_id, name in enumerate(CYRK):

        def final(r, method_id=method_id):
            return cyrk_final(address, t_end, y0, method_id, k, r, r / 100)

        rtol = loosest(lambda r, final=final: np.abs(final(r)[0][:n] - reference[:n]).max())
        last, steps = final(rtol)
        runs[f"CyRK {name}"] = lambda rtol=rtol, final=final: final(rtol)
        rows.append((f"CyRK {name}", rtol, np.abs(last[:n] - reference[:n]).max(), int(steps), None))

    best = interleaved_best(runs)
    rows = [(*row, best[row[0]], best.get(f"floor of {row[0]}")) for row in rows]

    print(f"\n{label}: final-state error target {TARGET:g}")
    print("| path | rtol | final error | steps | RHS evaluations | time ms | floor ms | time / floor |")
    print("|---|---|---|---|---|---|---|---|")
    for path, rtol, error, steps, nfev, seconds, floor_s in rows:
        nf = "" if nfev is None else f"{nfev}"
        fl = "" if floor_s is None else f"{floor_s * 1e3:.3f}"
        ratio = "" if floor_s is None else f"{seconds / floor_s:.2f}"
        print(f"| {path} | {rtol:.1e} | {error:.1e} | {steps} | {nf} | {seconds * 1e3:.3f} | {fl} | {ratio} |")
    fastest_cyrk = min(r[5] for r in rows if r[0].startswith("CyRK"))
    default = next(r for r in rows if r[0].startswith("ours default"))
    print(
        f"\ndefault path / fastest CyRK: {default[5] / fastest_cyrk:.2f} (target <= 1); "
        f"default path / its floor: {default[5] / default[6]:.2f} (target <= 1.3)"
    )
    our_kernel = next(r for r in rows if r[0] == "ours Vern8 (kernel from Python)")
    print(f"default path - our Vern8 kernel: {(default[5] - our_kernel[5]) * 1e3:.3f} ms; of it:")
    plan_costs(system, k, y0, t_end, default[1], runs["CyRK Vern8"])
    return {r[0]: r[5] for r in rows}


def plan_costs(system, k, y0, t_end, rtol, between: Callable[[], object], rounds: int = REPEATS) -> None:
    """The plan (``auto``'s analysis of the start and its choice) and the analysis alone, each timed right
    after a CyRK run, as in the interleaved rounds (cold caches), and back to back (warm)."""
    atol = np.full(y0.size, rtol / 100)
    jacobian = choose.jacobian(system, 0.0, y0, k)
    parts = {
        "the plan": lambda: plan(system, k, y0, t_end, 2, "auto", rtol, rtol / 100, False, True),
        "the analysis of the start": lambda: choose.analyse(system, k, y0, t_end, rtol, atol),
        "its eigenvalues": lambda: choose.eigenvalues(jacobian),
        "its right-hand side call": lambda: system.f(0.0, y0, k),
    }
    for name, part in parts.items():
        cold, warm = [], []
        for _ in range(rounds):
            between()
            start = time.perf_counter()
            part()
            cold.append(time.perf_counter() - start)
        for _ in range(rounds):
            start = time.perf_counter()
            part()
            warm.append(time.perf_counter() - start)
        print(f"  {name}: {statistics.median(cold) * 1e6:.0f} us after a CyRK run, {min(warm) * 1e6:.0f} us warm")


def main() -> None:
    for case in cases():
        side_by_side(*case)


if __name__ == "__main__":
    main()
