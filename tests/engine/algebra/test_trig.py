"""Pairs of products of sines and cosines merged by the angle-sum formulas (app/engine/algebra/trig.py)."""

from __future__ import annotations

import random

import pytest
import sympy as sp

from app.engine.algebra.trig import merged
from app.engine.equations.mechanics import build_mechanics
from tests.engine.document.test_staged import chain

a, b, c, k, m = sp.symbols("a b c k m")


def _equal(x: sp.Expr, y: sp.Expr) -> bool:
    """Equal at five random points (to 30 digits): sin² + cos² = 1 is left for the numbers to show."""
    rng = random.Random(5)
    for _ in range(5):
        point = {s: sp.Float(rng.uniform(-2, 2), 30) for s in (x - y).free_symbols}
        if abs(sp.N((x - y).xreplace(point), 30)) > 1e-25:
            return False
    return True


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        (k * sp.sin(a) * sp.sin(b) + k * sp.cos(a) * sp.cos(b), k * sp.cos(a - b)),
        (-k * sp.sin(a) * sp.sin(b) + k * sp.cos(a) * sp.cos(b), k * sp.cos(a + b)),
        (3 * sp.sin(a) * sp.cos(b) - 3 * sp.cos(a) * sp.sin(b), 3 * sp.sin(a - b)),
        (sp.sin(a) * sp.cos(b) + sp.cos(a) * sp.sin(b) + c, sp.sin(a + b) + c),
    ],
)
def test_each_angle_sum_formula_read_backwards(expr: sp.Expr, expected: sp.Expr) -> None:
    assert merged(expr) == expected


def test_terms_that_do_not_pair_stay_as_they_are() -> None:
    """Coefficients that differ (other than in sign), one angle twice, or a lone product: nothing to merge."""
    for expr in (
        k * sp.sin(a) * sp.sin(b) + 2 * k * sp.cos(a) * sp.cos(b),
        k * sp.sin(a) * sp.sin(b) + m * sp.cos(a) * sp.cos(b),
        sp.sin(a) ** 2 + sp.cos(a) ** 2,
        k * sp.sin(a) * sp.cos(b),
    ):
        assert merged(expr) == expr


@pytest.mark.slow
def test_random_sums_merge_into_equal_and_never_longer_expressions() -> None:
    rng = random.Random(11)
    angles = [a, b, c, a - b]
    coefficients = [1, -1, 2, k, -k, m * k, sp.Rational(1, 2)]
    for _ in range(200):
        terms = []
        for _ in range(rng.randint(1, 6)):
            f, g = rng.sample(angles, 2)
            kind = rng.choice([(sp.sin, sp.sin), (sp.cos, sp.cos), (sp.sin, sp.cos), (sp.cos, sp.sin)])
            terms.append(rng.choice(coefficients) * kind[0](f) * kind[1](g))
        expr = sp.Add(*terms)
        out = merged(expr)
        assert _equal(out, expr), expr
        assert sp.count_ops(out) <= sp.count_ops(expr), expr


@pytest.mark.slow
@pytest.mark.parametrize("n", [2, 3, 5])
def test_a_chains_kinetic_energy_holds_cosines_of_differences(n: int) -> None:
    """v² of a chain's last bob: lᵢ lⱼ θ̇ᵢ θ̇ⱼ cos(θᵢ − θⱼ) for each pair, no product of sines or cosines left."""
    mech = build_mechanics(chain(n))
    q = mech.table.q
    for i in range(n):
        for j in range(i + 1, n):
            assert mech.T.has(sp.cos(q[i] - q[j]))
    for term in sp.Add.make_args(mech.T):
        assert sum(1 for f in sp.Mul.make_args(term) if isinstance(f, (sp.sin, sp.cos))) <= 1, term
