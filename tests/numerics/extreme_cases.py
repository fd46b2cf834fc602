"""The stiff and extreme cases, shared by tests/numerics/test_extreme.py and the table in docs/benchmarks.md
(benchmarks/bench_numerics_extreme.py).

Each case is a system (a scene id or a test system), parameter overrides, a start, a duration and,
where one is known, an exact solution derived independently of the engine: the pendulum's Jacobi
elliptic solution, constant acceleration, or a circular orbit.  Parameters may lie outside a scene's
declared ranges (M/m = 1e-9): these cases run the numerics directly, as the API would refuse them.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache

import mpmath
import numpy as np

from app.engine.derivation.derive import derive
from app.numerics.exact import constant_acceleration, constant_accelerations, pendulum
from app.numerics.methods import STIFF as STIFF_METHOD
from app.numerics.observables import build, summarize
from app.numerics.simulate import Outcome, simulate
from app.numerics.system import NumericSystem, numeric_system
from app.scenes import SCENES
from tests.numerics.systems import STIFF_SPRING


@cache
def system_for(key: str) -> NumericSystem:
    return numeric_system(derive(SCENES[key].system if key in SCENES else {"stiff-spring": STIFF_SPRING}[key]))


def pendulum_period(theta0: float, g: float = 9.81, R: float = 1.0) -> float:
    # T = 4 K(m) / w0 with m = sin^2(theta0 / 2)
    return float(4 * mpmath.ellipk(math.sin(theta0 / 2) ** 2) / math.sqrt(g / R))


def circular_radius(k_over_m: float, l0: float, spin: float) -> float:
    # k (r - l0) = m r spin^2  (spring force = centripetal force)
    return k_over_m * l0 / (k_over_m - spin**2)


@dataclass(frozen=True)
class Case:
    name: str
    system: str
    parameters: dict[str, float]
    initial: dict[str, float]
    t_end: float
    samples: int = 400
    method: str = "auto"
    rtol: float = 1e-8
    atol: float = 1e-10
    exact: str = ""  # "pendulum", "constant", "circle" or ""
    note: str = ""
    expect: dict = field(default_factory=dict)

    def vectors(self) -> tuple[NumericSystem, np.ndarray, np.ndarray]:
        s = system_for(self.system)
        declared = SCENES[self.system].system.parameters if self.system in SCENES else STIFF_SPRING.parameters
        k = np.array([self.parameters.get(p.name, p.default) for p in declared], dtype=float)
        y0 = np.array(
            [self.initial.get(q, 0.0) for q in s.coordinates]
            + [self.initial.get(f"{q}_dot", 0.0) for q in s.coordinates]
        )
        return s, k, y0

    def exact_solution(self, k: np.ndarray, y0: np.ndarray) -> Callable[[np.ndarray], np.ndarray] | None:
        s = system_for(self.system)
        if self.exact == "pendulum":
            g, R = self.parameters.get("g", 9.81), self.parameters.get("R", 1.0)
            return pendulum(g / R, float(y0[0]), float(y0[1]))
        if self.exact == "constant":
            return constant_acceleration(constant_accelerations(s, k), y0)
        if self.exact == "circle":
            r0, spin = float(y0[0]), float(y0[3])
            return lambda t: np.column_stack([np.full_like(t, r0), spin * t, np.zeros_like(t), np.full_like(t, spin)])
        return None


STIFF = {"m": 1.0, "l0": 1.0}
CASES = [
    Case(
        "pendulum released at θ0 = π − 1e-3",
        "simple-pendulum",
        {},
        {"theta": math.pi - 1e-3},
        20.0,
        exact="pendulum",
    ),
    Case(
        "pendulum released at θ0 = π − 1e-6",
        "simple-pendulum",
        {},
        {"theta": math.pi - 1e-6},
        30.0,
        exact="pendulum",
    ),
    Case(
        "pendulum θ0 = 2.5, 10⁴ periods",
        "simple-pendulum",
        {},
        {"theta": 2.5},
        1e4 * pendulum_period(2.5),
        samples=389,  # 388 intervals: each sample lands at a different phase of the swing
        rtol=1e-6,
        atol=1e-8,
        exact="pendulum",
        expect={"method": "Gauss-Legendre"},
    ),
    Case(
        "stiff radial spring k/m = 1e6, slow orbit",
        "stiff-spring",
        {**STIFF, "k": 1e6},
        {"r": circular_radius(1e6, 1.0, 1.0), "theta_dot": 1.0},
        10.0,
        exact="circle",
        expect={"method": STIFF_METHOD},
    ),
    Case(
        "stiff radial spring k/m = 1e8, slow orbit",
        "stiff-spring",
        {**STIFF, "k": 1e8},
        {"r": circular_radius(1e8, 1.0, 1.0), "theta_dot": 1.0},
        10.0,
        exact="circle",
        expect={"method": STIFF_METHOD},
    ),
    Case(
        "stiff radial spring k/m = 1e6, fast mode excited",
        "stiff-spring",
        {**STIFF, "k": 1e6},
        {"r": 1.001, "theta_dot": 1.0},
        10.0,
        expect={"not_method": STIFF_METHOD},
    ),
    Case(
        "stiff radial spring k/m = 1e8, fast mode excited",
        "stiff-spring",
        {**STIFF, "k": 1e8},
        {"r": 1.001, "theta_dot": 1.0},
        10.0,
        expect={"not_method": STIFF_METHOD},
    ),
    Case(
        "spherical pendulum passing 1e-4 rad from the pole",
        "spherical-pendulum",
        {},
        {"theta": 2.2, "phi_dot": 1e-3},
        4.0,
        samples=2000,
        expect={"warning": "singular point"},
    ),
    Case("movable incline M/m = 1e-9", "movable-incline", {"m": 1.0, "M": 1e-9}, {}, 1.5, exact="constant"),
    Case("movable incline M/m = 1e9", "movable-incline", {"m": 1.0, "M": 1e9}, {}, 1.5, exact="constant"),
    Case("pulley M → 0 (M = 1e-9)", "pulley", {"M": 1e-9}, {}, 2.0, exact="constant"),
    Case(
        "rotating parabola ω² > 2gα (ω = 10)",
        "rotating-parabola",
        {"omega": 10.0},
        {"rho": 0.5},
        1000.0,
        expect={"runaway": True},
    ),
]


@dataclass
class Result:
    case: Case
    outcome: Outcome
    seconds: float
    true_error: float | None
    energy_drift: float  # relative drift of the conserved energy-like quantity (E or h), or of E
    summary: dict


def run(case: Case) -> Result:
    s, k, y0 = case.vectors()
    obs = build(s)
    start = time.perf_counter()
    outcome = simulate(s, k, y0, case.t_end, case.samples, case.method, case.rtol, case.atol)
    seconds = time.perf_counter() - start - outcome.compile_seconds
    tr = outcome.trajectory
    exact = case.exact_solution(k, y0)
    true_error = None
    if exact is not None:
        reference = exact(tr.t)
        true_error = float(np.max(np.abs(tr.y[:, : s.n] - reference[:, : s.n])))
    values = obs.evaluate(tr.t, tr.y, k)
    summary = summarize(obs, tr.t, values, case.rtol)
    name = s.energy_name or "E"
    drift = summary["conserved_drift"].get(name, {}).get("relative", float("nan"))
    return Result(case, outcome, seconds, true_error, drift, summary)
