"""Relaxing the discretised action between two fixed ends: the pendulum's true path below the kinetic focus, a
saddle beyond it, and agreement with shooting."""

import math

import numpy as np
import pytest

from app.numerics.action import action_terms
from app.numerics.action_relax import find_path, relax
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from app.service.chapter.derivations import derivation

K = np.array([1.0, 9.81, 1.0])  # m, g, R of the simple pendulum
FOCUS = 1.0695688  # the first kinetic focus from theta = 1, at rest (POST .../action's conjugate_time)


@pytest.fixture(scope="module")
def pendulum():
    return numeric_system(derivation("simple-pendulum"))


def _true(system, T, steps):
    run = simulate(system, K, np.array([1.0, 0.0]), T, steps + 1, rtol=1e-12, atol=1e-14, estimate=False)
    return run.trajectory.y[:, 0]


@pytest.mark.parametrize(("T", "kind"), [(0.9, "minimum"), (1.5, "saddle")])
def test_relaxation_recovers_the_true_path(pendulum, T, kind):
    steps = 200
    q = _true(pendulum, T, steps)
    # a trial path: the straight line between the ends with a bump
    t = np.linspace(0, T, steps + 1)
    trial = (np.linspace(q[0], q[-1], steps + 1) + 0.3 * np.sin(math.pi * t / T) ** 2)[None, :]
    found = find_path(pendulum, action_terms(pendulum), K, q[:1], q[-1:], T, trial)
    assert np.abs(found.q[0] - q).max() < 1e-6
    assert found.difference < 1e-6  # the shooting solution is the same path
    assert found.fine.kind == kind and (found.fine.negative == 0) == (T < FOCUS)
    assert len(found.coarse.iterations) > 2  # the animation has frames


def test_relaxation_of_a_straight_line_converges_and_the_discrete_action_falls(pendulum):
    T, steps = 0.9, 100
    q = _true(pendulum, T, steps)
    line = np.linspace(q[0], q[-1], steps + 1)[None, :]
    r = relax(action_terms(pendulum), K, q[:1], q[-1:], T, line)
    assert r.converged and r.kind == "minimum"
    # below the focus the stationary path is the minimum: every iterate's action is above it
    terms = action_terms(pendulum)
    t = np.linspace(0, T, steps + 1)

    def S(Q):
        h = t[1] - t[0]
        X, V = (Q[:, :-1] + Q[:, 1:]) / 2, (Q[:, 1:] - Q[:, :-1]) / h
        return h * terms.lagrangian((t[:-1] + t[1:]) / 2, X, V, K).sum()

    assert all(S(Q) >= r.action - 1e-12 for Q in r.iterations)
