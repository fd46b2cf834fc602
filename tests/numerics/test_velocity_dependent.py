"""A Lagrangian whose ∂²L/∂q̇² depends on the velocities, simulated (issue 42): W q̈ = f solved at each step.

The relativistic oscillator L = −mc²√(1 − ẋ²/c²) − ½kx²: its p = mγẋ is not linear in ẋ, so no ``ham``
(q̇(q, p) = M⁻¹(p − b)) is generated, Gauss–Legendre (which steps in (q, p)) says why it cannot run, and
``auto`` keeps to an adaptive method even on a long run whose h is conserved.
"""

import numpy as np
import pytest

from app.engine.derivation.derive import derive
from app.numerics.errors import SimulationError
from app.numerics.methods import METHODS, symplectic_for
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from app.scenes.types import Parameter, System

OSCILLATOR = System(
    coordinates=("x",),
    parameters=(Parameter("m", 1.0, "kg"), Parameter("c", 1.0, "m/s"), Parameter("k", 4.0, "N/m")),
    lagrangian="-m*c**2*sqrt(1 - x_dot**2/c**2) - k*x**2/2",
)
K = np.array([1.0, 1.0, 4.0])


@pytest.fixture(scope="module")
def system():
    return numeric_system(derive(OSCILLATOR))


def test_no_phase_space_form_and_no_symplectic_method(system):
    assert not system.legendre_linear and "ham" not in system.sources
    assert not system.separable
    assert symplectic_for(system) is None
    why = METHODS["Gauss-Legendre"].applicable(system)
    assert why is not None and "depends on the velocities" in why
    with pytest.raises(SimulationError, match="Gauss-Legendre cannot integrate this system: it steps in"):
        simulate(system, K, np.array([1.0, 0.0]), 1.0, 11, method="Gauss-Legendre")


def test_the_right_hand_side_solves_w_for_the_acceleration(system):
    # W ẍ = f with W = mγ³ and f = −kx, by hand at x = 0.5, ẋ = 0.6c: ẍ = −kx/(mγ³) = −2 · 0.8³
    out = system.f(0.0, np.array([0.5, 0.6]), K)
    assert out[0] == pytest.approx(0.6)
    assert out[1] == pytest.approx(-2.0 * 0.8**3, rel=1e-14)


@pytest.mark.slow
def test_auto_on_a_long_run_keeps_h(system):
    # a long run with h conserved would take a symplectic method; none applies, so an adaptive one runs
    out = simulate(system, K, np.array([1.0, 0.0]), 300.0, 3001, rtol=1e-10, atol=1e-10)
    assert out.method not in ("Gauss-Legendre", "Yoshida4", "Verlet")
    x, v = out.trajectory.y[:, 0], out.trajectory.y[:, 1]
    h = 1.0 / np.sqrt(1.0 - v**2) + 2.0 * x**2
    assert np.max(np.abs(h - h[0])) < 1e-6 * h[0]
