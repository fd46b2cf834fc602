"""Poincaré sections: crossings located on the plane, starts on the energy surface, curves for an
integrable system and a scattered cloud for a chaotic one."""

from functools import cache

import numpy as np
import pytest

from app.engine.derivation.derive import derive
from app.numerics.errors import SimulationError
from app.numerics.observables import build
from app.numerics.poincare import energy_starts, hamiltonian, section
from app.numerics.system import numeric_system
from app.scenes import SCENES
from app.scenes.types import Parameter, System

# Two oscillators that do not interact, with incommensurate frequencies 1 and sqrt(2).
UNCOUPLED = System(
    coordinates=("x", "y"),
    parameters=(Parameter("w1", 1.0, min=0.1), Parameter("w2", 2.0**0.5, min=0.1)),
    kinetic="x_dot**2/2 + y_dot**2/2",
    potential="w1**2*x**2/2 + w2**2*y**2/2",
)


@cache
def compiled(which):
    system = SCENES[which].system if which in SCENES else UNCOUPLED
    numeric = numeric_system(derive(system))
    k = np.array([p.default for p in system.parameters])
    return numeric, build(numeric), k


def spread_across_curve(points):
    """Median, over the points, of how far their 4 nearest neighbours are from lying on a line.

    Each point's neighbourhood is summarised by its principal axes; the ratio of the small to the large
    axis is about 0 for points on a smooth curve and of order 1 for points filling an area.
    """
    z = (points - points.mean(axis=0)) / points.std(axis=0)
    ratios = []
    for p in z:
        near = z[np.argsort(np.sum((z - p) ** 2, axis=1))[1:5]]
        s = np.linalg.svd(near - near.mean(axis=0), compute_uv=False)
        ratios.append(s[-1] / s[0])
    return float(np.median(ratios))


def test_starts_lie_on_the_energy_surface_and_the_plane():
    system, obs, k = compiled("uncoupled")
    starts = energy_starts(system, obs, k, 1.0, 1, 0.0, 1, 5)
    assert len(starts) == 5
    for y in starts:
        assert y[1] == 0.0 and y[3] > 0  # on y = 0, moving upward
        assert hamiltonian(obs, y, k)[0] == pytest.approx(1.0, rel=1e-12)
    with pytest.raises(SimulationError, match="below the potential"):
        energy_starts(system, obs, k, -1.0, 1, 0.0, 1, 5)


@pytest.mark.slow
def test_an_integrable_systems_section_lies_on_curves():
    system, obs, k = compiled("uncoupled")
    cut = section(system, obs, k, 1.0, 1, 0.0, 1, count=3, t_end=800.0, wall_seconds=60.0)
    assert len(cut.orbits) == 3
    for orbit in cut.orbits:
        assert orbit.complete and orbit.t.size > 150
        x, y, xd, yd = orbit.states.T
        # every crossing on the plane, in the chosen direction
        assert np.abs(y).max() < 1e-9 and (yd > 0).all()
        # the x oscillator keeps its own energy: the points lie on one ellipse
        e_x = xd**2 / 2 + x**2 / 2
        assert e_x.std() <= 1e-8 * max(e_x.mean(), 1e-12)
        if e_x.mean() > 1e-6:  # (the start with the x oscillator at rest sits at one point)
            assert spread_across_curve(np.column_stack([x, orbit.momenta[:, 0]])) < 0.05
        assert orbit.energy_drift < 1e-8


@pytest.mark.slow
def test_a_chaotic_double_pendulums_section_fills_an_area():
    system, obs, k = compiled("double-pendulum")
    s = SCENES["double-pendulum"]
    y0 = np.array([s.initial[n] for n in ("theta1", "theta2", "theta1_dot", "theta2_dot")])
    energy = float(hamiltonian(obs, y0, k)[0])
    cut = section(system, obs, k, energy, 1, 0.0, 1, count=2, t_end=400.0, wall_seconds=60.0)
    orbit = max(cut.orbits, key=lambda o: o.t.size)
    assert orbit.t.size > 150
    theta2 = orbit.states[:, 1]
    # an angle: every crossing is through theta2 = 0 (mod 2 pi), moving upward
    assert np.abs(np.sin(theta2)).max() < 1e-8 and (np.cos(theta2) > 0).all() and (orbit.states[:, 3] > 0).all()
    assert orbit.energy_drift < 1e-6
    theta1 = np.angle(np.exp(1j * orbit.states[:, 0]))
    assert spread_across_curve(np.column_stack([theta1, orbit.momenta[:, 0]])) > 0.2


def test_a_section_needs_a_conserved_energy():
    system = numeric_system(derive(SCENES["damped-pendulum"].system))
    with pytest.raises(SimulationError, match="conserved energy"):
        section(system, build(system), np.array([1.0, 9.81, 1.0, 0.3]), 1.0, 0)
