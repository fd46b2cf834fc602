"""The exported script: standalone, and it lands where the app's own simulation lands."""

import ast
import json
import subprocess
import sys

import pytest

from tests.service.export.common import CASES, HOSTILE_TEXT, USER_SYSTEMS, app_end_state, exported

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
    # the names are string literals naming SymPy symbols; the code itself uses q0, v0, k0, ...
    assert "q0 = sp.Symbol('exec', real=True)" in script and "k2 = sp.Symbol('q0', real=True)" in script
    assert "exec(" not in script and "print(" in script.splitlines()[-1]


def run(script: str, tmp_path) -> dict:
    path = tmp_path / "exported.py"
    path.write_text(script)
    done = subprocess.run([sys.executable, str(path)], capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES)
def test_the_script_lands_within_1e_6_of_the_apps_own_simulation(case, tmp_path):
    printed = run(exported(case, "py"), tmp_path)
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
