"""The Python API (lagrange/): a typed system and a scene derived and simulated as the web book does."""

from __future__ import annotations

import numpy as np
import pytest

import lagrange

pytestmark = pytest.mark.slow  # a derivation and a compiled run

SPRING = {"coordinates": ["x"], "parameters": {"m": 2.0, "k": 8.0}, "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}


@pytest.fixture(scope="module")
def spring():
    return lagrange.derive(lagrange.System(**SPRING))


def test_a_typed_system_gives_its_equation_as_sympy_and_as_latex(spring):
    assert {q: str(a) for q, a in spring.accelerations.items()} == {"x_ddot": "-k*x/m"}
    assert str(spring.equations[0]) == "Eq(k*x + m*x_ddot, 0)"
    assert spring._repr_latex_() == "$$\\begin{aligned}\\ddot{x} + \\frac{k}{m} x &= 0\\end{aligned}$$"
    titles = [s.title for s in spring.steps]
    assert "Kinetic energy" in titles and "Potential energy" in titles
    assert all(s.latex and s.reason for s in spring.steps)
    assert "<details><summary>the system in x:" in spring._repr_html_()


def test_a_run_follows_the_exact_motion_within_its_error(spring):
    # x(0) = 0.1 m at rest: x = 0.1 cos(ω t) with ω = √(k/m) = 2 rad/s
    run = lagrange.simulate(spring, t_end=5, initial={"x": 0.1})
    exact = 0.1 * np.cos(2.0 * run.t)
    assert run.error is not None and np.max(np.abs(run["x"] - exact)) < 10 * run.error + 1e-9
    assert run.names == ("x", "x_dot") and run.t[-1] == pytest.approx(5.0)
    with pytest.raises(KeyError, match="this run has x, x_dot"):
        run["y"]


def test_a_parameter_given_to_the_run_replaces_its_default(spring):
    run = lagrange.simulate(spring, t_end=np.pi / 2, initial={"x": 0.1}, parameters={"k": 2.0})
    # ω = 1 rad/s: a quarter period at t = π/2
    assert run["x"][-1] == pytest.approx(0.0, abs=1e-6)


def test_the_playground_json_reads_as_the_same_system(spring):
    data = {**SPRING, "parameters": [{"name": "m", "value": 2.0, "unit": "kg"}, {"name": "k", "value": 8.0}]}
    assert str(lagrange.derive(lagrange.System.from_json(data)).accelerations) == str(spring.accelerations)


def test_a_scene_derives_as_on_its_page():
    d = lagrange.derive(lagrange.scene("simple-pendulum"))
    assert d.document["equations_of_motion"][0]["latex"] == "\\ddot{\\theta} + \\frac{g}{R} \\sin {\\theta} = 0"
    assert d.steps[0].title.startswith("The action")


def test_mistakes_are_refused_with_the_playgrounds_message():
    with pytest.raises(lagrange.Refused, match="potential: unknown name .*'k'"):
        lagrange.System(coordinates=["x"], parameters={"m": 1}, kinetic="m*x_dot**2/2", potential="k*x**2/2")
    with pytest.raises(KeyError, match="no scene 'pendulum'; the scenes are: "):
        lagrange.scene("pendulum")
    d = lagrange.derive(lagrange.System(**SPRING))
    with pytest.raises(lagrange.Refused, match="unknown parameter 'q'"):
        lagrange.simulate(d, parameters={"q": 1.0})
