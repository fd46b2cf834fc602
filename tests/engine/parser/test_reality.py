"""Energies that are real nowhere are refused before deriving (issue 32); real ones, even partly real, are not."""

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.parser.reality import nowhere_real, real_somewhere
from app.engine.parser.user_system import UserSystem
from app.engine.tutor.check import CheckError, parse_answer, problem
from app.service.users.user_checks import InvalidSystem
from app.service.users.user_jobs import build_system
from tests.engine.equilibria_systems import SYSTEMS

NEVER_REAL = ["sqrt(-1 - x**2)", "log(-1 - x**2)", "acos(2 + x**2)", "asin(2 + cos(x))", "(-1 - x**2)**(1/3)"]
# real on part of the line (or everywhere): allowed
SOMEWHERE = ["sqrt(1 - x**2)", "log(x)", "acos(x)", "x**2", "sqrt(k)*x**2", "asin(cos(x))", "(1 + x**2)**(1/3)"]


def spring(potential):
    return {"coordinates": ["x"], "parameters": ["k"], "kinetic": "x_dot**2/2", "potential": potential}


@pytest.mark.parametrize("text", NEVER_REAL)
def test_a_potential_real_nowhere_is_refused_naming_it_and_a_point(text):
    with pytest.raises(InvalidSystem) as refused:
        build_system(UserSystem.of(spring(text)))
    message = str(refused.value)
    assert refused.value.loc == ("potential",)
    assert text in message and "not a real number anywhere" in message
    # the point named is one where the expression is indeed not real
    x = float(message.split("at x = ")[1].split(",")[0])
    value = complex(sp.sympify(text.replace("(1/3)", "Rational(1, 3)")).subs("x", x).evalf())
    assert abs(value.imag) > 1e-6


@pytest.mark.parametrize("text", SOMEWHERE)
def test_a_potential_real_somewhere_is_derived(text):
    assert build_system(UserSystem.of(spring(text))).potential == text


def test_a_lagrangian_real_nowhere_in_the_velocities_is_refused():
    with pytest.raises(InvalidSystem) as refused:
        build_system(UserSystem.of({"coordinates": ["theta"], "lagrangian": "sqrt(-1 - theta_dot**2)"}))
    assert refused.value.loc == ("lagrangian",) and "theta_dot = " in str(refused.value)


def test_nowhere_real_returns_a_point_only_when_no_sample_is_real():
    x = sp.Symbol("x", real=True)
    assert nowhere_real(sp.sqrt(-1 - x**2), [x]) is not None
    assert nowhere_real(sp.sqrt(1 - x**2), [x]) is None
    assert nowhere_real(sp.sqrt(2 - sp.cos(x)) * sp.I, [x]) is not None
    assert real_somewhere("x", x) == x


@pytest.mark.slow
def test_the_checker_refuses_an_answer_real_nowhere():
    d = derive(SYSTEMS["hoop-slow"])
    pb = problem(d, "lagrangian")
    with pytest.raises(CheckError) as refused:
        parse_answer(pb, "sqrt(-1 - phi_dot**2)")
    assert "not a real number anywhere" in str(refused.value)
    assert parse_answer(pb, "m*R**2*phi_dot**2/2") is not None


@pytest.mark.slow
def test_l_equal_to_u_minus_t_derives_and_its_modes_say_so():
    # the "negative mass" case: derived, and the equilibrium is the oscillator's
    from app.engine.document.contract import derivation_json

    doc = derivation_json(derive(SYSTEMS["negative-kinetic-energy"]))
    (e,) = doc["normal_modes"]
    assert e["kind"] == "stable" and e["modes"][0]["omega_squared"] == pytest.approx(8.0 / 2.0)
    step = next(s for s in doc["steps"] if s["key"] == "normal-modes:1")
    assert "negative" in step["explanation"] and "the same as for −L" in step["explanation"]


def test_an_expression_of_real_functions_is_not_sampled_and_sampling_would_find_it_real(monkeypatch):
    from app.engine.parser import reality

    x, k, t = sp.symbols("x k t")
    real = [x**2 / 2 - k * sp.cos(x), sp.exp(-t) * sp.tan(x) ** 3 / (1 + x**2), sp.Abs(x) - sp.sinh(k * x) + sp.pi]
    assert all(reality._real_wherever_finite(e) for e in real)
    # sampled anyway (the shortcut off), each is real at a sampled point: the same answer
    monkeypatch.setattr(reality, "_real_wherever_finite", lambda e: False)
    assert [nowhere_real(e, [x, t]) for e in real] == [None, None, None]
    monkeypatch.undo()
    # roots, logarithms, inverse sines, i and infinities go to the sampling
    for text in [*NEVER_REAL, *SOMEWHERE[:3], "I*x", "x + zoo", "x**k"]:
        assert not reality._real_wherever_finite(sp.sympify(text)), text
