"""The default simulation path against solve_ivp(RK45) with sympy.lambdify(modules="numpy"), at equal error.

Baseline: the engine's accelerations through ``sympy.lambdify(..., modules="numpy")`` (its default
printing, no cse) and ``scipy.integrate.solve_ivp(method="RK45")``: what one would write by hand.
Ours: ``app.numerics.simulate.simulate(method="auto")`` (analysis, choice, the compiled loop), with
and without the second run that gives the error estimate.

Each side's tolerance is the loosest on a grid (10^(-k/4), atol = rtol/100) whose final-state error
max_k |q_k(t_end) - q_k,ref(t_end)| is at most 1e-8; the time is the minimum of several runs.  The
reference is exact for the pendulum (Jacobi elliptic functions, mpmath) and for the double pendulum
the compiled DOP853 at rtol 1e-13, checked against Gauss-Legendre.  Goal: ratio >= 100 on each.

Also printed: CyRK's DOP853, Vern7 and Vern8 side by side with our DOP853 and Vern8 kernels and the
default path, at the same error, against the floor of bare right-hand-side calls (bench_cyrk); the cost of one right-hand-side call (cse'd scalar code vs lambdify), and the energy
error of the symplectic path against DOP853 over 10^4 pendulum periods, decade by decade.

    .venv/bin/python -m benchmarks.bench_numerics
"""

from __future__ import annotations

import math
import time

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from app.engine.derivation.derive import derive
from app.numerics.exact import pendulum
from app.numerics.methods import METHODS, NONSTIFF, Problem
from app.numerics.observables import build
from app.numerics.simulate import simulate
from app.numerics.system import NumericSystem, numeric_system
from app.scenes import SCENES
from tests.numerics.extreme_cases import pendulum_period
from tests.numerics.systems import DOUBLE_PENDULUM

TARGET = 1e-8
GRID = [10.0 ** (-k / 4) for k in range(12, 57)]  # 1e-3 ... 1e-14


def best_time(run, repeats: int = 5, budget: float = 20.0) -> float:
    run()  # warm-up
    times = []
    start = time.perf_counter()
    while len(times) < repeats and (not times or time.perf_counter() - start < budget):
        t0 = time.perf_counter()
        run()
        times.append(time.perf_counter() - t0)
    return min(times)


def lambdify_rhs(system: NumericSystem, k: np.ndarray):
    d = system.derivation
    table = d.table
    f = sp.lambdify((table.t, *table.q, *table.qd, *table.params), list(d.equations.accelerations), modules="numpy")
    n = system.n

    def fun(t, y):
        return np.concatenate([y[n:], f(t, *y, *k)])

    return fun


def baseline_final(fun, y0, t_end, rtol):
    return solve_ivp(fun, (0.0, t_end), y0, method="RK45", rtol=rtol, atol=rtol / 100).y[:, -1]


def ours_final(system, k, y0, t_end, rtol, estimate=False):
    return simulate(system, k, y0, t_end, 2, "auto", rtol, rtol / 100, wall_seconds=120, estimate=estimate)


def loosest(error_of) -> float:
    for rtol in GRID:
        if error_of(rtol) <= TARGET:
            return rtol
    raise RuntimeError("no tolerance on the grid reaches the target")


def compare(label, system, k, y0, t_end, reference) -> None:
    n = system.n
    fun = lambdify_rhs(system, k)
    rtol_base = loosest(lambda r: np.max(np.abs(baseline_final(fun, y0, t_end, r)[:n] - reference[:n])))
    rtol_ours = loosest(
        lambda r: np.max(np.abs(ours_final(system, k, y0, t_end, r).trajectory.y[-1, :n] - reference[:n]))
    )
    out = ours_final(system, k, y0, t_end, rtol_ours)
    err_base = np.max(np.abs(baseline_final(fun, y0, t_end, rtol_base)[:n] - reference[:n]))
    err_ours = np.max(np.abs(out.trajectory.y[-1, :n] - reference[:n]))
    t_base = best_time(lambda: baseline_final(fun, y0, t_end, rtol_base), repeats=3)
    t_ours = best_time(lambda: ours_final(system, k, y0, t_end, rtol_ours))
    t_est = best_time(lambda: ours_final(system, k, y0, t_end, rtol_ours, estimate=True))
    print(f"\n{label}: final-state error target {TARGET:g}")
    print("| path | method | rtol | final error | time s | ratio |")
    print("|---|---|---|---|---|---|")
    print(f"| solve_ivp RK45 + lambdify(numpy) | RK45 | {rtol_base:.1e} | {err_base:.1e} | {t_base:.4f} | 1 |")
    print(
        f"| default (auto) | {out.method} | {rtol_ours:.1e} | {err_ours:.1e} | {t_ours:.5f} | {t_base / t_ours:.0f} |"
    )
    print(
        f"| default (auto) with error estimate | {out.method} | {rtol_ours:.1e} | {err_ours:.1e} | {t_est:.5f} | "
        f"{t_base / t_est:.0f} |"
    )


def rhs_call_costs(system: NumericSystem, k: np.ndarray, y: np.ndarray) -> None:
    fun = lambdify_rhs(system, k)
    floats = k.tolist()
    out = np.empty(y.size)
    rhs = system.python["rhs"]
    calls = 20000
    t_lambdify = best_time(lambda: [fun(0.0, y) for _ in range(calls)], 3) / calls
    t_scalar = best_time(lambda: [rhs(0.0, y.tolist(), floats, out) for _ in range(calls)], 3) / calls
    # per step of the compiled DOP853 loop (12 right-hand sides each), from a long run
    run = METHODS["DOP853-compiled"]
    t = np.array([0.0, 2000.0])
    problem = Problem(system, k, y, t, 1e-10, np.full(y.size, 1e-12), np.full(y.size, 1e8), math.inf, 10**9)
    trajectory = run.integrate(problem)
    per_step = best_time(lambda: run.integrate(problem), 3) / trajectory.steps
    print(
        f"| {system.coordinates} | {t_lambdify * 1e6:.2f} µs | {t_scalar * 1e6:.2f} µs | "
        f"{t_lambdify / t_scalar:.1f} | {per_step * 1e9:.0f} ns |"
    )


def energy_decades() -> None:
    s = numeric_system(derive(SCENES["simple-pendulum"].system))
    k = np.array([1.0, 9.81, 1.0])
    y0 = np.array([2.5, 0.0])
    period = pendulum_period(2.5)
    periods = 1e4
    samples = 19_391  # not a divisor of the 2e4 half-periods: samples fall at every phase of the swing
    obs = build(s)
    print(f"\nEnergy error |E - E0| / |E0| over 10^4 periods (θ0 = 2.5, period {period:.4f} s), rtol = 1e-8:")
    print("| method | periods 1-10 | 10-100 | 100-1000 | 1000-10000 | last / first decade | time s |")
    print("|---|---|---|---|---|---|---|")
    for method in ("Yoshida4", "Gauss-Legendre", NONSTIFF, "DOP853-compiled"):
        start = time.perf_counter()
        out = simulate(s, k, y0, periods * period, samples, method, 1e-8, 1e-10, wall_seconds=300, estimate=False)
        seconds = time.perf_counter() - start
        tr = out.trajectory
        energy = obs.evaluate(tr.t, tr.y, k)["energy"]
        error = np.abs(energy - energy[0]) / abs(energy[0])
        cells = []
        for low, high in ((1, 10), (10, 100), (100, 1000), (1000, 10000)):
            window = (tr.t >= low * period) & (tr.t <= high * period)
            cells.append(float(error[window].max()))
        print(
            f"| {method} | "
            + " | ".join(f"{c:.1e}" for c in cells)
            + f" | {cells[-1] / cells[0]:.2g} | {seconds:.2f} |"
        )


def cases() -> list[tuple[str, NumericSystem, np.ndarray, np.ndarray, float, np.ndarray]]:
    """The equal-error comparisons (title, system, parameters, start, t_end, reference final state),
    shared with benchmarks/bench_cyrk.py: the pendulum at θ0 = 2.5 over 100 periods against its exact
    solution, and the double pendulum (θ1 = 1, others 0) to t = 50 s against DOP853 at rtol 1e-13."""
    pend = numeric_system(derive(SCENES["simple-pendulum"].system))
    k = np.array([1.0, 9.81, 1.0])
    y0 = np.array([2.5, 0.0])
    t_end = 100 * pendulum_period(2.5)
    reference = pendulum(9.81, 2.5, 0.0)(np.array([t_end]))[0]
    dp = numeric_system(derive(DOUBLE_PENDULUM))
    kd = np.array([1.0, 1.0, 1.0, 1.0, 9.81])
    yd = np.array([1.0, 0.0, 0.0, 0.0])
    problem = Problem(dp, kd, yd, np.array([0.0, 50.0]), 1e-13, np.full(4, 1e-16), np.full(4, 1e8), math.inf, 10**9)
    ref = METHODS["DOP853-compiled"].integrate(problem).y[-1]
    return [
        (f"Pendulum θ0 = 2.5, 100 periods (t = {t_end:.2f} s)", pend, k, y0, t_end, reference),
        ("Double pendulum (θ1 = 1, others 0), t = 50 s", dp, kd, yd, 50.0, ref),
    ]


def main() -> None:
    (pend_case, dp_case) = cases()
    compare(*pend_case)
    _, dp, kd, yd, t_end, ref = dp_case
    problem = Problem(dp, kd, yd, np.array([0.0, t_end]), 1e-12, np.full(4, 1e-16), np.full(4, 1e8), math.inf, 10**9)
    check = METHODS["Gauss-Legendre"].integrate(problem).y[-1]
    print(
        f"\nDouble pendulum reference: DOP853 at rtol 1e-13; Gauss-Legendre agrees to {np.max(np.abs(ref - check)[:2]):.1e}"
    )
    compare(*dp_case)
    _, pend, k, y0, _, _ = pend_case

    print("\nOne right-hand-side call (from Python) and one compiled DOP853 step:")
    print("| system | lambdify(numpy) | cse'd scalar code | ratio | compiled step |")
    print("|---|---|---|---|---|")
    rhs_call_costs(pend, k, y0)
    rhs_call_costs(dp, kd, yd)

    energy_decades()

    # our kernels and default path against CyRK's C++ integrators at the same error (benchmarks/bench_cyrk.py)
    from benchmarks import bench_cyrk

    bench_cyrk.main()


if __name__ == "__main__":
    main()
