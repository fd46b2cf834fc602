"""The browser's evaluator (static/js/expr.js) knows every function a figure tree may hold."""

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from app.engine.document.trees import FUNCTIONS
from app.viz.exprtree import evaluate

EXPR_JS = Path(__file__).resolve().parents[2] / "static" / "js" / "expr.js"

# slow: out of the fast tier (scripts/test-fast.sh), each test over 0.3 s (docs/testing.md)
pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(shutil.which("node") is None, reason="node is installed with the front-end assets"),
]


def test_expr_js_evaluates_every_function_like_python():
    env = {"x": 0.7, "y": -0.4}
    # one node of each function the engine's trees may hold (app/engine/document/trees.py), x = 0.7, y = -0.4
    trees = [["atan2", "y", "x"] if name == "atan2" else [name, "x"] for name in sorted(FUNCTIONS)]
    texts = [f"{t[0]}({', '.join(t[1:])})" for t in trees]
    script = (
        f"import {{ evaluate }} from {json.dumps(EXPR_JS.as_uri())};"
        f"const trees = {json.dumps(trees)}; const env = {json.dumps(env)};"
        "console.log(JSON.stringify(trees.map((t) => evaluate(t, env))));"
    )
    run = subprocess.run(["node", "--input-type=module", "-e", script], capture_output=True, text=True, timeout=30)
    assert run.returncode == 0, run.stderr
    values = json.loads(run.stdout)
    for text, node, value in zip(texts, trees, values, strict=True):
        assert value == pytest.approx(evaluate(node, env), rel=1e-12), text
