"""Numerics is pure, as ``solve_ivp`` is: a run takes a problem and returns a result on the caller's thread.
Threads, processes, the machine's load and the throttle belong to the service, which composes numerics' pieces
(``app.service.simulations.simulation_run``; ``app.service.runtime.cores`` gives a run its second core)."""

import ast
import pathlib
import threading

import numpy as np

from app.numerics.simulate import simulate
from app.scenes import SCENES
from tests.numerics.extreme_cases import system_for

NUMERICS = pathlib.Path(__file__).resolve().parents[2] / "app" / "numerics"
# what starts a thread or a process, waits on one, or reads the machine's load
FORBIDDEN = {
    "Thread", "ThreadPoolExecutor", "ProcessPoolExecutor", "Process", "Pool", "Future", "getloadavg", "cpu_count",
    "process_cpu_count", "sched_getaffinity",
}  # fmt: skip
# the server's concerns, which a run's caller decides and numerics never names: a throttle (one Python step
# loop at a time), another process, work placed beside the run, the cores, the gates, a pool
SERVICE_WORDS = {
    "python_loop", "throttle", "elsewhere", "offload", "alongside", "beside", "cores", "gates", "pool", "executor",
    "worker", "submit",
}  # fmt: skip
# how such a callback is typed: a context manager to hold, a future to wait on
SERVICE_TYPES = ("AbstractContextManager", "ContextManager", "Future", "Executor")


def test_numerics_names_no_thread_process_or_load():
    found = []
    for path in sorted(NUMERICS.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            name = node.attr if isinstance(node, ast.Attribute) else node.id if isinstance(node, ast.Name) else None
            if name in FORBIDDEN:
                found.append(f"{path.relative_to(NUMERICS)}:{node.lineno} {name}")
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith(("app.service", "app.web")):
                found.append(f"{path.relative_to(NUMERICS)}:{node.lineno} imports {node.module}")
            modules = [a.name for a in node.names] if isinstance(node, ast.Import) else []
            modules += [node.module] if isinstance(node, ast.ImportFrom) and node.module else []
            found += [
                f"{path.relative_to(NUMERICS)}:{node.lineno} imports {m}"
                for m in modules
                if m.split(".")[0] in ("concurrent", "multiprocessing", "subprocess")
            ]
    assert found == []


def test_numerics_takes_no_callback_for_the_servers_concerns():
    """A run takes a problem and returns a result: no function, method or property of numerics is named for
    the service's concerns, takes a parameter so named, or takes a context manager or a future."""
    found = []
    for path in sorted(NUMERICS.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                continue
            where = f"{path.relative_to(NUMERICS)}:{node.lineno} {node.name}"
            if node.name in SERVICE_WORDS:
                found.append(where)
            arguments = node.args
            for arg in [*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs]:
                typed = ast.unparse(arg.annotation) if arg.annotation is not None else ""
                if arg.arg in SERVICE_WORDS or any(t in typed for t in SERVICE_TYPES):
                    found.append(f"{where}({arg.arg}: {typed})")
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
