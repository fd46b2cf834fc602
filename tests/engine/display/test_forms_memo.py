"""The display forms' shortcuts give what the long way gives (issue 35: the whole document's time)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from sympy.simplify.fu import TR8

from app.engine.algebra import budget
from app.engine.algebra.budget import display_budget, memoized
from app.engine.derivation.derive import derive
from app.engine.display import forms
from app.engine.document.contract import derivation_json
from tests.engine.document.test_staged import chain

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

x, y, z, a = sp.symbols("x y z a")
ANGLES = [x, y, z, x - y, 2 * x - 2 * y, x + y - z, 3 * z, x / 2]


def _random_sum(rng: random.Random, atoms: list[sp.Expr]) -> sp.Expr:
    return sp.Add(*(
        sp.Mul(*(rng.choice(atoms) ** rng.randint(1, 3) for _ in range(rng.randint(1, 4))))
        for _ in range(rng.randint(1, 4))
    ))  # fmt: skip


def test_products_to_sums_is_what_tr8_gives() -> None:
    """Term by term, with each product turned once: the same expanded sum as TR8 on the whole (sines inside
    other factors, numbers and π in angles, tangents and reciprocals included)."""
    atoms = [sp.sin(x), sp.cos(x), sp.sin(y), sp.cos(x - y), sp.cos(2 * x - z), sp.sin(z), a, x, sp.Rational(1, 2),
             sp.sin(1), sp.cos(sp.pi / 5 + x), sp.sqrt(1 + sp.sin(x) ** 2), 1 / sp.cos(y), sp.tan(x)]  # fmt: skip
    rng = random.Random(1)
    with display_budget(600):
        for _ in range(120):
            e = _random_sum(rng, atoms)
            assert forms._products_to_sums(e) == sp.expand(TR8(sp.expand(e))), e


def test_short_products_turned_directly_agree_with_tr8() -> None:
    rng = random.Random(5)
    checked = 0
    for _ in range(300):
        product = sp.Mul(*(rng.choice([sp.sin, sp.cos])(rng.choice(ANGLES)) for _ in range(rng.randint(2, 4))))
        factors = [f for f in sp.Mul.make_args(product) if not f.is_Number]
        product = sp.Mul(*factors)
        if sum(int(f.exp) if f.is_Pow else 1 for f in factors) <= forms.MAX_SUM_DEGREE:
            checked += 1
        assert sp.expand(forms._product_to_sum(product, factors)) == sp.expand(TR8(product)), product
    assert checked > 100


def test_tr8_leaves_powers_of_its_sums_beyond_the_direct_degree() -> None:
    """Why longer products stay with TR8: there it does not give one sum of single sines and cosines."""
    assert sp.expand(TR8(sp.sin(x) ** 4)).has(sp.cos(2 * x) ** 2)
    assert forms.MAX_SUM_DEGREE < 4


def test_memo_lives_within_one_document() -> None:
    calls: list[int] = []

    def work() -> int:
        calls.append(1)
        return len(calls)

    assert memoized("test", "key", work) == 1 and memoized("test", "key", work) == 2  # no document: every time
    with display_budget(10):
        assert memoized("test", "key", work) == 3
        with display_budget(5):  # a document inside a document (the transformed derivation) shares it
            assert memoized("test", "key", work) == 3
        assert memoized("test", "key", work) == 3
    assert budget.document_memo() is None
    with display_budget(10):
        assert memoized("test", "key", work) == 4  # the next document starts empty


def test_a_late_search_that_ran_out_stops_larger_ones() -> None:
    """Past the shared budget, once a search ran out at some size, larger expressions take the cheap form."""
    expr = sp.expand((x + y + a) ** 3 * sp.sin(x) * sp.cos(y))
    with display_budget(0.0):
        memo = budget.document_memo()
        assert memo is not None
        memo[forms._LATE_LIMIT] = 10
        assert forms.textbook_form(expr, {}) == forms._fallback(expr)


def _squared(e: sp.Expr) -> bool:
    return any(isinstance(b, sp.Add) and n == 2 for b, n in (f.as_base_exp() for f in sp.Mul.make_args(e)))


def test_square_free_at_a_point_proves_only_square_free() -> None:
    """The shortcut past factoring says square-free only where factoring finds no squared sum."""
    k, l0 = sp.symbols("k l0")
    rng = random.Random(3)
    atoms = [x, y, z, a, sp.sin(x), sp.cos(y), sp.Rational(1, 2), x + y, a - k, sp.sqrt(z), sp.cos(x - y)]
    for _ in range(150):
        e = _random_sum(rng, atoms)
        if rng.random() < 0.4:
            e = sp.expand(e * rng.choice([x + y, a - k, sp.sin(x) + 1, x]) ** 2)
        factored, got = sp.factor(e), forms._squared_factors(e)
        # what squares() reads: a squared sum among the factors, and then that factorisation
        assert _squared(got) == _squared(factored), e
        assert got == factored or not _squared(factored), e
    assert not forms._square_free_at_a_point(sp.expand(k * (x - y + l0) ** 2))
    assert forms._square_free_at_a_point(sp.expand(x**2 + y**2))


def test_hamiltons_p_dot_keeps_its_squared_denominator() -> None:
    """ṗ₁ of the double pendulum over (m₁ + m₂ sin²(θ₁ − θ₂))²: a textbook keeps the power; multiplied out into
    sums of single sines and cosines it runs to several times the length."""
    ham = derivation_json(derive(chain(2)))["hamilton"]
    assert ham is not None
    text = ham["equations"][0]["p_dot"]["sympy"]
    assert "3*q1" not in text and ")**2" in text, text


def test_a_terms_degree_in_the_velocities_is_its_polynomials() -> None:
    rng = random.Random(3)
    a, b, m, th = sp.symbols("a b m theta")
    ad, bd = sp.symbols("a_dot b_dot")
    factors = [a, b, m, sp.cos(th), sp.sin(a - b), ad, bd, ad + bd, m * ad - bd, sp.Rational(1, 2)]
    for _ in range(300):
        term = sp.Mul(*(f ** rng.randint(1, 3) for f in rng.sample(factors, rng.randint(1, 4))))
        assert forms._degree_in(term, [ad, bd]) == sp.Poly(term, ad, bd).total_degree(), term


def test_lowest_terms_is_cancels_up_to_a_constant() -> None:
    rng = random.Random(11)
    a, b, m1, m2, l1 = sp.symbols("a b m1 m2 l1")
    pieces = [a, b, m1, m2, l1, sp.sin(a - b), sp.cos(a - b), sp.sin(a), m1 + m2 * sp.sin(a - b) ** 2, m1 - 2 * m2]

    def poly(terms: int) -> sp.Expr:
        return sp.Add(*(rng.randint(-3, 3) * sp.Mul(*rng.sample(pieces, rng.randint(1, 3))) for _ in range(terms)))

    checked = 0
    for _ in range(150):
        common = sp.Mul(*rng.sample(pieces, rng.randint(0, 2)))  # a factor above and below, sometimes squared
        # multiplied out, so that SymPy's own products do not cancel the common factor on sight
        expr = sp.expand(poly(4) * common) / sp.expand(rng.choice([1, 2, -3]) * poly(2) * common ** rng.randint(1, 2))
        if expr.is_zero or not sp.denom(sp.together(expr)).free_symbols:
            continue
        num, den = forms.lowest_terms(expr)
        ref_num, ref_den = sp.fraction(sp.cancel(sp.together(expr)))
        # the same numerator and the same denominator, each up to the same constant
        ratio = sp.cancel(num / ref_num)
        assert ratio.is_Number and sp.cancel(den / ref_den) == ratio, expr
        checked += 1
    assert checked > 100


def test_a_sum_of_two_terms_has_no_squared_sum_in_it() -> None:
    # why squares() leaves parts of fewer than three terms alone: m₁ + m₂ = m₁(1 + m₂/m₁) is square-free
    # up to a monomial; checked against SymPy's square-free decomposition on random ones
    rng = random.Random(5)
    x, y, k = sp.symbols("x y k")
    gens = [x, y, k, sp.sin(x), sp.cos(y)]

    def monomial() -> sp.Expr:
        return sp.Mul(*(g ** rng.randint(0, 4) for g in gens))

    for _ in range(300):
        part = rng.choice([1, -2, 3]) * monomial() + rng.choice([1, -1, 4, sp.Rational(1, 2)]) * monomial()
        _, factors = sp.sqf_list(part)
        assert not any(k >= 2 and isinstance(f, sp.Add) for f, k in factors), part
