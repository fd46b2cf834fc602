"""Issue 40: the forms a textbook prints in a typed system's document (app.engine.display.forms).

A pendulum whose pivot slides on a horizontal spring, typed as a reviewer typed it (a cart M at X on a spring k,
a bob m on a rod l at angle φ), and a pendulum hung from a block sliding down an incline: terms that differ only by
a parameter factor are one term ((M + m)Ẋ, (M + m)p_φ²), and the two accelerations of a system share one
denominator, the determinant of the mass matrix in single angles, M first (l(M + m sin² φ)).  Every printed form
is checked against the engine's own expression at random points.
"""

import random
from functools import cache

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.document.contract import derivation_json
from app.scenes.types import Parameter, Particle, System

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def _kg(name: str, value: float) -> Parameter:
    return Parameter(name, value, "kg", 1e-3, 1e3)


def _metre(name: str, value: float) -> Parameter:
    return Parameter(name, value, "m", 1e-3, 1e3)


G = Parameter("g", 9.81, "m/s²", 0.1, 100.0)

SYSTEMS = {
    "cart-on-a-spring": System(
        coordinates=("X", "phi"),
        parameters=(_kg("M", 2.0), _kg("m", 0.3), _metre("l", 0.8), Parameter("k", 5.0, "N/m", 0.0, 1e3), G),
        particles=(Particle("M", ("X", "0", "0")), Particle("m", ("X + l*sin(phi)", "-l*cos(phi)", "0"))),
        potential="k*X**2/2 - m*g*l*cos(phi)",
    ),
    "pendulum-on-an-incline": System(
        coordinates=("s", "theta"),
        parameters=(_kg("M", 2.0), _kg("m", 0.3), _metre("l", 0.8), Parameter("alpha", 0.4, "rad", 0.0, 1.5), G),
        particles=(
            Particle("M", ("s*cos(alpha)", "-s*sin(alpha)", "0")),
            Particle("m", ("s*cos(alpha) + l*sin(theta)", "-s*sin(alpha) - l*cos(theta)", "0")),
        ),
        potential="-M*g*s*sin(alpha) - m*g*(s*sin(alpha) + l*cos(theta))",
    ),
    # a particle on a cone of slope c, typed as a reviewer typed it (prof-o F5)
    "cone": System(
        coordinates=("r", "phi"),
        parameters=(_kg("m", 1.0), G, Parameter("c", 1.0, "", 0.01, 10.0)),
        kinetic="m*((1+c**2)*r_dot**2 + r**2*phi_dot**2)/2",
        potential="m*g*c*r",
    ),
    # a mass hung from a spring, x measured down from where the spring is unstretched
    "hung-spring": System(
        coordinates=("x",),
        parameters=(_kg("m", 1.0), Parameter("k", 2.0, "N/m", 0.01, 100.0), G),
        kinetic="m*x_dot**2/2",
        potential="k*x**2/2 - m*g*x",
    ),
}


@cache
def _document(name: str):
    d = derive(SYSTEMS[name])
    return d, derivation_json(d)


def _step(doc, key: str) -> str:
    return next(s["latex"] for s in doc["steps"] if s["key"] == key)


def _same(shown: str, engine: sp.Expr) -> None:
    """The served text of a form equals the engine's expression at random points."""
    expr = sp.sympify(shown)
    symbols = {s.name: s for s in engine.free_symbols}
    expr = expr.xreplace({s: symbols.get(s.name, s) for s in expr.free_symbols})
    rng = random.Random(40)
    for _ in range(5):
        at = {s: rng.uniform(0.3, 1.7) for s in engine.free_symbols | expr.free_symbols}
        assert abs(float((expr - engine).evalf(subs=at))) < 1e-9


def test_terms_differing_by_a_mass_are_one_term_in_every_member():
    d, doc = _document("cart-on-a-spring")
    # ∂L/∂Ẋ = (M + m)Ẋ + m l φ̇ cos φ, not M Ẋ + m Ẋ + …
    assert r"\frac{\partial L}{\partial \dot{X}} &= \left(M + m\right) \dot{X} + m l \dot{\varphi} \cos {\varphi}" in (
        _step(doc, "derivatives:X")
    )
    ham = doc["hamilton"]
    # φ̇ from the momenta and H, collected: (M + m)p_φ, (M + m)p_φ²
    assert ham["equations"][1]["q_dot"]["latex"] == (
        r"\frac{\left(M + m\right) p_{\varphi} - m l p_{X} \cos {\varphi}}{m l^{2} \left(M + m \sin^{2} {\varphi}\right)}"
    )
    assert ham["hamiltonian"]["latex"].startswith(
        r"\frac{\left(M + m\right) p_{\varphi}^{2} + m l^{2} p_{X}^{2} - 2 m l p_{\varphi} p_{X} \cos {\varphi}}"
        r"{2 m l^{2} \left(M + m \sin^{2} {\varphi}\right)}"
    )
    assert r"M p_{\varphi} + m p_{\varphi}" not in _step(doc, "hamilton-equations")
    h = d.hamilton
    _same(ham["hamiltonian"]["sympy"], h.hamiltonian)
    for row, v, p_dot in zip(ham["equations"], h.velocities, h.p_dot, strict=True):
        _same(row["q_dot"]["sympy"], v)
        _same(row["p_dot"]["sympy"], p_dot)
    _same(doc["momenta"]["X"]["sympy"], d.equations.momenta[0])


def test_the_incline_pendulums_momentum_and_forces_collected():
    d, doc = _document("pendulum-on-an-incline")
    rows = _step(doc, "derivatives:s")
    assert r"\frac{\partial L}{\partial \dot{s}} &= \left(M + m\right) \dot{s}" in rows
    assert r"M \dot{s} + m \dot{s}" not in rows


def test_the_accelerations_share_one_denominator_in_single_angles():
    d, doc = _document("cart-on-a-spring")
    acc = doc["accelerations"]
    assert acc["X"]["latex"] == (
        r"\frac{m g \sin {\varphi} \cos {\varphi} + m l \dot{\varphi}^{2} \sin {\varphi} - k X}{M + m \sin^{2} {\varphi}}"
    )
    assert acc["phi"]["latex"] == (
        r"\frac{k X \cos {\varphi} - \left(M + m\right) g \sin {\varphi} - m l \dot{\varphi}^{2} \sin {\varphi} "
        r"\cos {\varphi}}{l \left(M + m \sin^{2} {\varphi}\right)}"
    )
    # the step prints the same forms
    step = _step(doc, "accelerations")
    assert acc["X"]["latex"] in step and acc["phi"]["latex"] in step
    for name, engine in zip(d.table.names, d.equations.accelerations, strict=True):
        _same(acc[name]["sympy"], engine)


@pytest.mark.parametrize("name", ["pendulum-on-an-incline"])
def test_double_angles_give_way_to_a_shorter_single_angle_form(name):
    d, doc = _document(name)
    acc = doc["accelerations"]
    below = r"M + m \sin^{2}{\left(\theta + \alpha \right)}"
    assert acc["s"]["latex"].endswith(f"{{{below}}}")
    assert acc["theta"]["latex"].endswith(rf"{{l \left({below}\right)}}")
    for form in acc.values():
        assert r"2 \theta" not in form["latex"] and r"2 \alpha" not in form["latex"]
    for q, engine in zip(d.table.names, d.equations.accelerations, strict=True):
        _same(acc[q]["sympy"], engine)


def test_the_cones_equation_is_cancelled_and_its_hamiltonian_factored():
    d, doc = _document("cone")
    # r̈ − rφ̇²/(1 + c²) + gc/(1 + c²) = 0, not r̈ − (1 + c²)/(1 + c²)² · rφ̇² + …
    row = r"\ddot{r} - \frac{r \dot{\varphi}^{2}}{1 + c^{2}} + \frac{g c}{1 + c^{2}} = 0"
    assert doc["equations_of_motion"][0]["latex"] == row
    assert row in _step(doc, "euler-lagrange")
    # H's denominator as the velocities step writes m(1 + c²): 2m(1 + c²), not 2m + 2mc²
    H = doc["hamilton"]["hamiltonian"]["latex"]
    assert H.startswith(r"\frac{p_{r}^{2}}{2 m \left(1 + c^{2}\right)} + ")
    assert H in _step(doc, "hamiltonian-pq")
    _same(doc["hamilton"]["hamiltonian"]["sympy"], d.hamilton.hamiltonian)
    # the equation shown is the engine's residual divided by its factor m(1 + c²)
    factor = d.equations.mass_matrix[0, 0]
    _same(doc["equations_of_motion"][0]["sympy"], sp.expand(d.equations.residuals[0]) / factor)


def test_an_effective_potential_that_is_u_prints_in_us_form():
    """prof-o F8: one coordinate, nothing held: U_eff is U, in the step and in the results as U's step prints it
    (½kx² − mgx, not x(½kx − mg))."""
    d, doc = _document("hung-spring")
    u = r"\frac{1}{2} k x^{2} - m g x"
    assert _step(doc, "potential") == f"U = {u}"
    assert doc["effective_potential"]["potential"]["latex"] == u
    assert _step(doc, "effective-potential").startswith(rf"\begin{{aligned}}U_\text{{eff}}(x) &= {u} \\ ")
    _same(doc["effective_potential"]["potential"]["sympy"], d.reduction.effective_potential)
