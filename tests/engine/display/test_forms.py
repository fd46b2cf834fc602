"""The textbook-form simplifier: each rewriting on its own, equality with the input, and its bounds."""

import random

import pytest
import sympy as sp

from app.engine.algebra import work
from app.engine.display import forms
from app.engine.display.forms import textbook_form
from app.engine.parser.symbols import SymbolTable

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

TABLE = SymbolTable(("a", "b", "x1", "x2"), ("m1", "m2", "l1", "l2", "g", "k", "l0", "M"))
NAMES = TABLE.latex_names()
a, b, x1, x2 = TABLE.q
ad, bd, x1d, x2d = TABLE.qd
add, bdd, _, _ = TABLE.qdd
m1, m2, l1, l2, g, k, l0, M = TABLE.params


def _equal(x, y):
    rng = random.Random(1)
    for _ in range(5):
        at = {s: rng.uniform(0.2, 1.8) for s in x.free_symbols | y.free_symbols}
        assert abs(complex((x - y).evalf(subs=at))) < 1e-10


def test_products_of_sines_and_cosines_recombine():
    T = l1 * l2 * m2 * ad * bd * (sp.sin(a) * sp.sin(b) + sp.cos(a) * sp.cos(b))
    shown = textbook_form(sp.expand(T), NAMES)
    assert shown == l1 * l2 * m2 * ad * bd * sp.cos(a - b)


def test_pythagoras():
    expr = sp.expand(l1**2 * ad**2 * (sp.sin(a) ** 2 + sp.cos(a) ** 2) * m1 / 2)
    assert textbook_form(expr, NAMES) == l1**2 * ad**2 * m1 / 2


def test_a_square_of_a_sum_is_recovered():
    U = sp.expand(k * (x2 - x1 - l0) ** 2 / 2)
    shown = textbook_form(U, NAMES)
    assert sp.count_ops(shown) < sp.count_ops(U) and shown.has(sp.Pow(x1 - x2 + l0, 2))
    kinetic = sp.expand(M * (x1d + x2d) ** 2 / 8 + m1 * x1d**2 / 2)
    assert textbook_form(kinetic, NAMES) == M * (x1d + x2d) ** 2 / 8 + m1 * x1d**2 / 2


def test_a_quotient_over_a_whole_denominator():
    D = m1 + m2 - m2 * (sp.sin(a) * sp.sin(b) + sp.cos(a) * sp.cos(b)) ** 2
    acc = sp.expand(g * m2 * sp.sin(b) * sp.cos(a - b).expand(trig=True)) / sp.expand(l1 * D)
    shown = textbook_form(acc, NAMES)
    _equal(shown, acc)
    assert sp.denom(shown) == l1 * (2 * m1 + m2 - m2 * sp.cos(2 * a - 2 * b))


def test_the_engines_form_stays_when_nothing_is_shorter():
    pendulum = m1 * l1**2 * ad**2 / 2 - m1 * g * l1 * (1 - sp.cos(a))
    assert textbook_form(pendulum, NAMES) == pendulum
    # sin a cos a is not traded for sin 2a / 2
    assert textbook_form(ad**2 * sp.sin(a) * sp.cos(a), NAMES) == ad**2 * sp.sin(a) * sp.cos(a)


def test_common_factors_out_of_an_equation_not_out_of_an_energy():
    residual = sp.expand(m1 * l1 * (l1 * add + g * sp.sin(a)))
    assert textbook_form(residual, NAMES) == m1 * l1 * (l1 * add + g * sp.sin(a))
    assert isinstance(textbook_form(sp.expand(m1 * l1 * (l1 * ad**2 / 2 - g * sp.cos(a))), NAMES), sp.Add)


def test_forming_twice_changes_nothing():
    T = sp.expand(l1 * l2 * m2 * ad * bd * sp.cos(a - b).expand(trig=True) + m1 * l1**2 * ad**2 / 2)
    once = textbook_form(T, NAMES)
    assert textbook_form(once, NAMES) is once


def test_bounded_with_the_engines_display_form_as_fallback():
    big = sp.expand((sp.sin(a) + sp.cos(b) + ad + bd + m1 + m2) ** 9)  # beyond the node budget
    before = work.done()
    shown = textbook_form(big, NAMES)
    assert work.done() - before < 3 * (forms.FORM_WORK + forms.FALLBACK_WORK)
    _equal(shown, big)


def test_the_practice_difference_is_the_mistake_alone():
    # the double pendulum's θ₂ equation without its θ̇₁² term: the difference shown is that term, nothing else
    from app.engine.tutor.check import judge, problem
    from app.service.chapter.derivations import derivation

    d = derivation("double-pendulum")
    result = judge(
        problem(d, "equation", "theta2"), "l2*theta2_ddot + l1*cos(theta1 - theta2)*theta1_ddot + g*sin(theta2)"
    )
    assert result["verdict"] == "incorrect"
    assert result["reveal"]["difference"]["sympy"] == "l1*theta1_dot**2*sin(theta1 - theta2)"
    assert "ddot" not in result["reveal"]["difference"]["sympy"]


def test_a_speed_under_a_root_is_formed_without_a_polynomial_error():
    # a generated mistake's piece can be a speed, sqrt(ρ̇² + ω²ρ²): no degree in the velocities to factor by
    rho, rho_dot, omega, m = sp.symbols("rho rho_dot omega m", positive=True)
    speed = m * sp.sqrt(omega**2 * rho**2 + rho_dot**2) / 2 + m * rho_dot**2
    form = textbook_form(speed)
    assert sp.simplify(form - speed) == 0


def test_terms_differing_by_a_parameter_factor_are_one_term():
    # M ẋ₁ + m₁ ẋ₁ + m₁ l₁ ȧ cos a → (M + m₁)ẋ₁ + m₁ l₁ ȧ cos a; M g + m₁ g beside them → (M + m₁)g
    shown = forms.like_terms_added(M * x1d + m1 * x1d + m1 * l1 * ad * sp.cos(a) + M * g + m1 * g, {x1d, ad, a})
    assert shown == (M + m1) * x1d + m1 * l1 * ad * sp.cos(a) + (M + m1) * g
    # a multiplier is an unknown of the motion: λ₂ z − M g z stays two terms
    lam = sp.Symbol("lambda_2", real=True)
    assert forms.like_terms_added(lam * x1 - M * g * x1, {x1}) == lam * x1 - M * g * x1
    # a sign before a bracket stays there
    inner = sp.Mul(-1, sp.Add(M * g * sp.sin(a), m1 * g * sp.sin(a), m1 * ad**2), evaluate=False)
    shown = forms.like_terms_added(inner, {a, ad})
    assert isinstance(shown, sp.Mul) and shown.args[0] == -1 and shown.has((M + m1) * g * sp.sin(a))


def test_a_sum_that_is_a_mass_times_one_plus_more_is_printed_factored():
    """prof-n 6: the helix wrote p_z = m(1 + α²R²) ż and, one line later, (m + mα²R²) z̈; the rotating wire
    𝓜 = 4mα²ρ² + m. A sum whose terms share one mass, one of them the mass alone, is that mass times (1 + …)."""
    shown = textbook_form(M + M * l1**2 * g**2, NAMES)
    assert shown.args.count(M) == 1 and any(isinstance(f, sp.Add) and 1 in f.args for f in shown.args), shown
    _equal(shown, M + M * l1**2 * g**2)
    moving = textbook_form((M + M * l1**2 * g**2) * add, NAMES)
    assert isinstance(moving, sp.Mul) and M in moving.args and add in moving.args, moving
    coordinate = textbook_form(4 * M * l1**2 * a**2 + M, NAMES)
    assert isinstance(coordinate, sp.Mul) and M in coordinate.args, coordinate
    # two masses share nothing to take out: m₁ + m₂ stays
    assert textbook_form(m1 + m2 * a**2, NAMES) == m1 + m2 * a**2


def test_a_mass_times_one_plus_more_is_taken_out_within_a_sum_too():
    """prof-n 6: the rotating wire printed d/dt ∂L/∂ρ̇ = (4mα²ρ² + m) ρ̈ + 8mα²ρρ̇²: the rule that writes
    4mα²ρ² + m as m(1 + 4α²ρ²) reaches each term of a sum."""
    expr = (4 * M * l1**2 * a**2 + M) * add + 8 * M * l1**2 * a * ad**2
    shown = forms.mass_out(expr)
    _equal(shown, expr)
    inertia = next(t for t in sp.Add.make_args(shown) if t.has(add))
    assert M in sp.Mul.make_args(inertia) and sp.Add(1, 4 * l1**2 * a**2) in sp.Mul.make_args(inertia), shown
    # a sum with nothing to take out is the same object
    plain = m1 * add + m2 * ad**2
    assert forms.mass_out(plain) is plain


def test_a_settled_form_is_found_again_when_the_store_is_full(monkeypatch):
    """A long-lived process fills the store of forms: a form settled then must still be the one printed (the
    tabletop spring's d/dt ∂L/∂θ̇ = m r² θ̈ + 2 m r ṙ θ̇ was formed again into m r(r θ̈ + 2 ṙ θ̇) once it was full)."""
    monkeypatch.setattr(forms, "_CACHE", {})
    monkeypatch.setattr(forms, "_SETTLED", {})
    monkeypatch.setattr(forms, "_CACHE_SIZE", 3)
    for k in range(1, 5):
        forms.settle(textbook_form(k * m1 * ad**2 + a, NAMES), NAMES)
    assert len(forms._CACHE) == 3 and len(forms._SETTLED) == 3
    # as built, not as the search would write it: m₁ a ȧ² + 2 m₁ a² ä, never m₁ a(ȧ² + 2 a ä)
    built = sp.Add(m1 * a * ad**2, 2 * m1 * a**2 * add)
    assert forms.settle(built, NAMES) is built
    assert textbook_form(built, NAMES) is built
    assert len(forms._SETTLED) == 3


def test_a_search_finishing_after_a_settle_does_not_replace_the_settled_form(monkeypatch):
    """Two threads: one settles a form as built while the other's search of the same expression finishes and
    stores its own (the warm-up derives scenes side by side): the settled form is still the one printed."""
    monkeypatch.setattr(forms, "_CACHE", {})
    monkeypatch.setattr(forms, "_SETTLED", {})
    built = sp.Add(m1 * a * ad**2, 2 * m1 * a**2 * add)
    searched = textbook_form(sp.expand(built), NAMES)
    assert sp.srepr(searched) != sp.srepr(built)  # the search writes it another way: m₁ a(ȧ² + 2 a ä)
    forms.settle(built, NAMES)
    # the other thread's search, finishing now, stores its form under the same expression
    forms._CACHE[(sp.expand(built), frozenset(forms.moving_symbols(built, NAMES)))] = searched
    assert textbook_form(built, NAMES) is built
