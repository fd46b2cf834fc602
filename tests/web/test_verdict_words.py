"""How a verdict's reason is made a sentence (static/js/verdict-words.js, run in node): a capital only on a word,
never on a symbol, which a capital would turn into another symbol (student-g 2: "Why: Α is a fixed angle", "Ω²",
"Z is measured upward", "D/dt")."""

import json
import shutil
import subprocess
from pathlib import Path

import pytest

NODE = shutil.which("node")
WORDS = Path(__file__).resolve().parents[2] / "static" / "js" / "verdict-words.js"
RUN = """
import { readFileSync } from "node:fs";
const { sentenceOf } = await import(process.argv[1]);
process.stdout.write(JSON.stringify(JSON.parse(readFileSync(0, "utf8")).map((t) => sentenceOf(t))));
"""
pytestmark = pytest.mark.skipif(NODE is None, reason="node is installed by scripts/assets.sh")

CASES = {
    "α is a fixed angle of the set-up, not a coordinate": "α is a fixed angle of the set-up, not a coordinate.",
    "z is measured upward, as the figure draws it": "z is measured upward, as the figure draws it.",
    "ω² = U_eff″/m_eff at the equilibrium": "ω² = U_eff″/m_eff at the equilibrium.",
    "d/dt(∂L/∂q̇) − ∂L/∂q = Q": "d/dt(∂L/∂q̇) − ∂L/∂q = Q.",
    "x₁ is the left mass's position": "x₁ is the left mass's position.",
    "a velocity's part is squared whole": "A velocity's part is squared whole.",
    "the sign of U is that of the height": "The sign of U is that of the height.",
    "check which component takes the sine!": "Check which component takes the sine!",
    "": "",
}


def test_a_reason_is_capitalised_only_where_it_opens_with_a_word():
    run = subprocess.run(
        [NODE, "--input-type=module", "-e", RUN, WORDS.as_uri()],
        input=json.dumps(list(CASES)), capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    assert dict(zip(CASES, json.loads(run.stdout), strict=True)) == CASES
