"""The Docker image, built and run for real with podman (opt-in: several minutes).

LAGRANGE_CONTAINER_TESTS=1 .venv/bin/python -m pytest tests/deploy -m container
"""

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.container
@pytest.mark.skipif(os.environ.get("LAGRANGE_CONTAINER_TESTS") != "1", reason="opt-in: set LAGRANGE_CONTAINER_TESTS=1")
def test_image_builds_and_serves_offline():
    run = subprocess.run(
        [str(ROOT / "scripts" / "container_test.sh")], cwd=ROOT, capture_output=True, text=True, timeout=1800
    )
    assert run.returncode == 0, run.stdout[-4000:] + run.stderr[-4000:]
    assert "container test passed" in run.stdout
    for check in ("/", "no network", "simulate", "work-precision", "classes kept on a volume"):
        assert f"ok   {check}" in run.stdout
