"""The action panel's browser numbers (static/js/action-live.js, run in node) agree with the server's: the
generated L, S(ε) on the preview's RK4 path, and the kinetic focus from neighbouring paths."""

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from app.numerics.action import action_of, action_terms
from app.numerics.system import numeric_system
from app.service.chapter.derivations import derivation

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)

NODE = shutil.which("node")
LIVE = Path(__file__).resolve().parents[2] / "static" / "js" / "action-live.js"
RUN = """
import { readFileSync } from "node:fs";
const { liveAction, focus, compileLagrangian } = await import(process.argv[1]);
const setup = JSON.parse(readFileSync(0, "utf8"));
const rhs = new Function("t", "y", "k", "out", '"use strict";\\n' + setup.preview.rhs);
const fns = { rhs, L: compileLagrangian(setup.preview) };
const y0 = Float64Array.from(setup.y0), k = Float64Array.from(setup.k);
const live = liveAction(fns, { y0, k, T: setup.T, c: 0, shape: 1, eps: setup.eps, epsilons: setup.epsilons });
process.stdout.write(JSON.stringify({ curve: live.curve, kind: live.kind, focus: focus(rhs, y0, k, setup.span, 800) }));
"""


@pytest.mark.skipif(NODE is None, reason="node is installed by scripts/assets.sh")
@pytest.mark.parametrize(("T", "kind"), [(0.8, "minimum"), (1.4, "saddle")])
def test_browser_numbers_match_the_server(T, kind):
    system = numeric_system(derivation("simple-pendulum"))
    k, y0 = np.array([1.0, 9.81, 1.0]), np.array([1.0, 0.0])
    epsilons = [-0.3, 0.0, 0.2]
    server = action_of(system, k, y0, T, 0, 1, epsilons)
    setup = {
        "preview": {"rhs": system.browser, "lagrangian": action_terms(system).browser},
        "y0": y0.tolist(), "k": k.tolist(), "T": T, "eps": 0.2, "epsilons": epsilons, "span": 3.0,
    }  # fmt: skip
    answer = subprocess.run(
        [NODE, "--input-type=module", "-e", RUN, LIVE.as_uri()],
        input=json.dumps(setup), capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert answer.returncode == 0, answer.stderr
    live = json.loads(answer.stdout)
    # RK4 with 1600 steps and Simpson on 401 samples: a preview, close to the server's 1e-8
    np.testing.assert_allclose(live["curve"], server.action, rtol=1e-6)
    assert live["kind"] == server.kind == kind
    assert live["focus"] == pytest.approx(1.0695688, rel=1e-3)
