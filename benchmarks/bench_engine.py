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

import sympy.physics.mechanics as me
from sympy.core.cache import clear_cache

from app.engine.derive import accelerations_only
from app.scenes import SCENES
from tests.engine.systems import DOUBLE_PENDULUM
from tests.reference import _reader

REPEATS = 5


def lagranges_method(system) -> None:
    qs, read = _reader(system)
    N = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(N, 0)
    if system.particles:
        bodies = []
        for i, part in enumerate(system.particles):
            r = sum((read(c) * e for c, e in zip(part.position, (N.x, N.y, N.z), strict=True)), 0 * N.x)
            P = origin.locatenew(f"P{i}", r)
            P.set_vel(N, P.pos_from(origin).dt(N))
            bodies.append(me.Particle(f"B{i}", P, read(part.mass)))
        L = me.Lagrangian(N, *bodies) - read(system.potential)
    elif system.kinetic is not None:
        L = read(system.kinetic) - read(system.potential)
    else:
        L = read(system.lagrangian)
    lm = me.LagrangesMethod(L, qs)
    lm.form_lagranges_equations()
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
        theirs = best_time(lambda system=system: lagranges_method(system))
        worst = max(worst, ours / theirs)
        print(f"{name:28s} {ours * 1e3:10.1f} {theirs * 1e3:19.1f} {ours / theirs:6.2f}")
    print(f"worst ratio {worst:.2f} (goal <= 0.80): {'met' if worst <= 0.8 else 'NOT met'}")


if __name__ == "__main__":
    main()
