"""The derivatives on symengine (app.engine.algebra.fast) equal SymPy's, symbol for symbol and assumption for assumption."""

from __future__ import annotations

import pytest
import sympy as sp

from app.engine.algebra.fast import Fast, convertible
from app.engine.equations import lagrange
from app.engine.equations.mechanics import build_mechanics
from tests.engine.document.test_staged import chain


def test_round_trip_keeps_symbols_and_their_assumptions():
    q, m = sp.Symbol("q", real=True), sp.Symbol("m", positive=True)
    e = sp.sin(q) ** 2 * m / 3 + sp.sqrt(q) + sp.exp(q) * sp.Float(1.5) - sp.cot(m * q) + sp.log(q)
    fast = Fast([q, m])
    back = fast.back(fast.to(e))
    assert back == e
    assert back.free_symbols == {q, m}


def test_only_smooth_functions_go_to_symengine():
    x = sp.Symbol("x", real=True)
    assert convertible([sp.sin(x) + sp.exp(x) * sp.tanh(x)])
    assert not convertible([sp.Abs(x)])
    assert not convertible([sp.sign(x) * x])


@pytest.mark.slow
def test_symengine_and_sympy_derive_the_same_equations(monkeypatch):
    mech = build_mechanics(chain(3))
    on_symengine = lagrange._on_symengine(mech)
    on_sympy = lagrange._on_sympy(mech)
    for fast_part, slow_part in zip(on_symengine, on_sympy, strict=True):
        for a, b in zip(fast_part, slow_part, strict=True):
            assert sp.expand(a - b) == 0
    # and the engine takes the symengine path for it
    calls = []
    monkeypatch.setattr(lagrange, "_on_symengine", lambda m: calls.append(m) or on_symengine)
    lagrange.euler_lagrange(mech)
    assert calls == [mech]
