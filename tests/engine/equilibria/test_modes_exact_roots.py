"""omega^2 in closed form: roots from low-degree factors only when the coefficients hold parameters."""

from __future__ import annotations

import pytest
import sympy as sp

from app.engine.display.forms import roots_compacted
from app.engine.equilibria import modes_exact


def _triple_pendulum() -> tuple[sp.Matrix, sp.Matrix]:
    """M and K of the triple pendulum hanging at rest (links l₁, l₂, l₃, bobs m₁, m₂, m₃)."""
    m1, m2, m3, l1, l2, l3, g = sp.symbols("m1 m2 m3 l1 l2 l3 g", positive=True)
    s1, s2 = m1 + m2 + m3, m2 + m3
    M = sp.Matrix([[l1**2 * s1, l1 * l2 * s2, l1 * l3 * m3], [l1 * l2 * s2, l2**2 * s2, l2 * l3 * m3],
                   [l1 * l3 * m3, l2 * l3 * m3, l3**2 * m3]])  # fmt: skip
    return M, sp.diag(g * l1 * s1, g * l2 * s2, g * l3 * m3)


def _coupled_pair_beside_a_free_one() -> tuple[sp.Matrix, sp.Matrix, tuple[sp.Symbol, ...]]:
    """Two coupled coordinates beside a free one: det(K − λM) is a linear times a quadratic factor."""
    m, k, c = sp.symbols("m k c", positive=True)
    return sp.Matrix([[2 * m, m, 0], [m, 2 * m, 0], [0, 0, m]]), sp.diag(k, k, c), (m, k, c)


def test_irreducible_characteristic_polynomial_gives_no_closed_form() -> None:
    """The triple pendulum at rest: det(K - lambda M) has no factor, so no root is attempted (Cardano's would
    run past MAX_EXACT_OPS and the time this step is given)."""
    M, K = _triple_pendulum()
    assert modes_exact._irreducible_at_a_point(M, K, sp.Dummy("lambda"))
    assert modes_exact._roots(M, K) == []


def test_a_cubic_that_factors_still_has_its_closed_forms() -> None:
    """A block of two coupled coordinates beside a free one: a linear times a quadratic factor, all three found."""
    M, K, (m, k, c) = _coupled_pair_beside_a_free_one()
    roots = modes_exact._roots(M, K)
    assert len(roots) == 3
    assert {sp.simplify(r) for r in roots} == {c / m, k / m, k / (3 * m)}


def test_numeric_cubic_keeps_cardano() -> None:
    """Without parameters the general formulas still run (their results may be short)."""
    M = sp.eye(3)
    K = sp.Matrix([[2, -1, 0], [-1, 2, -1], [0, -1, 2]])
    roots = modes_exact._roots(M, K)
    assert len(roots) == 3
    assert sorted(float(sp.re(sp.N(r))) for r in roots) == sorted(float(v) for v in (2 - sp.sqrt(2), 2, 2 + sp.sqrt(2)))


def test_irreducible_at_a_point_decides_before_the_symbolic_determinant() -> None:
    """The triple pendulum's det(K − λM) is shown irreducible from numbers put in; a determinant that factors
    (a coupled pair beside a free coordinate) never is."""
    M, K = _triple_pendulum()
    lam = sp.Dummy("lambda")
    assert modes_exact._irreducible_at_a_point(M, K, lam)
    M, K, _ = _coupled_pair_beside_a_free_one()
    assert not modes_exact._irreducible_at_a_point(M, K, lam)


def test_an_irreducible_numeric_cubic_keeps_its_closed_forms() -> None:
    """Numbers only: the shortcut for parameters never applies, so Cardano's formulas still give three roots."""
    M = sp.eye(3)
    K = sp.Matrix([[3, -1, 0], [-1, 3, -1], [0, -1, 2]])
    lam = sp.Dummy("lambda")
    assert sp.Poly((K - lam * M).det(), lam).is_irreducible
    roots = modes_exact._roots(M, K)
    assert len(roots) == 3
    values = sorted(complex(sp.N(r)).real for r in roots)
    expected = sorted(complex(sp.N(v)).real for v in K.eigenvals(multiple=True))
    assert all(abs(a - b) < 1e-9 for a, b in zip(values, expected, strict=True))


@pytest.mark.slow
def test_equilibria_with_opposite_stiffness_factor_one_discriminant(monkeypatch) -> None:
    from app.engine.algebra.budget import display_budget

    # the double pendulum at (0, 0) and at (π, π): the same M, K → −K
    g, l1, l2, m1, m2 = sp.symbols("g l1 l2 m1 m2", positive=True)
    M = sp.Matrix([[l1**2 * (m1 + m2), l1 * l2 * m2], [l1 * l2 * m2, l2**2 * m2]])
    K = sp.Matrix([[g * l1 * (m1 + m2), 0], [0, g * l2 * m2]])
    factored = []
    factor = sp.factor
    monkeypatch.setattr(modes_exact.sp, "factor", lambda e, *a, **k: factored.append(e) or factor(e, *a, **k))
    with display_budget(10):
        down, up = modes_exact._roots(M, K), modes_exact._roots(M, -K)
    discriminants = [e for e in factored if e.has(g**2)]
    assert len(discriminants) == 1
    # ω² at (π, π) is −ω² at (0, 0)
    assert {sp.simplify(x) for x in up} == {sp.simplify(-x) for x in down}


def test_an_entry_is_put_in_its_normal_form_once_per_document(monkeypatch) -> None:
    from app.engine.algebra.budget import display_budget

    x, y = sp.symbols("x y")
    cancelled = []
    cancel = sp.cancel
    monkeypatch.setattr(modes_exact.sp, "cancel", lambda e, *a, **k: cancelled.append(e) or cancel(e, *a, **k))
    entry = (x**2 - y**2) / (x + y)
    with display_budget(10):
        assert modes_exact.cheap(entry) == x - y and modes_exact.cheap(entry) == x - y
    assert len(cancelled) == 1
    assert modes_exact.cheap(entry) == x - y and len(cancelled) == 2  # outside a document: every time


def _double_pendulum() -> tuple[sp.Matrix, sp.Matrix, dict[sp.Symbol, sp.Symbol]]:
    """M and K of the double pendulum hanging at rest, in plain symbols, with their positive stand-ins."""
    m1, m2, l1, l2, g = sp.symbols("m_1 m_2 l_1 l_2 g")
    M = sp.Matrix([[(m1 + m2) * l1**2, m2 * l1 * l2], [m2 * l1 * l2, m2 * l2**2]])
    K = sp.diag((m1 + m2) * g * l1, m2 * g * l2)
    return M, K, {s: sp.Symbol(s.name, positive=True) for s in (m1, m2, l1, l2, g)}


@pytest.mark.slow
def test_the_double_pendulums_frequencies_print_compactly_with_the_same_values() -> None:
    """ω² = g[(m₁ + m₂)(l₁ + l₂) ∓ √(…)]/(2m₁l₁l₂): one square root (never √(m₁ + m₂) √(…)), the shared
    m₁ + m₂ taken out of the sum beside it and out of the radicand; equal to the quadratic formula's roots."""
    import random

    M, K, assume = _double_pendulum()
    m1, m2, l1, l2, g = sorted(assume, key=lambda s: ["m_1", "m_2", "l_1", "l_2", "g"].index(s.name))
    roots = modes_exact.eigenvalues(M, K, assume)
    assert len(roots) == 2
    for r in roots:
        assert len([p for p in r.atoms(sp.Pow) if p.exp == sp.S.Half]) == 1, r
        assert r.has((l1 + l2) * (m1 + m2)), r
        radicand = next(p.base for p in r.atoms(sp.Pow) if p.exp == sp.S.Half)
        assert isinstance(radicand, sp.Mul) and m1 + m2 in radicand.args, radicand
        assert sp.count_ops(r) <= 21, (r, sp.count_ops(r))
    # the roots of det(K − λM) = aλ² + bλ + c, as the quadratic formula gives them
    a, c = M.det(), K.det()
    b = -(K[0, 0] * M[1, 1] + K[1, 1] * M[0, 0] - 2 * K[0, 1] * M[0, 1])
    old = [(-b - sp.sqrt(b**2 - 4 * a * c)) / (2 * a), (-b + sp.sqrt(b**2 - 4 * a * c)) / (2 * a)]
    rng = random.Random(40)
    for _ in range(20):
        at = {s: rng.uniform(0.1, 5.0) for s in (m1, m2, l1, l2, g)}
        new = sorted(float(r.xreplace(at)) for r in roots)
        want = sorted(float(r.xreplace(at)) for r in old)
        assert new == pytest.approx(want, rel=1e-12)


@pytest.mark.slow
def test_a_product_of_roots_is_one_root_only_where_that_holds() -> None:
    """√a √b = √(ab) when a ≥ 0 (by the declared signs); √(x − y) √(y − x) stays, neither known ≥ 0 (where
    both radicands are negative, √a √b = −√(ab))."""
    x, y = sp.symbols("x y")
    signs = {x: sp.Symbol("x", positive=True), y: sp.Symbol("y", positive=True)}
    joined = roots_compacted(sp.sqrt(x + y) * sp.sqrt(x**2 - y), signs)
    assert joined == sp.sqrt((x + y) * (x**2 - y))
    apart = sp.sqrt(x - y) * sp.sqrt(y - x)
    assert roots_compacted(apart, signs) == apart
    # a shared factor out of the sum beside a root
    m, l1, l2 = sp.symbols("m l_1 l_2")
    assert roots_compacted(m * l1 + m * l2 + sp.sqrt(l1), {}) == m * (l1 + l2) + sp.sqrt(l1)
