"""The compiled explicit pairs: Verner's efficient 8(7) (auto's default) and DOP853.

Both kernels share one interface (``run``, ``STATE_SIZE`` and the state's slots), so one
driver serves them; a method names only its kernel."""

from __future__ import annotations

from typing import Any

import numpy as np

from app.numerics.methods.base import Method, Problem, Trajectory, run_kernel


class CompiledExplicit(Method):
    """An adaptive explicit pair whose whole step loop runs in numba (``kernel_module``)."""

    family = "explicit"
    compiled = True

    def _run(self, problem: Problem, **options: Any) -> Trajectory:
        # stop_on_stiff: give up at the first sign of stiffness (auto then tries an implicit method)
        stop_on_stiff = bool(options.get("stop_on_stiff", False))
        kernel = self.loop()
        rhs = problem.system.bound("rhs")
        y = np.array(problem.y0, dtype=np.float64)  # the kernel's own copy, advanced in place
        fy = np.empty_like(y)
        st = np.zeros(kernel.STATE_SIZE)
        Y = np.empty((problem.t.size, y.size))
        args = (problem.k, problem.t, problem.rtol, problem.atol, problem.bound, int(stop_on_stiff))

        return run_kernel(
            self,
            problem,
            kernel,
            lambda chunk: kernel.run_at(rhs.address, *args, chunk, y, fy, st, Y),  # run, f by its address
            (st, Y, y),
            stiff_detected=kernel.STIFF_SEEN,
        )


class CompiledDOP853(CompiledExplicit):
    name = "DOP853-compiled"
    label = "Dormand–Prince 8(5,3)"
    order = 8
    kernel_module = "app.numerics.kernels.dop853"
    summary = "Dormand-Prince 8(5,3), adaptive steps, 7th-order dense output; the loop runs in numba"


class CompiledVern8(CompiledExplicit):
    name = "Vern8"
    label = "Verner 8(7)"
    order = 8
    kernel_module = "app.numerics.kernels.vern8"
    summary = (
        "Verner's efficient 8(7) pair, adaptive steps, 8th-order dense output, stiffness test; the loop runs in numba"
    )
