"""The default fast path: DOP853 with its whole step loop compiled."""

from __future__ import annotations

import numpy as np

from app.numerics.methods.base import Method, Problem, Trajectory, drive, finished


class CompiledDOP853(Method):
    name = "DOP853-compiled"
    family = "explicit"
    order = 8
    compiled = True
    kernel_module = "app.numerics.kernels.dop853"
    summary = "Dormand-Prince 8(5,3), adaptive steps, 7th-order dense output; the loop runs in numba"

    def _run(self, problem: Problem, stop_on_stiff: bool = False) -> Trajectory:
        from app.numerics.kernels import dop853

        rhs = problem.system.bound("rhs")
        y = problem.y0.astype(float).copy()
        fy = np.empty_like(y)
        st = np.zeros(dop853.STATE_SIZE)
        Y = np.empty((problem.t.size, y.size))
        args = (problem.k, problem.t, problem.rtol, problem.atol, problem.bound, int(stop_on_stiff))

        status = drive(
            lambda chunk: dop853.run(rhs, *args, chunk, y, fy, st, Y),
            lambda: st[dop853.STEPS],
            problem,
            self,
        )
        trajectory = finished(
            self,
            problem,
            Y,
            int(st[dop853.NEXT_OUT]),
            status,
            last=y,
            steps=int(st[dop853.STEPS]),
            rhs_evaluations=int(st[dop853.NFEV]),
            stiff_detected=bool(st[dop853.STIFF_SEEN]),
        )
        if st[dop853.REJECTED]:
            trajectory.notes.append(f"{int(st[dop853.REJECTED])} rejected steps")
        return trajectory


class CompiledVern8(Method):
    name = "Vern8"
    family = "explicit"
    order = 8
    compiled = True
    kernel_module = "app.numerics.kernels.vern8"
    summary = "Verner's 8(7) pair, adaptive steps, 7th-order dense output, stiffness test; the loop runs in numba"

    def _run(self, problem: Problem, stop_on_stiff: bool = False) -> Trajectory:
        from app.numerics.kernels import vern8

        rhs = problem.system.bound("rhs")
        y = problem.y0.astype(float).copy()
        fy = np.empty_like(y)
        st = np.zeros(vern8.STATE_SIZE)
        Y = np.empty((problem.t.size, y.size))
        args = (problem.k, problem.t, problem.rtol, problem.atol, problem.bound, int(stop_on_stiff))
        status = drive(lambda chunk: vern8.run(rhs, *args, chunk, y, fy, st, Y), lambda: st[vern8.STEPS], problem, self)
        trajectory = finished(
            self,
            problem,
            Y,
            int(st[vern8.NEXT_OUT]),
            status,
            last=y,
            steps=int(st[vern8.STEPS]),
            rhs_evaluations=int(st[vern8.NFEV]),
            stiff_detected=bool(st[vern8.STIFF_SEEN]),
        )
        if st[vern8.REJECTED]:
            trajectory.notes.append(f"{int(st[vern8.REJECTED])} rejected steps")
        return trajectory
