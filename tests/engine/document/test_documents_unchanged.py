"""The whole document of a user's N-link pendulum, byte for byte as it was before the engine was made faster.

The engine's speed work (issue 47: the document at LagrangesMethod's speed) computes shared pieces once and
skips work whose outcome is known; none of it may change what a reader sees.  Each document (every member:
forms, conservation, equilibria, normal modes, Hamilton's equations, steps) is hashed and compared with the
hash of the document the engine printed before that work (main at eeb4d1a), after an emptied SymPy cache, as
a pool worker prints it.  A change meant to alter what a reader sees updates these hashes in the same commit,
saying so; a change meant only to make the engine faster never does.
"""

import hashlib
import json

import pytest

from app.engine.algebra.work import start_afresh
from app.engine.derivation.derive import derive
from app.engine.document.contract import derivation_json
from app.engine.parser.user_system import UserSystem
from tests.chains import chain_request


def digest(document: dict) -> str:
    return hashlib.sha256(json.dumps(document, sort_keys=True, ensure_ascii=False).encode()).hexdigest()


# the sha256 of each document as printed by the engine before the speed work
BEFORE = {
    2: "70163cb2238ee6cb7210629386b20dfe488a4131227e0abca9f694bad033ef26",
    3: "9898e084b0212cbc2f21086340c5f583ed118c0777c36b7d50da0a92e3dab21c",
    4: "51b7cbfc236c3097195574ac2575de84a58cb0c5d865e4fc26874a4c2de996ef",
    # the 5-link chain's document gained its step-by-step derivation, left out before for its bound of work: the
    # momenta's grouping no longer factors each coefficient to throw the factors away (report.by_inertia), and
    # each equation's factor is read from its display instead of cancelled out of residual/display
    # (report.equation_scales); every other member is as before
    5: "2ab5b4102b2bd83fba10029e39c8a26264b26d24679bf152fa0409bc3d741c07",
}


def document(n: int) -> dict:
    start_afresh()  # as a worker does before each job: the count of work, and so each bound's outcome, its own
    return derivation_json(derive(UserSystem.of(chain_request(n)).system()))


@pytest.mark.parametrize("n", [2, 3, pytest.param(4, marks=pytest.mark.slow), pytest.param(5, marks=pytest.mark.slow)])
def test_the_n_link_documents_are_unchanged(n):
    assert digest(document(n)) == BEFORE[n]
