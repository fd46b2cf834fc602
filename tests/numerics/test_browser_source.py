"""The JavaScript right-hand side of the live preview computes what the Python one computes (run in node)."""

import json
import random
import re
import shutil
import subprocess

import numpy as np
import pytest

from app.engine.derivation.derive import derive
from app.numerics.system import numeric_system
from tests.numerics.extreme_cases import system_for
from tests.numerics.systems import DOUBLE_PENDULUM
from tests.numerics.test_codegen import KEYS, random_point

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

NODE = shutil.which("node")
RUN = """
const cases = JSON.parse(require("fs").readFileSync(0, "utf8"));
const out = cases.map(({ body, t, y, k }) => {
  const f = new Function("t", "y", "k", "out", '"use strict";\\n' + body);
  const o = new Float64Array(y.length);
  f(t, Float64Array.from(y), Float64Array.from(k), o);
  return Array.from(o);
});
process.stdout.write(JSON.stringify(out));
"""


def systems():
    yield from ((key, system_for(key)) for key in KEYS)
    yield "double-pendulum", numeric_system(derive(DOUBLE_PENDULUM))


@pytest.mark.skipif(NODE is None, reason="node is installed by scripts/assets.sh")
def test_browser_rhs_matches_the_python_rhs():
    cases, expected = [], []
    rng = random.Random(5)
    for key, s in systems():
        for _ in range(3):
            t, y, k = random_point(s, rng)
            cases.append({"key": key, "body": s.browser, "t": t, "y": y.tolist(), "k": k.tolist()})
            expected.append(s.f(t, y, k))
    answer = subprocess.run([NODE, "-e", RUN], input=json.dumps(cases), capture_output=True, text=True, timeout=60)
    assert answer.returncode == 0, answer.stderr
    for case, want, got in zip(cases, expected, json.loads(answer.stdout), strict=True):
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12, err_msg=case["key"])


def test_browser_source_names_no_declared_symbol():
    # only the renamed symbols (q0, v0, k0, t), temporaries, numbers and Math calls appear
    s = numeric_system(derive(DOUBLE_PENDULUM))
    words = set(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", s.browser))
    allowed = {"let", "Math", "pow", "sin", "cos", "tan", "sqrt", "exp", "log", "abs", "sign", "out", "y", "k", "t"}
    odd = {w for w in words if w not in allowed and not re.fullmatch(r"(q|v|k|a_|_[a-z]*)\d*(_\d+)?", w)}
    assert odd == set(), odd
    assert "m1" not in words and "l2" not in words
