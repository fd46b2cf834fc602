"""Display simplification under time budgets: what is remembered and what is tried again."""

from __future__ import annotations

import time

import pytest
import sympy as sp

from app.engine import budget

x, y = sp.symbols("x y")


@pytest.fixture
def slow_simplify(monkeypatch):
    """sympy.simplify as the budget calls it: SymPy work for 2 s (the budget's signal is raised only in
    SymPy's or the app's frames), counting its calls."""
    calls = []
    budget.tidy((x + 3) ** 2 / (x + y))  # first calls load code (SymPy's units, the cheap step's): not in the budgets

    def slow(expr, *args, **kwargs):
        calls.append(expr)
        end = time.monotonic() + 2.0
        while time.monotonic() < end:
            sp.expand((x + y) ** 3)
        return expr

    monkeypatch.setattr(budget.sp, "simplify", slow)
    monkeypatch.setattr(budget, "_TIDY_CACHE", {})
    return calls


def test_a_simplification_out_of_its_own_time_is_not_tried_again(slow_simplify):
    expr = (x + 1) ** 2 / (x + y)
    first = budget.tidy(expr, seconds=0.1)
    assert len(slow_simplify) == 1
    assert budget.tidy(expr, seconds=0.1) == first
    assert len(slow_simplify) == 1  # remembered: the same attempt would run out again


def test_one_cut_short_by_a_shared_budget_is_tried_again_later(slow_simplify):
    expr = (x + 2) ** 2 / (x - y)
    with budget.display_budget(0.1):  # less than the expression's own 0.2 s: the shared budget cut it
        budget.tidy(expr, seconds=0.2)
    assert len(slow_simplify) == 1
    budget.tidy(expr, seconds=0.2)
    assert len(slow_simplify) == 2


def _busy(seconds: float) -> str:
    """SymPy work for ``seconds`` (the budget's signal is raised only in SymPy's or the app's frames)."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        sp.expand((x + y) ** 12)
    return "done"


def test_patience_lengthens_every_bound_in_its_block_and_only_there():
    from app.engine.budget import bounded, display_budget, display_seconds_left, patience

    skipped: list = []
    assert bounded("m", "A member", 0.02, lambda: _busy(0.1), "fallback", skipped) == "fallback"
    assert [s.member for s in skipped] == ["m"]
    with patience(50):
        assert bounded("m", "A member", 0.02, lambda: _busy(0.1), "fallback", skipped) == "done"
        with display_budget(0.01):
            assert display_seconds_left(0.01) > 0.1  # the shared display budget is as patient
    assert len(skipped) == 1
    assert bounded("m", "A member", 0.02, lambda: _busy(0.1), "fallback", skipped) == "fallback"
