"""Engine vs sympy.physics.mechanics.LagrangesMethod: time to the accelerations.

For each system both sides start from the same declaration: the engine parses
it, forms T and L, the Euler-Lagrange equations and solves M q_ddot = f;
LagrangesMethod gets its Lagrangian from Particle objects and runs
form_lagranges_equations() and rhs().  SymPy's cache is cleared before every
run so neither side profits from the other; each side's time is the minimum
of several runs.  Goal: ratio (engine / LagrangesMethod) <= 0.8 on each.

    .venv/bin/python -m benchmarks.bench_engine
"""

from __future__ import annotations

import time

from sympy.core.cache import clear_cache

from app.engine.derive import accelerations_only
from app.scenes import SCENES
from tests.engine.systems import DOUBLE_PENDULUM
from tests.reference import lagranges_method

REPEATS = 5


def lagranges_method_rhs(system) -> None:
    lm, _, _ = lagranges_method(system)
    lm.rhs()


def best_time(work) -> float:
    best = float("inf")
    for _ in range(REPEATS):
        clear_cache()
        start = time.perf_counter()
        work()
        best = min(best, time.perf_counter() - start)
    return best


def main() -> None:
    systems = {**{k: s.system for k, s in SCENES.items()}, "double-pendulum (test)": DOUBLE_PENDULUM}
    print(f"{'system':28s} {'engine ms':>10s} {'LagrangesMethod ms':>19s} {'ratio':>6s}")
    worst = 0.0
    for name, system in systems.items():
        ours = best_time(lambda system=system: accelerations_only(system))
        theirs = best_time(lambda system=system: lagranges_method_rhs(system))
        worst = max(worst, ours / theirs)
        print(f"{name:28s} {ours * 1e3:10.1f} {theirs * 1e3:19.1f} {ours / theirs:6.2f}")
    print(f"worst ratio {worst:.2f} (goal <= 0.80): {'met' if worst <= 0.8 else 'NOT met'}")


if __name__ == "__main__":
    main()
