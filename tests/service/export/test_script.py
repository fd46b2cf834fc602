"""The exported script: standalone, and it lands where the app's own simulation lands."""

import ast
import json
import select
import subprocess
import sys

import pytest

from tests.service.export.common import CASES, HOSTILE_TEXT, USER_SYSTEMS, app_end_state, exported

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

ALLOWED_IMPORTS = {"json", "numpy", "sympy", "scipy.integrate"}


def imports_of(source: str) -> set[str]:
    found = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            found.add(node.module)
    return found


@pytest.mark.parametrize("case", CASES)
def test_the_script_imports_only_numpy_scipy_sympy_and_json(case):
    assert imports_of(exported(case, "py")) == ALLOWED_IMPORTS


def test_nothing_typed_reaches_the_script_but_checked_names():
    script = exported("hostile", "py")
    for text in HOSTILE_TEXT:
        assert text not in script
    # the code uses the system's own names, with a trailing underscore where one is Python's or the file's own
    assert "exec_ = sp.Symbol('exec', real=True)" in script and "q0 = sp.Symbol('q0', real=True)" in script
    assert "print_ = sp.Symbol('print', real=True)" in script and "sp_ = sp.Symbol('sp', real=True)" in script
    assert "# written with a trailing underscore" in script and "exec as exec_" in script
    assert "exec(" not in script and "print(" in script.splitlines()[-1]


# Runs each script it is sent (a path per line) as __main__ in a namespace of its own, and answers with one JSON
# line: what the script printed, and its traceback if it failed.
RUNNER = """
import contextlib, io, json, runpy, sys, traceback
for path in sys.stdin:
    printed, error = io.StringIO(), None
    try:
        with contextlib.redirect_stdout(printed):
            runpy.run_path(path.strip(), run_name="__main__")
    except SystemExit as done:
        if done.code not in (None, 0):
            error = f"exit status {done.code}"
    except BaseException:
        error = traceback.format_exc()
    print(json.dumps({"stdout": printed.getvalue(), "error": error}), flush=True)
"""


class ScriptRunner:
    """One Python process that runs the exported scripts one after another.

    A process per script spends most of its time importing numpy, scipy and sympy; here each script still runs
    top to bottom as __main__ with nothing but its own names, only the imported modules are shared.
    """

    def __init__(self, folder):
        self.folder = folder
        self.start()

    def start(self) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-c", RUNNER], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, cwd=self.folder
        )

    def run(self, name: str, script: str, timeout: float = 120) -> dict:
        path = self.folder / f"{name}.py"
        path.write_text(script)
        self.process.stdin.write(f"{path}\n")
        self.process.stdin.flush()
        ready, _, _ = select.select([self.process.stdout], [], [], timeout)
        if not ready:
            self.close()
            self.start()  # the next script gets a process that is not busy with this one
            raise AssertionError(f"the script ran for more than {timeout} s")
        answer = json.loads(self.process.stdout.readline())
        assert answer["error"] is None, answer["error"][-2000:]
        return json.loads(answer["stdout"].strip().splitlines()[-1])

    def close(self) -> None:
        self.process.kill()
        self.process.wait()
        self.process.stdin.close()
        self.process.stdout.close()


@pytest.fixture(scope="module")
def runner(tmp_path_factory):
    scripts = ScriptRunner(tmp_path_factory.mktemp("scripts"))
    yield scripts
    scripts.close()


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES)
def test_the_script_lands_within_1e_6_of_the_apps_own_simulation(case, runner):
    printed = runner.run(case, exported(case, "py"))
    t_end, state = app_end_state(case)
    assert printed["t"] == pytest.approx(t_end, rel=1e-9, abs=1e-12)  # t_end, or where a terminal event ends it
    assert set(printed["state"]) == set(state)
    worst = max(abs(printed["state"][name] - value) for name, value in state.items())
    assert worst < 1e-6, (case, worst)


def test_the_user_systems_cover_each_way_of_declaring_mechanics():
    forms = {
        name: next(k for k in ("particles", "kinetic", "lagrangian") if body.get(k))
        for name, (body, _, _) in USER_SYSTEMS.items()
    }
    assert set(forms.values()) >= {"particles", "kinetic"}


def test_the_script_reads_like_the_system():
    script = exported("double-pendulum", "py")
    for line in ("theta1 = sp.Symbol('theta1', real=True)", "theta2_dot = sp.Symbol('theta2_dot', real=True)",
                 "l1 = sp.Symbol('l1', real=True)", "m2 = sp.Symbol('m2', real=True)"):  # fmt: skip
        assert line in script
    assert "q0" not in script and "k0" not in script and "trailing underscore" not in script
    assert "sp.cos(theta1)" in script
