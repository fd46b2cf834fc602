"""Compiled user systems are found by their declaration before any code generation (issue 35)."""

from __future__ import annotations

import pytest

from app.engine.derivation.derive import derive, value_or
from app.service.chapter import compiled
from app.service.chapter.compiled import Compiled, system_key
from app.service.chapter.derivations import derivation
from tests.engine.document.test_staged import chain

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


def test_a_warm_user_system_is_found_without_generating_code(monkeypatch):
    d = derive(chain(2))
    cache = Compiled()
    first = cache.get(None, d, [])

    def no_generation(*args, **kwargs):
        raise AssertionError("code generated again for a warm system")

    monkeypatch.setattr(compiled, "numeric_system", no_generation)
    monkeypatch.setattr(compiled, "generated_sources", no_generation)
    assert cache.get(None, d, []) is first
    # the same declaration derived again (another request, another worker's derivation object) is the same key
    assert cache.get(None, derive(chain(2)), []) is first


def test_the_key_is_the_declaration_and_its_constraint_forces():
    d2, d3 = derive(chain(2)), derive(chain(3))
    assert system_key(d2, []) == system_key(derive(chain(2)), [])
    assert system_key(d2, []) != system_key(d3, [])
    forces = value_or(derivation("simple-pendulum").constraint_forces, ())
    assert forces and system_key(d2, []) != system_key(d2, forces)


@pytest.mark.parametrize("n", [3])
def test_a_large_chain_compiles_from_mass_matrix_and_forcing(n):
    # M⁻¹f is not a closed form here: the generated right-hand side solves M q_ddot = f
    d = derive(chain(n))
    system, _ = Compiled().get(None, d, [])
    assert "_x0" in system.sources["rhs"]
    assert "jac" not in system.sources
