"""cot, sec, csc and atan2 (issue 19): parsed, differentiated, derived, printed for the numerics and the pages."""

import math

import numpy as np
import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.document.trees import of_sympy, of_text
from app.engine.parser.parse import FUNCTIONS, ExpressionError, parse_expression
from app.numerics.system import numeric_system
from app.scenes.types import Parameter, Particle, System
from app.viz.exprtree import evaluate
from tests.reference import numerically_equal, reference_accelerations

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

x, y, a = (sp.Symbol(n, real=True) for n in ("x", "y", "a"))
NAMES = {"x": x, "y": y, "a": a}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("cot(x)", sp.cot(x)),
        ("sec(x)", sp.sec(x)),
        ("csc(x)", sp.csc(x)),
        ("atan2(y, x)", sp.atan2(y, x)),
        ("a*cot(a)**2 + sec(x)*csc(x)", a * sp.cot(a) ** 2 + sp.sec(x) * sp.csc(x)),
    ],
)
def test_the_four_functions_parse(text, expected):
    assert parse_expression(text, NAMES) == expected


def test_their_derivatives():
    d = sp.diff
    assert sp.simplify(d(parse_expression("cot(x)", NAMES), x) + 1 / sp.sin(x) ** 2) == 0
    assert sp.simplify(d(parse_expression("sec(x)", NAMES), x) - sp.sin(x) / sp.cos(x) ** 2) == 0
    assert sp.simplify(d(parse_expression("csc(x)", NAMES), x) + sp.cos(x) / sp.sin(x) ** 2) == 0
    angle = parse_expression("atan2(y, x)", NAMES)
    assert sp.simplify(d(angle, x) + y / (x**2 + y**2)) == 0
    assert sp.simplify(d(angle, y) - x / (x**2 + y**2)) == 0


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("atan2(y)", "exactly 2 arguments"),
        ("atan2(y, x, a)", "exactly 2 arguments"),
        ("cot(x, y)", "exactly one argument"),
        ("cot(0)", "division by zero"),
        ("csc(0)*x", "division by zero"),
        ("atan2(0, 0)", "undefined"),
        ("cot(pi)*x", "undefined"),
    ],
)
def test_wrong_uses_are_refused(text, words):
    with pytest.raises(ExpressionError, match=words):
        parse_expression(text, NAMES)


def test_constant_values_are_folded_like_sympy():
    assert float(parse_expression("atan2(1, -1)", NAMES)) == pytest.approx(3 * math.pi / 4)
    assert float(parse_expression("sec(1)", NAMES)) == pytest.approx(1 / math.cos(1))


# A particle on a cone of half-angle a about the vertical axis: height r cot(a) at distance r.
CONE = System(
    coordinates=("r", "phi"),
    parameters=(Parameter("m", 1.0, "kg", 0.01), Parameter("g", 9.81, "m/s²", 0.1), Parameter("a", 0.5, "rad", 0.1)),
    particles=(Particle("m", ("r*cos(phi)", "r*sin(phi)", "r*cot(a)")),),
    potential="m*g*r*cot(a)",
    nonnegative=("r",),
)
# A particle in the plane with a potential that depends on the polar angle written with atan2,
# and a sec/csc spring: every function appears in the equations.
ANGULAR = System(
    coordinates=("x", "y"),
    parameters=(Parameter("m", 1.0, "kg", 0.01), Parameter("k", 1.0, "N", 0.01)),
    kinetic="m*(x_dot**2 + y_dot**2)/2",
    potential="k*(atan2(y, x)**2 + x**2*sec(x/4) + y**2*csc(1 + y/4))",
)


@pytest.mark.parametrize("system", [CONE, ANGULAR], ids=["cone", "angular"])
def test_derivation_matches_lagranges_method(system):
    ours = derive(system).equations.accelerations
    theirs, _ = reference_accelerations(system)
    symbols = sorted(set().union(*(e.free_symbols for e in (*ours, *theirs))), key=str)
    for p, q in zip(ours, theirs, strict=True):
        assert numerically_equal(p, q, symbols)


@pytest.mark.parametrize("system", [CONE, ANGULAR], ids=["cone", "angular"])
def test_numerics_print_and_compile_them(system):
    d = derive(system)
    s = numeric_system(d)
    table = d.table
    y0 = np.array([0.7, 0.4, 0.3, -0.2])
    k = np.array([1.3, 0.8, 0.6][: len(table.params)])
    point = {q: v for q, v in zip((*table.q, *table.qd), y0, strict=True)}
    point.update(zip(table.params, k, strict=True))
    point[table.t] = 0.0
    expected = [float(sp.N(acc.xreplace(point), 20)) for acc in d.equations.accelerations]
    assert np.allclose(s.f(0.0, y0, k)[2:], expected, rtol=1e-12)
    out = np.empty(4)
    s.bound("rhs")(0.0, y0, k, out)  # numba compiles math.atan2, 1/math.tan, ...
    assert np.allclose(out[2:], expected, rtol=1e-12)


def test_every_allowed_function_has_a_figure_tree_and_a_value():
    env = {"x": 0.7, "y": -0.4}
    for name in FUNCTIONS:
        text = "atan2(y, x)" if name == "atan2" else f"{name}(x)"
        expr = parse_expression(text, NAMES)
        expected = float(sp.N(expr.xreplace({x: 0.7, y: -0.4})))
        assert evaluate(of_text(text, ["x", "y"]), env) == pytest.approx(expected, rel=1e-12), name
        assert evaluate(of_sympy(expr), env) == pytest.approx(expected, rel=1e-12), name
