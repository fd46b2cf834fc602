"""Numerics is pure, as ``solve_ivp`` is: a run takes a problem and returns a result on the caller's thread.
Threads, processes and the machine's load belong to the service (``app.service.cores`` gives a run its second
core)."""

import ast
import pathlib
import threading

import numpy as np

from app.numerics.simulate import simulate
from app.scenes import SCENES
from tests.numerics.extreme_cases import system_for

NUMERICS = pathlib.Path(__file__).resolve().parents[2] / "app" / "numerics"
# what starts a thread or a process, or reads the machine's load
FORBIDDEN = {"Thread", "ThreadPoolExecutor", "ProcessPoolExecutor", "Process", "Pool", "getloadavg", "cpu_count"}


def test_numerics_names_no_thread_process_or_load():
    found = []
    for path in sorted(NUMERICS.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            name = node.attr if isinstance(node, ast.Attribute) else node.id if isinstance(node, ast.Name) else None
            if name in FORBIDDEN:
                found.append(f"{path.relative_to(NUMERICS)}:{node.lineno} {name}")
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith(("app.service", "app.web")):
                found.append(f"{path.relative_to(NUMERICS)}:{node.lineno} imports {node.module}")
    assert found == []


def test_a_run_with_its_estimate_starts_no_thread():
    scene = SCENES["simple-pendulum"]
    system = system_for("simple-pendulum")
    k = np.array([{p.name: p.default for p in scene.system.parameters}[name] for name in system.parameter_names])
    y0 = np.array(
        [scene.initial[q] for q in system.coordinates] + [scene.initial[f"{q}_dot"] for q in system.coordinates]
    )
    before = set(threading.enumerate())
    outcome = simulate(system, k, y0, 3.0, 200)
    assert outcome.estimate is not None and outcome.trajectory.complete
    assert set(threading.enumerate()) <= before
