"""The settings: one place, read from LAGRANGE_ variables, and README's table generated from it."""

import subprocess
import sys

from app.settings import ROOT, Settings


def test_a_setting_is_read_from_its_lagrange_variable(monkeypatch):
    monkeypatch.setenv("LAGRANGE_DERIVE_SECONDS", "12.5")
    monkeypatch.setenv("LAGRANGE_WARM", "0")
    read = Settings()
    assert read.derive_seconds == 12.5 and read.warm is False


def test_the_readme_lists_every_setting_as_settings_defines_it():
    check = subprocess.run(
        [sys.executable, "scripts/settings_table.py", "--check"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"},
    )
    assert check.returncode == 0, check.stdout + check.stderr
