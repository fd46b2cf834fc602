"""The one clock of a user's derivation (issue 43): when it fires the job is refused, and nothing it produced is
kept: the same system asked again, with time enough, gets the document a process that never saw the clock
fire gives."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from app.service.users import user_jobs
from app.service.users.user_checks import TooCostly, checked
from app.web.api.examples_user import DOUBLE_PENDULUM

ROOT = Path(__file__).resolve().parents[3]
pytestmark = pytest.mark.slow  # a fresh process derives the reference document (about 10 s)

# a system no other test of this process derives (SymPy's and the engine's caches hold nothing of it)
SYSTEM = {**DOUBLE_PENDULUM, "potential": "-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2) + 0"}
FRESH = f"""
import json, sys
from app.service.users import user_jobs
from app.service.users.user_checks import checked
sys.stdout.write(user_jobs.derive_job(checked(json.loads({json.dumps(json.dumps(SYSTEM))}))).decode())
"""


def _fresh_document() -> dict:
    done = subprocess.run([sys.executable, "-c", FRESH], cwd=ROOT, capture_output=True, text=True, check=True,
                          env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "LAGRANGE_WARM": "0",
                               "LAGRANGE_DERIVE_SECONDS": "900"})  # fmt: skip
    return json.loads(done.stdout)


def test_a_job_whose_clock_fired_is_refused_and_leaves_nothing_poorer_behind(monkeypatch):
    user = checked(SYSTEM)
    refused = 0
    # the clock fires at several points of the derivation and of its document (members, display forms)
    for seconds in (0.02, 0.1, 0.25, 0.5, 1.0):
        monkeypatch.setattr(user_jobs, "engine_seconds", lambda seconds=seconds: seconds)
        try:
            user_jobs.derive_job(user)
        except TooCostly as exc:
            assert "longer to derive than the" in str(exc)
            refused += 1
        else:
            break
    assert refused >= 2  # the clock did fire, more than once
    monkeypatch.setattr(user_jobs, "engine_seconds", lambda: 600.0)
    document = json.loads(user_jobs.derive_job(user))
    assert document["skipped"] == []
    assert document == _fresh_document()


def test_the_modes_job_measures_the_normal_modes_the_derivation_holds():
    """The worker measures the derivation's own normal modes (the member the document prints), with nothing
    sent to it but the system: each predicted ω² is the document's, and each is measured."""
    from app.web.api.examples_user import SPINNING_HOOP

    for spec in (SPINNING_HOOP, DOUBLE_PENDULUM):
        user = checked(spec)
        found = json.loads(user_jobs.modes_job(user))
        document = json.loads(user_jobs.derive_job(user))
        printed = [m["omega_squared"] for e in document["normal_modes"] if e["stable"] and not e["momenta"]
                   for m in e["modes"] if m["omega_squared"] > 0]  # fmt: skip
        assert [m["omega_squared"] for e in found for m in e["modes"] if m["omega_squared"] > 0] == printed
        assert printed and all(m["measured"] is not None for e in found for m in e["modes"] if m["omega_squared"] > 0)
