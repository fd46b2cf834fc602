"""What every pool worker has done before its first job: one small derivation, in the forkserver.

The forkserver imports this module last (``PRELOAD`` in app/service/runtime/worker.py), after the engine and
SciPy.  A worker forked before it ran a first job that loaded the rest: SymPy's solvers and printers on
their first call, the lambdified NumPy code of the equilibria's search, SciPy's root finders.  A single
pendulum's document took 0.20 s as a worker's first job against 0.10 s as its second.  Every worker is
forked from the forkserver (at the start, after MAX_TASKS jobs, after a retirement or a timeout), so each
starts with that done.

The system's names are used by no example, test or benchmark, so that no memo of this derivation answers
for a system someone types (the per-worker derivation memo of ``user_jobs`` would, for this one only).
"""

from __future__ import annotations

import logging

from app.engine.parser.user_system import UserSystem
from app.service.users.user_jobs import derive_job

log = logging.getLogger(__name__)

# a pendulum: angles, sines and cosines, equilibria, normal modes, Hamilton's equations, the reduction
SWING = {
    "coordinates": ["warmangle"],
    "parameters": [
        {"name": "warmmass", "value": 2.0, "min": 0.01},
        {"name": "warmlength", "value": 0.5, "min": 0.01},
        {"name": "warmgravity", "value": 9.8, "min": 0.01},
    ],
    "particles": [{"mass": "warmmass", "position": ["warmlength*sin(warmangle)", "0", "-warmlength*cos(warmangle)"]}],
    "potential": "-warmmass*warmgravity*warmlength*cos(warmangle)",
}


def warm() -> int:
    """The swing's document, derived once here; its size in bytes (0 if it failed: warming is optional)."""
    try:
        return len(derive_job(UserSystem.of(SWING)))
    except Exception:  # noqa: BLE001 - a worker that starts cold still answers, only later
        log.warning("the workers' warm-up derivation failed", exc_info=True)
        return 0


DOCUMENT_BYTES = warm()
