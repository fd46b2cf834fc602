"""Structure-preserving fixed-step methods: Störmer-Verlet, Yoshida-4, Gauss-Legendre.

A symplectic method keeps the energy error bounded over very long runs only
with a constant step, so the step is chosen once, before the run, to meet the
tolerance: the local error of one step is estimated by step doubling,

    e_h ~ (Phi_h(y) - Phi_{h/2}(Phi_{h/2}(y))) / (1 - 2^-p),

at states spread along the motion (the ``pilot``: a quick compiled DOP853
pass at the same tolerance), and h is scaled by (0.9 / max e_h)^(1/(p+1))
until the largest scaled error (atol + rtol |y|) is about one.  The step then
divides every interval between samples exactly.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.polynomial import Polynomial
from numpy.polynomial.legendre import leggauss

from app.numerics.methods.base import Method, Problem, Trajectory, drive, finished
from app.numerics.system import NumericSystem

PILOT_STATES = 96


def gauss_tableau(s: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A, b, c of the s-stage Gauss collocation method, and the extrapolation matrix E."""
    x, _ = leggauss(s)
    c = (x + 1.0) / 2.0
    basis = []
    for j in range(s):
        # l_j(x) = prod_{m != j} (x - c_m) / (c_j - c_m)
        others = np.delete(c, j)
        basis.append(Polynomial.fromroots(others) / np.prod(c[j] - others))
    # a_ij = integral_0^{c_i} l_j,  b_j = integral_0^1 l_j,  E_ij = l_j(1 + c_i)
    A = np.array([[lj.integ()(ci) - lj.integ()(0.0) for lj in basis] for ci in c])
    b = np.array([lj.integ()(1.0) - lj.integ()(0.0) for lj in basis])
    E = np.array([[lj(1.0 + ci) for lj in basis] for ci in c])
    return np.ascontiguousarray(A), b, c, np.ascontiguousarray(E)


class FixedStep(Method):
    family = "symplectic"
    compiled = True

    def start_state(self, problem: Problem, t: float, y: np.ndarray) -> np.ndarray:
        return y.astype(float).copy()

    def kernel(self, problem: Problem, t: np.ndarray, state: np.ndarray, substeps: int, chunked: bool):
        """Run the compiled loop over sample times t; return (Y, filled, status, steps, nfev, extra)."""
        raise NotImplementedError

    def local_errors(self, problem: Problem, times: np.ndarray, states: np.ndarray, h: float) -> np.ndarray:
        """Scaled local error of one step of size h from each (t, y), by step doubling (compiled)."""
        raise NotImplementedError

    def prepare(self, system: NumericSystem) -> None:
        from app.numerics.methods.explicit import CompiledDOP853

        super().prepare(system)
        CompiledDOP853().prepare(system)  # the pilot pass

    def ready(self, system: NumericSystem) -> bool:
        from app.numerics.methods.explicit import CompiledDOP853

        return super().ready(system) and CompiledDOP853().ready(system)

    def pilot(self, problem: Problem) -> tuple[np.ndarray, np.ndarray, float]:
        """States along the motion and a first step size, from a quick compiled DOP853 pass."""
        from app.numerics.methods.explicit import CompiledDOP853

        grid = np.linspace(problem.t[0], problem.t_end, PILOT_STATES + 1)
        quick = Problem(**{**problem.__dict__, "t": grid})
        run = CompiledDOP853().integrate(quick)
        return run.t, run.y, (run.t_reached - problem.t[0]) / max(run.steps, 1)

    def choose_substeps(self, problem: Problem) -> tuple[int, float]:
        t_pilot, y_pilot, mean_step = self.pilot(problem)
        pick = np.unique(np.linspace(0, len(t_pilot) - 1, min(PILOT_STATES, len(t_pilot))).astype(int))
        spacing = float(np.max(np.diff(problem.t)))
        # a pilot that stopped at once (a runaway, a singular start) gives no step size to start from
        h = min(spacing, mean_step) if mean_step > 0 and math.isfinite(mean_step) else spacing / 1000.0
        times = np.ascontiguousarray(t_pilot[pick], dtype=float)
        states = np.ascontiguousarray(y_pilot[pick], dtype=float)
        for _ in range(8):
            err = float(np.max(self.local_errors(problem, times, states, h)))
            if err == 0.0:
                factor = 4.0
            elif not math.isfinite(err):
                factor = 0.05
            else:
                factor = min(4.0, max(0.05, 0.9 * err ** (-1.0 / (self.order + 1))))
            h = min(h * factor, spacing)
            if 0.8 <= factor <= 1.25 or (factor > 1.0 and h >= spacing):
                break
        substeps = max(1, math.ceil(spacing / h))
        return substeps, spacing / substeps

    def _run(self, problem: Problem, **options: Any) -> Trajectory:
        # substeps: steps per interval between samples (the error reference asks for twice the run's)
        substeps: int | None = options.get("substeps")
        if substeps is None:
            substeps, h = self.choose_substeps(problem)
        total = (problem.t.size - 1) * substeps
        if total > problem.max_steps:
            raise self.too_much(
                problem, f"{total:,} steps of {self.name} at this tolerance (limit {problem.max_steps:,})"
            )
        from app.numerics.kernels.common import NO_CONVERGENCE

        retries = []
        for _ in range(4):
            start = self.start_state(problem, problem.t[0], problem.y0)
            Y, filled, status, steps, nfev, notes = self.kernel(problem, problem.t, start, substeps, True)
            if status != NO_CONVERGENCE:
                break
            # the stage equations did not converge: the step is too long for the local stiffness
            retries.append(f"stage iteration failed near t = {problem.t[filled - 1]:.4g} s, step halved")
            substeps *= 2
            if (problem.t.size - 1) * substeps > problem.max_steps:
                break
        trajectory = finished(self, problem, Y, filled, status, steps=steps, rhs_evaluations=nfev)
        trajectory.step_size = float(np.max(np.diff(problem.t))) / substeps
        trajectory.substeps = substeps
        trajectory.notes.extend(retries + notes)
        return trajectory


class Composition(FixedStep):
    weights = np.array([1.0])
    kernel_module = "app.numerics.kernels.composition"

    def applicable(self, system: NumericSystem) -> str | None:
        if system.separable:
            return None
        return (
            "it needs a separable Hamiltonian H = T(p) + U(q) with a constant mass matrix and no "
            "velocity- or time-dependent forces; use Gauss-Legendre (symplectic for any Hamiltonian)"
        )

    def local_errors(self, problem: Problem, times: np.ndarray, states: np.ndarray, h: float) -> np.ndarray:
        from app.numerics.kernels import composition as kc

        out = np.empty(len(times))
        rhs = problem.system.bound("rhs")
        kc.local_errors(rhs, problem.k, self.weights, times, states, h, problem.atol, problem.rtol, self.order, out)
        return out

    def kernel(self, problem: Problem, t: np.ndarray, state: np.ndarray, substeps: int, chunked: bool):
        from app.numerics.kernels import composition as kc

        rhs = problem.system.bound("rhs")
        n = problem.system.n
        acc = np.empty(n)
        comp = np.zeros(2 * n)
        st = np.zeros(kc.STATE_SIZE)
        Y = np.empty((t.size, 2 * n))
        args = (problem.k, t, self.weights, substeps, problem.bound)
        if chunked:
            status = drive(
                lambda chunk: kc.run(rhs, *args, chunk, state, acc, comp, st, Y), lambda: st[kc.STEPS], problem, self
            )
        else:
            status = kc.run(rhs, *args, 1 << 40, state, acc, comp, st, Y)
        return Y, int(st[kc.INTERVAL]) + 1, status, int(st[kc.STEPS]), int(st[kc.NFEV]), []


class StormerVerlet(Composition):
    name = "Verlet"
    label = "Störmer–Verlet, symplectic"
    order = 2
    summary = "Störmer-Verlet (leapfrog), order 2, symplectic, fixed step; separable H only"
    weights = np.array([1.0])


_X1 = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))


class Yoshida4(Composition):
    name = "Yoshida4"
    label = "Yoshida 4, symplectic"
    order = 4
    summary = "Yoshida's triple-jump composition of Verlet, order 4, symplectic, fixed step; separable H only"
    # w = (x1, x0, x1) with x0 = 1 - 2 x1 = -2^(1/3) x1
    weights = np.array([_X1, 1.0 - 2.0 * _X1, _X1])


class GaussLegendre(FixedStep):
    name = "Gauss-Legendre"
    label = "Gauss–Legendre 6, symplectic"
    kernel_module = "app.numerics.kernels.gauss"
    implicit = True
    stages = 3
    order = 6
    summary = "3-stage Gauss-Legendre collocation on (q, p), order 6, symplectic for any Hamiltonian, fixed step"

    def applicable(self, system: NumericSystem) -> str | None:
        if system.legendre_linear:
            return None
        return (
            "it steps in (q, p), and here ∂²L/∂q̇² depends on the velocities, so p = ∂L/∂q̇ is not linear in q̇ "
            "and q̇(q, p) has no form to step with; use an adaptive method (Vern8, DOP853 or Radau)"
        )

    def __init__(self) -> None:
        self.A, self.b, self.c, self.E = gauss_tableau(self.stages)

    def start_state(self, problem: Problem, t: float, y: np.ndarray) -> np.ndarray:
        # z = (q, p) with p = dL/dq_dot from the engine
        n = problem.system.n
        return np.concatenate([y[:n], problem.system.momenta(t, y, problem.k)])

    def local_errors(self, problem: Problem, times: np.ndarray, states: np.ndarray, h: float) -> np.ndarray:
        from app.numerics.kernels import gauss as kg

        # errors measured on z = (q, p), the variables the method advances
        z = np.array([self.start_state(problem, t, y) for t, y in zip(times, states, strict=True)])
        out = np.empty(len(times))
        ham = problem.system.bound("ham")
        kg.local_errors(
            ham,
            problem.k,
            self.A,
            self.b,
            self.c,
            self.E,
            times,
            z,
            h,
            self.floor(problem),
            problem.rtol,
            self.order,
            out,
        )
        return out

    def floor(self, problem: Problem) -> np.ndarray:
        """Absolute tolerance on z = (q, p): atol for q, and for p the largest atol."""
        n = problem.system.n
        return np.concatenate([problem.atol[:n], np.full(n, float(np.max(problem.atol)))])

    def kernel(self, problem: Problem, t: np.ndarray, state: np.ndarray, substeps: int, chunked: bool):
        from app.numerics.kernels import gauss as kg

        ham = problem.system.bound("ham")
        m = state.size
        comp = np.zeros(m)
        Kprev = np.zeros((self.stages, m))
        st = np.zeros(kg.STATE_SIZE)
        Y = np.empty((t.size, m))
        floor = self.floor(problem)
        args = (problem.k, t, self.A, self.b, self.c, self.E, substeps, problem.bound, floor)
        if chunked:
            status = drive(
                lambda chunk: kg.run(ham, *args, chunk, state, comp, Kprev, st, Y), lambda: st[kg.STEPS], problem, self
            )
        else:
            status = kg.run(ham, *args, 1 << 40, state, comp, Kprev, st, Y)
        notes = []
        if st[kg.STEPS]:
            notes.append(
                f"{st[kg.SWEEPS] / st[kg.STEPS]:.1f} fixed-point sweeps per step (at most {int(st[kg.MAX_SWEEPS_SEEN])})"
            )
        filled = int(st[kg.INTERVAL]) + 1
        return Y, filled, status, int(st[kg.STEPS]), int(st[kg.NFEV]), notes
