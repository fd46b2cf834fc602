"""What the action panel says after Relax (static/js/action-verdict.js, run in node) on the server's answers:
a found path is certified with its numbers and units, a refused one says why and what to do, and no sentence
reads as a log ("about 0", e-notation)."""

import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from app.service.chapter.derivations import PROCESS_SCENES
from app.service.runtime.gates import Gates
from app.service.simulations.action import relax_of_scene

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

NODE = shutil.which("node")
VERDICT = Path(__file__).resolve().parents[2] / "static" / "js" / "action-verdict.js"
RUN = """
import { readFileSync } from "node:fs";
const { verdict } = await import(process.argv[1]);
const { answer, context } = JSON.parse(readFileSync(0, "utf8"));
process.stdout.write(JSON.stringify(verdict(answer, context)));
"""
T = 2.0
CONTEXT = {"q": "theta", "label": "θ", "unit": "rad", "rateUnit": "rad/s", "T": T, "steps": 200}
LOG_WORDS = re.compile(r"about 0\b|\d[eE][+-]?\d|NaN|undefined|null")


def _said(lift: float) -> tuple[dict, dict]:
    true = relax_of_scene("simple-pendulum", Gates(), PROCESS_SCENES, t_end=T, initial={"theta": 1.0})
    trial = [
        q + lift * math.sin(math.pi * t / T) for t, q in zip(true["t"], true["shooting"]["q"]["theta"], strict=True)
    ]
    answer = relax_of_scene(
        "simple-pendulum", Gates(), PROCESS_SCENES, t_end=T, initial={"theta": 1.0}, trial={"theta": trial}
    )
    run = subprocess.run(
        [NODE, "--input-type=module", "-e", RUN, VERDICT.as_uri()],
        input=json.dumps({"answer": answer, "context": CONTEXT}), capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    return answer, json.loads(run.stdout)


@pytest.mark.skipif(NODE is None, reason="node is installed by scripts/assets.sh")
def test_a_found_path_is_certified_with_named_numbers():
    answer, said = _said(3.0)
    assert answer["found"] and said["found"] and said["advice"] == []
    text, method = said["text"], said["method"]
    # the lead says what a second-year needs, with the panel's own number: the shooting solution's distance from
    # the relaxed path (prof-l 8); the method's account (Newton, the grid) is the disclosure's, not the lead's
    within = re.match(
        r"The relaxed path agrees with the true motion to within ([\d.]+) × 10⁻([⁰¹²³⁴⁵⁶⁷⁸⁹]+) rad: ", text
    )
    assert within, text
    digits = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789")
    printed = float(within.group(1)) * 10 ** -int(within.group(2).translate(digits))
    assert printed == pytest.approx(answer["difference"], rel=0.01)
    assert "the motion that starts with θ̇(0) = 0 rad/s." in text  # the true motion starts at rest
    assert "not a minimum" in text and "past the kinetic focus" in text  # T = 2 s > t* = 1.07 s
    assert "Newton" not in text and "grid" not in text and "extrapolated" not in text
    assert method.startswith("Newton's method made the discrete action stationary in ")
    assert "on a 200-step time grid" in method and "the extrapolated path shown is closer still" in method
    assert re.search(r"runs along the relaxed path to within [\d.]+ × 10⁻[⁰¹²³⁴⁵⁶⁷⁸⁹]+ rad\.", method), method
    assert not LOG_WORDS.search(text + method), text + method


@pytest.mark.skipif(NODE is None, reason="node is installed by scripts/assets.sh")
def test_a_wrong_path_is_refused_with_the_reason_and_what_to_do():
    answer, said = _said(12.0)
    assert not answer["found"] and not said["found"]
    text = said["text"]
    assert text.startswith("The path was not found. Newton's method stopped after ")
    assert "so the curve shown is not a stationary path of S" in text
    assert "No true motion runs along it: the shooting solution between the same ends" in text
    assert text.endswith(
        "To find it: drag the points of the trial path nearer the true path, choose a shorter τ, or start from the "
        "shooting solution (the button “Start from the shooting solution”)."
    )
    assert "minimum" not in text and "saddle" not in text  # nothing is said of a path that was not found
    assert said["method"] == ""  # and no account of a computation that found nothing
    assert not LOG_WORDS.search(text), text
