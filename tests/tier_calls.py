"""A pytest plugin that records which modules of app/ had a function called during the run.

``scripts/fast-tier-modules.sh`` loads it (``-p tests.tier_calls``) into the fast tier and lists the modules of app/
no fast test reaches.  Importing a module runs its top level; that does not count: a module counts once one of
its functions, methods or comprehensions runs (in the test's process or one of its threads, not in the worker
processes a test starts).  Each pytest process appends the modules it saw, one a line, to the file named by
``LAGRANGE_TIER_CALLS``.
"""

from __future__ import annotations

import ast
import os
import sys
import threading
from pathlib import Path

APP = str(Path(__file__).resolve().parents[1] / "app") + os.sep
seen: set[str] = set()


def _on_call(frame, event, arg):
    # the global trace function sees each new frame once; returning None asks for no line events in it
    code = frame.f_code
    if code.co_filename.startswith(APP) and code.co_name != "<module>":
        seen.add(code.co_filename)
    return None


# from the plugin's import on, before the conftest imports the app: a function the app calls while it is imported
# counts too (the examples built at import, for instance)
sys.settrace(_on_call)
threading.settrace(_on_call)


def pytest_unconfigure(config):
    sys.settrace(None)
    threading.settrace(None)
    out = os.environ.get("LAGRANGE_TIER_CALLS")
    if out:
        with open(out, "a", encoding="utf-8") as f:
            f.writelines(name + "\n" for name in sorted(seen))


# Modules of app/ that the fast tier may leave unreached, each with the reason (keep it short and true).
_COMPILED = "numba compiles its functions to machine code, which leaves no Python frame to see; the fast tier runs them"
OUTSIDE: dict[str, str] = {
    **{f"app/numerics/kernels/{name}.py": _COMPILED for name in ("common", "composition", "dop853", "gauss", "radau")},
    **{f"app/numerics/kernels/{name}.py": _COMPILED for name in ("vern8", "vern8_stages")},
    "app/service/simulations/scene_jobs.py": "runs in the scenes' worker processes, which the trace does not follow",
    "app/service/users/worker_warmup.py": "runs in a worker process as it starts, which the trace does not follow",
    "app/service/runtime/memory.py": "the server's start-up after warming; tests/service/runtime/test_memory.py (slow)",
    "app/service/warm.py": "the warm-up, off in the tests (LAGRANGE_WARM=0); tests/service/test_warm.py (slow)",
    "app/service/simulations/warm_kernels.py": "the warm-up, off in the tests (LAGRANGE_WARM=0); tests/service/test_warm.py (slow)",
    "app/web/warm.py": "the command python -m app.web.warm; tests/web/test_warm.py (slow)",
    "app/web/http/server_options.py": "run as a command by scripts/serve.sh; tests/test_limits.py runs it so (slow)",
}


def unreached(calls: Path) -> list[str]:
    """The modules of app/ (their paths from the project's root) that no recorded call reached."""
    root = Path(APP).parent
    reached = {Path(line) for line in calls.read_text(encoding="utf-8").split()}
    every = [p for p in sorted(Path(APP).rglob("*.py")) if "__pycache__" not in p.parts]
    # a module with no function of its own (constants, plain models) has nothing to call: it counts as reached
    return [str(p.relative_to(root)) for p in every if defines_a_function(p) and p not in reached]


def defines_a_function(path: Path) -> bool:
    nodes = ast.walk(ast.parse(path.read_text(encoding="utf-8")))
    return any(isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)) for n in nodes)


def main(argv: list[str]) -> int:
    missing = unreached(Path(argv[0]))
    unexplained = [m for m in missing if m not in OUTSIDE]
    # a reason kept for a module the fast tier now reaches is stale: it goes
    stale = sorted(OUTSIDE.keys() - set(missing))
    for m in missing:
        print(m, "—", OUTSIDE.get(m, "NO FAST TEST"))
    for m in stale:
        print(m, "— reached now: take it out of OUTSIDE")
    print(f"{len(missing)} modules of app/ unreached by the fast tier, {len(unexplained)} without a reason")
    return 1 if unexplained or stale else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
