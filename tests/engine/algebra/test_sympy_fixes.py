"""The step around SymPy's slow ``Factors`` comparison changes no answer and does step around it."""

import random
from collections import defaultdict

import pytest
import sympy as sp
from sympy.core import containers
from sympy.core.exprtools import Factors

from app.engine.algebra import sympy_fixes

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

x, y, z, m, g, l = sp.symbols("x y z m g l")  # noqa: E741


@pytest.fixture
def unfixed():
    """SymPy's own Factors.__init__ for the length of a test."""
    Factors.__init__ = sympy_fixes._sympy_init
    yield
    sympy_fixes.install()


def _sums(count: int) -> list[sp.Expr]:
    rng = random.Random(35)
    atoms = [x, y, z, m, g, l, sp.sin(x), sp.cos(x - y), sp.Rational(3, 2), sp.Integer(-2), sp.sqrt(2)]
    out = []
    for _ in range(count):
        terms = [sp.Mul(*rng.sample(atoms, rng.randint(1, 4))) ** rng.choice([1, 1, 2, -1]) for _ in range(4)]
        out.append(sp.Add(*terms))
    return out


def _answers(exprs: list[sp.Expr]) -> list[tuple[sp.Expr, sp.Expr, dict]]:
    return [
        (sp.factor_terms(e), sp.gcd_terms(e), Factors(dict(e.as_powers_dict())).factors) for e in exprs
    ]


def test_factor_terms_and_gcd_terms_answer_as_sympy_does(request):
    exprs = _sums(150) + [m * g * l * sp.cos(x) + m * l**2 * y**2 / 2, 2 * x + 4 * x * y, x / y + x / z, sp.S.One]
    fixed = _answers(exprs)
    request.getfixturevalue("unfixed")
    assert _answers(exprs) == fixed
    assert Factors({}).factors == {} and type(Factors({x: 1}).factors) is dict
    kept = Factors(defaultdict(int, {x: 2})).factors
    assert type(kept) is defaultdict and kept.default_factory is int and kept[y] == 0


def _conversions(monkeypatch) -> list[int]:
    """Count SymPy's conversions of a dict into a Dict from here on."""
    counted = []
    convert = containers._sympy_converter[dict]
    monkeypatch.setitem(containers._sympy_converter, dict, lambda d: counted.append(1) or convert(d))
    return counted


def test_a_dict_is_no_longer_converted_to_be_compared_with_one(monkeypatch):
    counted = _conversions(monkeypatch)
    sp.factor_terms(m * g * l * sp.cos(x) * y + m * l**2 * y**2 / 2)
    assert counted == []


def test_without_the_fix_sympy_converts_it(monkeypatch, unfixed):
    counted = _conversions(monkeypatch)
    sp.factor_terms(m * g * l * sp.cos(x) * y + m * l**2 * y**2 / 2)
    assert counted  # what the fix steps around (a newer SymPy that no longer does this makes the fix unneeded)
