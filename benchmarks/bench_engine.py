"""Engine vs sympy.physics.mechanics.LagrangesMethod: time to the accelerations.

For each system both sides start from the same declaration: the engine parses
it, forms T and L, the Euler-Lagrange equations and solves M q_ddot = f;
LagrangesMethod gets its Lagrangian from Particle objects and runs
form_lagranges_equations() and rhs().  SymPy's cache is cleared before every
run so neither side profits from the other; each side's time is the minimum
of several runs (two for chains of four links or more).  Goal: ratio (engine / LagrangesMethod) <= 0.8 on each, and
the engine's time growing monotonically along a chain of 1 to 6 pendulum links.

    .venv/bin/python -m benchmarks.bench_engine
"""

from __future__ import annotations

import time

from sympy.core.cache import clear_cache

from app.engine.derivation.derive import accelerations_only
from app.scenes import SCENES
from app.scenes.types import Parameter, Particle, System
from tests.engine.systems import DOUBLE_PENDULUM
from tests.reference import lagranges_method

REPEATS = 5
CHAIN_LINKS = range(1, 7)


def pendulum_chain(links: int) -> System:
    """A planar chain of ``links`` point masses on rigid massless rods, angles from the vertical."""
    names = [f"a{i}" for i in range(1, links + 1)]
    masses = [Parameter(f"m{i}", 1.0, min=0.1) for i in range(1, links + 1)]
    lengths = [Parameter(f"l{i}", 1.0, min=0.1) for i in range(1, links + 1)]
    particles, potential, x, y = [], [], [], []
    for i in range(links):
        x.append(f"{lengths[i].name}*sin({names[i]})")
        y.append(f"-{lengths[i].name}*cos({names[i]})")
        particles.append(Particle(masses[i].name, (" + ".join(x), " + ".join(y), "0")))
        potential.append(f"{masses[i].name}*g*({' + '.join(y)})")
    return System(
        coordinates=tuple(names),
        parameters=(*masses, *lengths, Parameter("g", 9.81, min=0.1)),
        particles=tuple(particles),
        potential=" + ".join(potential),
    )


def lagranges_method_rhs(system) -> None:
    lm, _, _ = lagranges_method(system)
    lm.rhs()


def best_time(work, repeats: int = REPEATS) -> float:
    best = float("inf")
    for _ in range(repeats):
        clear_cache()
        start = time.perf_counter()
        work()
        best = min(best, time.perf_counter() - start)
    return best


def main() -> None:
    chain = {f"pendulum chain, {n} link{'s' if n > 1 else ''}": pendulum_chain(n) for n in CHAIN_LINKS}
    systems = {
        **{k: s.system for k, s in SCENES.items()},
        "double-pendulum (test)": DOUBLE_PENDULUM,
        **chain,
    }
    print("| system | engine ms | LagrangesMethod ms | ratio |")
    print("|---|---|---|---|")
    worst = 0.0
    engine = {}
    for name, system in systems.items():
        # the long chains take tens of seconds per LagrangesMethod run: fewer repeats there
        repeats = REPEATS if len(system.coordinates) <= 3 else 2
        ours = best_time(lambda system=system: accelerations_only(system), repeats)
        theirs = best_time(lambda system=system: lagranges_method_rhs(system), repeats)
        engine[name] = ours
        worst = max(worst, ours / theirs)
        print(f"| {name} | {ours * 1e3:.1f} | {theirs * 1e3:.1f} | {ours / theirs:.2f} |")
    along = [engine[name] for name in chain]
    monotonic = all(a < b for a, b in zip(along, along[1:], strict=False))
    print(f"\nworst ratio {worst:.2f} (goal <= 0.80): {'met' if worst <= 0.8 else 'NOT met'}")
    print(f"engine time along the chain {'grows monotonically' if monotonic else 'is NOT monotonic'}")


if __name__ == "__main__":
    main()
