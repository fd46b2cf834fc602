"""The compiled implicit method: Radau IIA of order 5 with the engine's Jacobian (``auto``'s pick when stiff).

The step loop (``app.numerics.kernels.radau``) runs in numba like the explicit pairs', under
the same driver (chunks between which the deadline and the step limit are checked); the
Jacobian dF/dy is the engine's expressions differentiated, generated and compiled as the
right-hand side is (``NumericSystem.compiled_jacobian``), or forward differences inside the
kernel for a system whose accelerations are solved numerically (no Jacobian generated).
"""

from __future__ import annotations

import importlib
from typing import Any

import numpy as np

from app.numerics.methods.base import Method, Problem, Trajectory, run_kernel
from app.numerics.system import NumericSystem


class CompiledRadau(Method):
    name = "Radau-compiled"
    label = "Radau IIA, implicit"
    family = "implicit"
    order = 5
    compiled = True
    implicit = True
    kernel_module = "app.numerics.kernels.radau"
    summary = (
        "Radau IIA order 5 (Hairer and Wanner's RADAU5), implicit, with the engine's exact Jacobian; "
        "the loop runs in numba (stiff problems)"
    )

    def prepare(self, system: NumericSystem) -> None:
        super().prepare(system)
        system.compiled_jacobian()

    def ready(self, system: NumericSystem) -> bool:
        return super().ready(system) and system.is_jacobian_compiled()

    def _run(self, problem: Problem, **options: Any) -> Trajectory:
        kernel = importlib.import_module(self.kernel_module)
        system = problem.system
        rhs = system.bound("rhs")
        has_jac = system.has_jacobian
        # without a generated Jacobian the kernel differences rhs itself; the argument is then unused
        jac = system.bound("jac") if has_jac else rhs
        m = problem.y0.size
        y = problem.y0.astype(float).copy()
        fy = np.empty(m)
        st = np.zeros(kernel.STATE_SIZE)
        Y = np.empty((problem.t.size, m))
        J = np.empty((m, m))
        Q = np.zeros((4, m))
        args = (problem.k, problem.t, problem.rtol, problem.atol, problem.bound)

        trajectory = run_kernel(
            self,
            problem,
            kernel,
            lambda chunk: kernel.run(rhs, jac, int(has_jac), *args, chunk, y, fy, st, Y, J, Q),
            (st, Y, y),
        )
        source = "the engine's" if has_jac else "forward differences"
        trajectory.notes.insert(
            0, f"{int(st[kernel.NJEV])} Jacobian evaluations ({source}), {int(st[kernel.NLU])} LU decompositions"
        )
        return trajectory
