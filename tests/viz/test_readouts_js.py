"""Readouts computed in the browser: turning points, number formats, axis formats (run with node)."""

import json
import math
import shutil
import subprocess
from pathlib import Path

import pytest

JS = Path(__file__).resolve().parents[2] / "static" / "js"

pytestmark = pytest.mark.skipif(shutil.which("node") is None, reason="node is installed with the front-end assets")


def node(module: str, body: str):
    script = f"import * as m from {json.dumps((JS / module).as_uri())}; console.log(JSON.stringify(({body})(m)));"
    run = subprocess.run(["node", "--input-type=module", "-e", script], capture_output=True, text=True, timeout=30)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_pendulum_turning_points_are_unique_and_bracket_the_motion():
    # released from rest at θ = 1: the level is U(1), the well is [−1, 1], and θ = 1 is both start and turning point
    pts = node(
        "reduction.js",
        "(m) => { const U = (x) => 1 - Math.cos(x), lvl = U(1); "
        "return [m.turningPoints((x) => U(x) - lvl, -1.6, 1.6, 1), m.turningPoints((x) => U(x) - lvl, -1.6, 1.6, 0.2)]; }",
    )
    for found in pts:
        assert len(found) == 2
        assert found[0] == pytest.approx(-1, abs=1e-9) and found[1] == pytest.approx(1, abs=1e-9)


def test_only_the_well_that_holds_the_motion():
    # a double well U = (x² − 4)²/16 with level 0.5: two wells; a particle at x = 2.3 turns inside the right one
    found = node(
        "reduction.js",
        "(m) => m.turningPoints((x) => (x * x - 4) ** 2 / 16 - 0.5, -4, 4, 2.3)",
    )
    inner, outer = math.sqrt(4 - math.sqrt(8)), math.sqrt(4 + math.sqrt(8))
    assert found == pytest.approx([inner, outer], abs=1e-9)


def test_one_sided_and_none():
    one = node("reduction.js", "(m) => m.turningPoints((x) => x - 1, -4, 4, 0)")  # a slope: turns at x = 1 only
    assert one == pytest.approx([1], abs=1e-9)
    assert node("reduction.js", "(m) => m.turningPoints((x) => 1, -4, 4, 0)") == []  # outside every well
