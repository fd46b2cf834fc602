"""Vern8's step-size rule: PI control (the kernel's) against the plain rule h err^(-1/8), error for work.

The plain rule is the same kernel compiled with BETA = 0 (then 0.9 err^-ALPHA err_prev^BETA is
0.9 err^(-1/8)), so nothing else differs.  For bench_cyrk's two cases (the pendulum at θ0 = 2.5 over
100 periods, the double pendulum with θ1 = 1 over 50 s), at rtol 1e-6 ... 1e-12 (atol = rtol/100),
each rule's right-hand-side evaluations, rejected steps and largest error of q over 1001 samples of
the whole run against the compiled DOP853 at rtol 1e-13 (its own dense output at the same times).

    .venv/bin/python -m benchmarks.bench_step_control      (compiles the plain kernel: about 30 s)
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from app.numerics.kernels import vern8
from app.numerics.kernels.common import JIT
from app.numerics.methods import METHODS, Problem
from benchmarks.bench_numerics import cases

RTOLS = [10.0**-e for e in range(6, 13)]


def plain_rule_kernel():
    """vern8.run compiled again with BETA = 0 (numba reads the module's globals as it compiles)."""
    saved = vern8.BETA, vern8.ALPHA
    vern8.BETA, vern8.ALPHA = 0.0, 0.125
    try:
        options = {**JIT, "cache": False}
        return njit(vern8.run.signatures[0], **options)(vern8.run.py_func)
    finally:
        vern8.BETA, vern8.ALPHA = saved


def compare(plain, title, system, k, y0, t_end) -> None:
    m, n = y0.size, y0.size // 2
    t = np.linspace(0.0, t_end, 1001)
    bound = np.full(m, 1e8)
    reference = (
        METHODS["DOP853-compiled"]
        .integrate(Problem(system, k, y0, t, 1e-13, np.full(m, 1e-16), bound, math.inf, 10**9))
        .y
    )
    f = system.bound("rhs")

    def run(kernel, rtol):
        y, fy, st, Y = y0.astype(float).copy(), np.empty(m), np.zeros(vern8.STATE_SIZE), np.empty((t.size, m))
        status = kernel(f, k, t, rtol, np.full(m, rtol / 100), bound, 0, 10**9, y, fy, st, Y)
        assert status == 1, status
        return np.abs(Y[:, :n] - reference[:, :n]).max(), int(st[vern8.NFEV]), int(st[vern8.REJECTED])

    print(f"\n{title}")
    print("| rtol | plain: evaluations, rejected, error | PI: evaluations, rejected, error | error plain / PI |")
    print("|---|---|---|---|")
    for rtol in RTOLS:
        ep, fp, rp = run(plain, rtol)
        ei, fi, ri = run(vern8.run, rtol)
        print(f"| {rtol:.0e} | {fp}, {rp}, {ep:.1e} | {fi}, {ri}, {ei:.1e} | {ep / ei:.2f} |")


def main() -> None:
    plain = plain_rule_kernel()
    for title, system, k, y0, t_end, _ in cases():
        compare(plain, title, system, k, y0, t_end)


if __name__ == "__main__":
    main()
