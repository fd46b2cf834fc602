"""Every scene and test system: the engine's accelerations equal LagrangesMethod's."""

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.scenes import SCENES
from tests.engine.systems import TEST_SYSTEMS
from tests.reference import numerically_equal, reference_accelerations

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

SYSTEMS = {**{f"scene:{k}": s.system for k, s in SCENES.items()}, **TEST_SYSTEMS}


@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_accelerations_match_lagranges_method(name):
    system = SYSTEMS[name]
    ours = derive(system).equations.accelerations
    theirs, _ = reference_accelerations(system)
    symbols = set().union(*(e.free_symbols for e in (*ours, *theirs))) | {sp.Symbol("t", real=True)}
    for a, b in zip(ours, theirs, strict=True):
        assert numerically_equal(a, b, sorted(symbols, key=str)), (name, a, b)
