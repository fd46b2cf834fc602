"""Linearised equations with a common factor of t (issue 42): after dividing by it their coefficients are
constant, and the equilibrium gets its exponents, frequency and damping.

Caldirola–Kanai, L = e^{γt}(½mẋ² − ½kx²): d/dt(m e^{γt} ẋ) + k e^{γt} x = 0, divided by e^{γt},
ẍ + γẋ + (k/m)x = 0, so s² + γs + k/m = 0: s = −γ/2 ± i√(k/m − γ²/4).  The test checks this by hand and
against LagrangesMethod's equation, and the verdict (stable, decaying) against the app's own simulation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.equilibria.modes import STABLE, normal_modes
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from app.scenes.types import Parameter, System
from tests.reference import lagranges_method

M_, K_, GAMMA = 2.0, 8.0, 0.5
CALDIROLA_KANAI = System(
    coordinates=("x",),
    parameters=(Parameter("m", M_), Parameter("k", K_), Parameter("gamma", GAMMA)),
    lagrangian="exp(gamma*t)*(m*x_dot**2/2 - k*x**2/2)",
)
# a time factor that is not common: L = ½ẋ² − ½(1 + t)x² (a stiffening spring) stays without frequencies
STIFFENING = System(coordinates=("x",), parameters=(), lagrangian="x_dot**2/2 - (1 + t)*x**2/2")


@pytest.mark.slow
def test_by_hand_agrees_with_lagranges_method():
    lm, qs, read = lagranges_method(CALDIROLA_KANAI)
    t = sp.Symbol("t")
    x = qs[0]
    m, k, gamma = (read(n) for n in ("m", "k", "gamma"))
    equation = sp.simplify(lm.eom[0] * sp.exp(-gamma * t) / m)  # divided by the common factor m e^{γt}
    xt = x.diff(t)
    assert sp.simplify(equation - (xt.diff(t) + gamma * xt + k / m * x)) == 0


@pytest.mark.slow
def test_caldirola_kanai_has_constant_exponents_after_dividing_by_its_factor():
    d = derive(CALDIROLA_KANAI)
    nm = normal_modes(d.system, d.mechanics, d.equations, d.reduction)
    assert not nm.unclassified
    [e] = nm.equilibria
    assert e.position["x"] == pytest.approx(0.0, abs=1e-12)
    assert e.kind == STABLE
    exponents = sorted(e.linear.exponents, key=lambda s: s.imag)
    by_hand = math.sqrt(K_ / M_ - GAMMA**2 / 4)
    for s, imag in zip(exponents, (-by_hand, by_hand), strict=True):
        assert s.real == pytest.approx(-GAMMA / 2, rel=1e-9)
        assert s.imag == pytest.approx(imag, rel=1e-9)
    assert [m.omega_squared for m in e.modes] == pytest.approx([K_ / M_], rel=1e-12)
    assert nm.common_factor


def test_the_verdict_agrees_with_a_simulation():
    # from x = 0.01 at rest the amplitude decays as e^{-γt/2}, the oscillation at √(k/m − γ²/4)
    system = numeric_system(derive(CALDIROLA_KANAI))
    T = 12.0
    run = simulate(system, np.array([M_, K_, GAMMA]), np.array([0.01, 0.0]), T, 2001, rtol=1e-11, atol=1e-14)
    t, x = run.trajectory.t, run.trajectory.y[:, 0]
    w = math.sqrt(K_ / M_ - GAMMA**2 / 4)
    exact = 0.01 * np.exp(-GAMMA * t / 2) * (np.cos(w * t) + GAMMA / (2 * w) * np.sin(w * t))
    assert np.max(np.abs(x - exact)) < 1e-8


def test_a_factor_that_is_not_common_leaves_no_frequencies():
    d = derive(STIFFENING)
    nm = normal_modes(d.system, d.mechanics, d.equations, d.reduction)
    assert not nm.equilibria and [p["x"] for p in nm.unclassified] == [pytest.approx(0.0, abs=1e-12)]
    assert not nm.common_factor
