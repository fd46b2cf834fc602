"""Every formula a scene page shows typesets with KaTeX (strict): steps, results and the errata."""

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from app.scenes import SCENES
from app.service.chapter.derivations import derivation_document

ROOT = Path(__file__).resolve().parents[2]

# slow: out of the fast tier (scripts/test-fast.sh), each test over 0.3 s (docs/testing.md)
pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(
        shutil.which("node") is None or not (ROOT / "node_modules" / "katex").is_dir(),
        reason="node and katex are installed with the front-end assets",
    ),
]


def formulas(doc):
    yield from (s["latex"] for s in doc["steps"])
    yield from (e["latex"] for e in doc["equations_of_motion"])
    for e in doc["errata"]:
        yield e["chapter_latex"]
        yield e["correct_latex"]


def test_every_formula_typesets():
    texts = [t for scene_id in sorted(SCENES) for t in formulas(derivation_document(scene_id))]
    script = (
        "const katex = require('katex'); const texts = JSON.parse(require('fs').readFileSync(0, 'utf8'));"
        "const bad = [];"
        "for (const t of texts) { try { katex.renderToString(t, { throwOnError: true, strict: 'error', displayMode: true }); }"
        " catch (e) { bad.push([t, e.message]); } }"
        "console.log(JSON.stringify(bad));"
    )
    run = subprocess.run(
        ["node", "-e", script], input=json.dumps(texts), capture_output=True, text=True, timeout=120, cwd=ROOT
    )
    assert run.returncode == 0, run.stderr
    assert json.loads(run.stdout) == [], run.stdout[:2000]
    assert len(texts) > 300
