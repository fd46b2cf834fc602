"""Circular orbits of a Yukawa central force (issue 42): found as steady motions of the reduced system with p_φ
held, checked against roots found independently, and against the app's own simulation started on them.

L = ½m(ṙ² + r²φ̇²) + k e^{−r/a}/r.  With p_φ = m r² φ̇ held, V_eff = p_φ²/(2mr²) − k e^{−r/a}/r, and
    V_eff'(r)  = −p_φ²/(m r³) + k e^{−r/a} (1/(a r) + 1/r²),
    V_eff''(r) = 3p_φ²/(m r⁴) − k e^{−r/a} (1/(a² r) + 2/(a r²) + 2/r³),
a circular orbit where V_eff' = 0, its radial frequency² V_eff''/m (stable when positive).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from app.engine.derivation.derive import derive
from app.engine.equilibria.modes import STABLE, UNSTABLE, normal_modes
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from app.scenes.types import Parameter, System

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

M_, K_, A_, P = 1.0, 1.0, 2.0, 1.0
YUKAWA = System(
    coordinates=("r", "phi"),
    parameters=(Parameter("m", M_), Parameter("k", K_), Parameter("a", A_)),
    lagrangian="m*(r_dot**2 + r**2*phi_dot**2)/2 + k*exp(-r/a)/r",
    nonnegative=("r",),
)


def _slope(r: float) -> float:
    return -(P**2) / (M_ * r**3) + K_ * math.exp(-r / A_) * (1 / (A_ * r) + 1 / r**2)


def _curvature(r: float) -> float:
    return 3 * P**2 / (M_ * r**4) - K_ * math.exp(-r / A_) * (1 / (A_**2 * r) + 2 / (A_ * r**2) + 2 / r**3)


# by hand: V_eff' changes sign on (0.5, 3) and on (3, 20), and nowhere else on (0.05, 200)
BY_HAND = [brentq(_slope, 0.5, 3.0, xtol=1e-14), brentq(_slope, 3.0, 20.0, xtol=1e-14)]


def test_the_hand_roots_are_the_issues():
    assert BY_HAND == pytest.approx([1.1228, 6.7938], abs=1e-4)
    grid = np.geomspace(0.05, 200, 20001)
    assert np.count_nonzero(np.diff(np.sign([_slope(r) for r in grid]))) == 2


@pytest.fixture(scope="module")
def orbits():
    d = derive(YUKAWA)
    nm = normal_modes(d.system, d.mechanics, d.equations, d.reduction, {"p_phi": P})
    return sorted((e for e in nm.equilibria if e.momenta), key=lambda e: e.position["r"])


def test_both_circular_orbits_with_their_radial_frequencies(orbits):
    assert [e.position["r"] for e in orbits] == pytest.approx(BY_HAND, rel=1e-9)
    assert [e.kind for e in orbits] == [STABLE, UNSTABLE]
    for e, r in zip(orbits, BY_HAND, strict=True):
        assert e.momenta == {"p_phi": P}
        assert [m.omega_squared for m in e.modes] == pytest.approx([_curvature(r) / M_], rel=1e-7)


@pytest.mark.parametrize("index", [0, 1])
def test_the_app_simulation_started_on_an_orbit_stays_on_it(orbits, index):
    r0 = orbits[index].position["r"]
    system = numeric_system(derive(YUKAWA))
    T = 20.0
    run = simulate(system, np.array([M_, K_, A_]), np.array([r0, 0.0, 0.0, P / (M_ * r0**2)]), T, 401,
                   rtol=1e-12, atol=1e-14)  # fmt: skip
    r = run.trajectory.y[:, 0]
    assert run.trajectory.complete and np.max(np.abs(r - r0)) < 1e-7 * r0


def test_near_the_stable_orbit_r_oscillates_at_the_radial_frequency(orbits):
    r0 = orbits[0].position["r"]
    w = math.sqrt(orbits[0].modes[0].omega_squared)
    system = numeric_system(derive(YUKAWA))
    T = 4 * 2 * math.pi / w
    # moved out by 1e-4 with p_φ still P: r oscillates about r0
    run = simulate(system, np.array([M_, K_, A_]), np.array([r0 + 1e-4, 0.0, 0.0, P / (M_ * (r0 + 1e-4) ** 2)]), T, 4001,
                   rtol=1e-12, atol=1e-14)  # fmt: skip
    t, r = run.trajectory.t, run.trajectory.y[:, 0] - r0
    assert np.max(np.abs(r)) < 1.1e-4  # bounded: stable
    # upward zero crossings of r - r0, one radial period apart
    ups = [t[i] - r[i] * (t[i + 1] - t[i]) / (r[i + 1] - r[i]) for i in range(t.size - 1) if r[i] < 0 <= r[i + 1]]
    assert np.diff(ups) == pytest.approx(2 * math.pi / w, rel=1e-3)
