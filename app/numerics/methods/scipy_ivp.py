"""scipy's ``solve_ivp`` methods (DOP853, RK45, Radau, BDF, LSODA) under the same rules.

The right-hand side is the generated scalar-math function (plain Python:
scipy calls back into Python at every step anyway).  The budget is enforced
in the step loop (scipy's ``OdeSolver.step``, the loop ``solve_ivp`` runs) and,
for long Newton iterations, inside the callback every 64 calls, so even a
method that never finishes (LSODA not switching to its stiff mode, RK45 on a
stiff spring) is stopped at the deadline.  Samples come from each solver's
dense output; a state outside its bound ends the run (a runaway).
"""

from __future__ import annotations

import time
from types import ModuleType

import numpy as np

from app import late
from app.numerics.methods.base import Method, Problem, Trajectory, cut_short, outside_names


def scipy_integrate() -> ModuleType:
    """scipy.integrate, imported on first use (0.5-1 s, which a server answering from its compiled
    kernels need not pay at start) and by one thread at a time (``app.late``)."""
    return late.module("scipy.integrate")


class _OutOfBudget(Exception):
    pass


class _NotEvaluable(Exception):
    pass


class ScipyMethod(Method):
    """A scipy ``OdeSolver`` class driven step by step; a subclass names the solver and describes it."""

    compiled = False
    solver: str  # the OdeSolver class's name in scipy.integrate

    def solver_class(self) -> type:
        return getattr(scipy_integrate(), self.solver)

    def _run(self, problem: Problem, **options) -> Trajectory:
        rhs = problem.system.python["rhs"]
        k = problem.k
        floats = k.tolist()
        m = problem.y0.size
        calls = [0]
        deadline = problem.deadline

        def fun(t, y):
            calls[0] += 1
            if calls[0] % 64 == 0 and time.perf_counter() > deadline:
                raise _OutOfBudget("the wall-clock budget ran out")
            out = np.empty(m)
            try:
                rhs(t, y.tolist(), floats, out)
            except (ZeroDivisionError, ValueError, OverflowError) as exc:
                raise _NotEvaluable(f"{exc} at t = {t:.6g} s") from None
            return out

        t_out = problem.t
        Y = np.empty((t_out.size, m))
        Y[0] = problem.y0
        filled = 1
        steps = 0
        stop = ""
        solver = None
        try:
            options = {}
            if self.implicit and "jac" in problem.system.python:
                # the engine's own Jacobian (differentiated, not simplified) instead of finite differences
                options["jac"] = lambda t, y: problem.system.jacobian(t, y, k)
            solver = self.solver_class()(
                fun, t_out[0], problem.y0, problem.t_end, rtol=problem.rtol, atol=problem.atol, **options
            )
            while solver.status == "running":
                # scipy's step-size and Jacobian heuristics may overflow on the way to a failure it reports
                with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                    message = solver.step()
                if solver.status == "failed":
                    where = f"t = {solver.t:.6g} s"
                    stop = f"{self.name} stopped at {where}: {message}"
                    break
                steps += 1
                if steps > problem.max_steps:
                    raise _OutOfBudget(f"more than {problem.max_steps:,} steps")
                upto = int(np.searchsorted(t_out, solver.t, side="right"))
                if upto > filled:
                    with np.errstate(over="ignore", invalid="ignore"):
                        Y[filled:upto] = solver.dense_output()(t_out[filled:upto]).T
                    filled = upto
                if not np.all(np.abs(solver.y) <= problem.bound):
                    outside = np.any(~(np.abs(Y[:filled]) <= problem.bound), axis=1)
                    if outside.any():
                        filled = int(np.argmax(outside)) + 1
                    stop = (
                        f"the motion ran away: {outside_names(problem, solver.y)} at t = {solver.t:.6g} s, "
                        "so the run stops there"
                    )
                    break
        except _OutOfBudget as exc:
            stats = {"steps": steps, "rhs_evaluations": calls[0]}
            raise cut_short(self.too_much(problem, str(exc)), self, problem, Y, filled, **stats) from None
        except _NotEvaluable as exc:
            stop = f"the right-hand side could not be evaluated ({exc})"
        trajectory = Trajectory(
            self.name,
            t_out[:filled],
            Y[:filled],
            steps=steps,
            rhs_evaluations=calls[0],
            wall_time_s=0.0,
            complete=not stop,
            stop_reason=stop,
        )
        njev = getattr(solver, "njev", 0)
        if njev:
            trajectory.notes.append(f"{njev} Jacobian evaluations, {getattr(solver, 'nlu', 0)} LU decompositions")
        return trajectory


class ScipyDOP853(ScipyMethod):
    name = "DOP853"
    label = "Dormand–Prince 8(5,3), SciPy"
    solver = "DOP853"
    family = "explicit"
    order = 8
    summary = "scipy's Dormand-Prince 8(5,3), Python step loop"


class ScipyRK45(ScipyMethod):
    name = "RK45"
    label = "Dormand–Prince 5(4), SciPy"
    solver = "RK45"
    family = "explicit"
    order = 5
    summary = "scipy's Dormand-Prince 5(4), Python step loop"


class ScipyRadau(ScipyMethod):
    name = "Radau"
    label = "Radau IIA, implicit, SciPy"
    solver = "Radau"
    family = "implicit"
    implicit = True
    order = 5
    summary = "scipy's Radau IIA order 5, implicit (stiff problems)"


class ScipyBDF(ScipyMethod):
    name = "BDF"
    label = "backward differentiation, implicit, SciPy"
    solver = "BDF"
    family = "implicit"
    implicit = True
    order = 5
    summary = "scipy's variable-order backward differentiation, implicit (stiff problems)"


class ScipyLSODA(ScipyMethod):
    name = "LSODA"
    label = "LSODA (Adams or BDF), SciPy"
    solver = "LSODA"
    family = "switching"
    implicit = True
    order = 12
    summary = "scipy's LSODA: Adams, switching to BDF when it detects stiffness"
