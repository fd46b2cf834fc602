"""Display simplification under bounds of work: what is remembered and what is tried again."""

from __future__ import annotations

import time

import pytest
import sympy as sp

from app.engine.algebra import budget, simplify

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

x, y = sp.symbols("x y")


@pytest.fixture
def slow_simplify(monkeypatch):
    """sympy.simplify as the budget calls it: SymPy work for up to 2 s (far more than the bounds below allow,
    so the bound ends it), counting its calls."""
    calls = []
    simplify.tidy((x + 3) ** 2 / (x + y))  # first calls load code (SymPy's units, the cheap step's): not in the budgets

    def slow(expr, *args, **kwargs):
        calls.append(expr)
        end = time.monotonic() + 2.0
        while time.monotonic() < end:
            sp.expand((x + y) ** 3)
        return expr

    monkeypatch.setattr(simplify.sp, "simplify", slow)
    monkeypatch.setattr(simplify, "_TIDY_CACHE", {})
    return calls


def test_a_simplification_out_of_its_own_time_is_not_tried_again(slow_simplify):
    expr = (x + 1) ** 2 / (x + y)
    first = simplify.tidy(expr, units=2_000)
    assert len(slow_simplify) == 1
    assert simplify.tidy(expr, units=2_000) == first
    assert len(slow_simplify) == 1  # remembered: the same attempt would run out again


def test_one_cut_short_by_a_shared_budget_is_tried_again_later(slow_simplify):
    expr = (x + 2) ** 2 / (x - y)
    with budget.display_budget(2_000):  # less than the expression's own 4,000 units: the shared budget cut it
        simplify.tidy(expr, units=4_000)
    assert len(slow_simplify) == 1
    simplify.tidy(expr, units=4_000)
    assert len(slow_simplify) == 2


def _busy(times: int) -> str:
    """New SymPy work (a fresh symbol: nothing from SymPy's cache) ``times`` times over (about 2,300 units each)."""
    z = sp.Dummy()
    for i in range(times):
        sp.expand((x + z + i) ** 14)
    return "done"


def test_patience_lengthens_every_bound_in_its_block_and_only_there():
    from app.engine.algebra.budget import bounded, display_budget, display_work_left, patience

    skipped: list = []
    assert bounded("m", "A member", 2_000, lambda: _busy(5), "fallback", skipped) == "fallback"
    assert [s.member for s in skipped] == ["m"]
    with patience(50):
        assert bounded("m", "A member", 2_000, lambda: _busy(5), "fallback", skipped) == "done"
        with display_budget(100):
            assert display_work_left(100) == 5_000  # the shared display budget is as patient
    assert len(skipped) == 1
    assert bounded("m", "A member", 2_000, lambda: _busy(5), "fallback", skipped) == "fallback"


def _random_products(count: int) -> list[sp.Expr]:
    import random

    rng = random.Random(7)
    g, l, m, q = sp.symbols("g l m q")  # noqa: E741
    factors = [g, l, m, q, sp.Rational(-3, 2), sp.Integer(4)]
    functions = [sp.sin(q), sp.cos(q), sp.tan(q), sp.exp(q), sp.cos(2 * q), sp.sin(q / 2)]
    out = []
    for _ in range(count):
        expr = sp.Mul(*(f ** rng.choice([-2, -1, 1, 2, 3]) for f in rng.sample(factors, rng.randint(1, 4))))
        out.append(expr * rng.choice(functions) ** rng.choice([-1, 1, 2]) if rng.random() < 0.8 else expr)
    return out


def test_a_product_with_one_function_is_not_simplified_and_simplify_would_not_change_it(monkeypatch):
    products = _random_products(120)
    assert all(simplify._product(e) for e in products)
    # what the shortcut leaves out: simplify would have returned each one as it is
    assert [e for e in products if sp.simplify(e) != e] == []
    calls = []
    monkeypatch.setattr(simplify, "_TIDY_CACHE", {})
    monkeypatch.setattr(simplify.sp, "simplify", lambda e, *a, **k: calls.append(e) or e)
    assert [simplify.tidy(e) for e in products] == products and calls == []
    # a sum, two functions or a root still go to simplify
    for expr in (x + y, sp.sin(x) * sp.cos(x), sp.sqrt(x**2 * y)):
        assert not simplify._product(expr)
        simplify.tidy(expr)
    assert len(calls) == 3


def test_a_charged_memo_counts_the_remembered_work_again_and_runs_into_a_limit_as_the_work_would():
    from app.engine.algebra import work

    x, y = sp.symbols("x y")
    computed = []

    def compute() -> sp.Expr:
        computed.append(1)
        return sp.expand((x + y) ** 6)

    with budget.display_budget(10**9):
        start = work.done()
        first = budget.memoized("test-charged", "key", compute, charged=True)
        cost = work.done() - start
        again = work.done()
        assert budget.memoized("test-charged", "key", compute, charged=True) == first
        # computed once, counted twice
        assert computed == [1] and cost > 0 and work.done() - again == cost
        # within a limit too small for the work, the remembered result is refused as the work would be
        with pytest.raises(work.WorkExceeded), work.limit(cost // 2):
            budget.memoized("test-charged", "key", compute, charged=True)
        assert computed == [1]
