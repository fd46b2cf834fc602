"""The server's start: what the web process imports, and a warm-up that gives way to requests."""

import os
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from app.numerics.methods import NONSTIFF
from app.service.chapter import compiled as compiled_systems
from app.service.chapter.derivations import PROCESS_SCENES
from app.service.runtime import gates
from app.service.simulations import simulation, warm_kernels

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

ROOT = Path(__file__).resolve().parents[2]


def test_the_web_process_imports_no_integrator_or_units_library_at_start():
    """scipy (the scipy fallback and methods, the stiffness analysis, normal modes), sympy.physics.units
    (simplify's first call), nbformat (notebook exports) and numba (the first compiled run, or the
    warm-up) are imported where first used (app/late.py), not by app.main."""
    late = ("scipy", "sympy.physics.units", "nbformat", "numba", "llvmlite")
    code = f"import sys, app.main; print(' '.join(m for m in {late!r} if m in sys.modules))"
    env = {**os.environ, "LAGRANGE_WARM": "0", "PYTHONPATH": str(ROOT)}
    out = subprocess.run([sys.executable, "-c", code], env=env, cwd=ROOT, capture_output=True, text=True, check=True)
    assert out.stdout.split() == []


class FakeMethod:
    """A compiled method that records what the warm-up prepares, in order."""

    compiled = True

    def __init__(self, name, log):
        self.name, self.log = name, log

    def applicable(self, system):
        return None

    def prepare(self, system):
        self.log.append(f"{self.name}:{system.coordinates}")


def fake_methods(monkeypatch, log):
    methods = {NONSTIFF: FakeMethod("first", log), "other": FakeMethod("other", log)}
    monkeypatch.setattr(warm_kernels, "METHODS", methods)
    monkeypatch.setattr(warm_kernels, "SCENES", {k: warm_kernels.SCENES[k] for k in ("simple-pendulum", "pulley")})


def test_warm_up_goes_scene_by_scene_with_the_first_method_and_gives_way_between_steps(monkeypatch):
    log: list[str] = []
    fake_methods(monkeypatch, log)
    spent = warm_kernels.warm_all(PROCESS_SCENES, give_way=lambda: log.append("give way"))
    assert log == [
        "give way",  # before the simple pendulum's system
        "give way",
        "first:('theta',)",
        "give way",  # before the pulley's system
        "give way",
        "first:('y1', 'y2')",
        "give way",
        "other:('theta',)",
        "give way",
        "other:('y1', 'y2')",
    ]
    assert set(spent) == {"scipy.integrate", "numeric systems", "first", "other"}


def test_the_warm_up_waits_while_a_simulation_is_being_served(monkeypatch):
    log: list[str] = []
    fake_methods(monkeypatch, log)
    warm_kernels.warm_all(PROCESS_SCENES)  # the systems are built: what is left to do is preparing the methods
    log.clear()
    gate = gates.Gates().in_flight  # an app's
    with gate.serving():
        warming = threading.Thread(target=warm_kernels.warm_all, args=(PROCESS_SCENES, lambda: gate.wait_quiet(30.0)))
        warming.start()
        warming.join(timeout=0.5)
        assert warming.is_alive() and log == []  # waiting for the request to finish
    warming.join(timeout=30.0)
    assert not warming.is_alive() and len(log) == 4
    assert gate.wait_quiet(0.0)


def test_a_scene_simulation_counts_as_in_flight(monkeypatch):
    seen = []
    original = simulation.simulate_derivation
    served = gates.Gates()  # an app's

    def spy(*args, **kwargs):
        seen.append(served.in_flight.wait_quiet(0.0))
        return original(*args, **kwargs)

    monkeypatch.setattr(simulation, "simulate_derivation", spy)
    request = {"parameters": {}, "initial": {}, "t_end": 0.5, "method": "auto", "rtol": None, "atol": None}
    simulation.simulate_scene("simple-pendulum", type("R", (), {**request, "samples": 10})(), served, PROCESS_SCENES)
    assert seen == [False] and served.in_flight.wait_quiet(0.0)


def test_a_scene_does_not_wait_while_another_scene_is_being_built(monkeypatch):
    from app.service.chapter.derivations import derivation

    compiled = compiled_systems.Compiled()
    release = threading.Event()
    original = compiled_systems.numeric_system
    slow, quick = derivation("simple-pendulum"), derivation("pulley")

    def numeric_system(d, sources=None):
        if d is slow:
            assert release.wait(30.0)
        return original(d, sources)

    monkeypatch.setattr(compiled_systems, "numeric_system", numeric_system)
    building = threading.Thread(target=compiled.get, args=("simple-pendulum", slow, []))
    building.start()
    try:
        system, _ = compiled.get("pulley", quick, [])  # while the pendulum's build is held
        assert system.coordinates == ("y1", "y2") and building.is_alive()
    finally:
        release.set()
        building.join(30.0)
    assert compiled.get("simple-pendulum", slow, [])[0].coordinates == ("theta",)
    assert list(compiled.items) == ["pulley", "simple-pendulum"]
