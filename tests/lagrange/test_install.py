"""``pip install`` of the project in a fresh virtual environment gives the console command and the API."""

from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]


def _run(*args: str, cwd: Path, check: bool = True) -> subprocess.CompletedProcess:
    # without the test's PYTHONPATH: the fresh environment finds only what is installed in it
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    return subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=600, check=check)


def test_a_fresh_environment_gets_the_package_and_the_command(tmp_path):
    # the wheel, built as pip builds it (setuptools from the package index, as pyproject.toml asks); the
    # dependencies from this environment
    _run(sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path), str(ROOT), cwd=tmp_path)
    wheel = next(tmp_path.glob("lagrange-*.whl"))
    fresh = tmp_path / "venv"
    _run(sys.executable, "-m", "venv", str(fresh), cwd=tmp_path)
    python = fresh / "bin" / "python"
    _run(str(python), "-m", "pip", "install", "-q", "--no-deps", "--no-index", str(wheel), cwd=tmp_path)
    site = _run(str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])", cwd=tmp_path)
    (Path(site.stdout.strip()) / "dependencies.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")

    # the API, imported from the installed copy (not the source tree), derives a system
    script = (
        "import lagrange, app; "
        "d = lagrange.derive(lagrange.System(['x'], {'m': 1, 'k': 4}, kinetic='m*x_dot**2/2', potential='k*x**2/2')); "
        "print(lagrange.__file__); print(app.__file__); print(d.accelerations)"
    )
    out = _run(str(python), "-c", script, cwd=tmp_path).stdout.splitlines()
    assert all(line.startswith(str(fresh)) for line in out[:2]), out
    assert out[2] == "{'x_ddot': -k*x/m}"

    # the console command; away from the project's files, serve says where to run it
    assert "serve" in _run(str(fresh / "bin" / "lagrange"), "--help", cwd=tmp_path).stdout
    served = _run(str(fresh / "bin" / "lagrange"), "serve", cwd=tmp_path, check=False)
    assert served.returncode == 2
    assert "run it from the project's directory" in served.stderr
