"""Every method on one cheap problem, and every scene with the default method, keep what the engine says is
conserved, within its tolerance."""

import numpy as np
import pytest

from app.numerics.errors import SimulationError
from app.numerics.methods import AUTO, METHODS
from app.numerics.observables import build, summarize
from app.numerics.simulate import simulate
from app.scenes import SCENES
from tests.numerics.extreme_cases import system_for

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

RTOL, ATOL = 1e-9, 1e-12
# relative drift allowed at rtol = 1e-9 over a few seconds: on the pendulum the largest seen is 2.6e-9 (Verlet),
# BDF and LSODA 2e-9; with the default method every scene stays below 4e-10 (print them with -s)
LIMIT = 100 * RTOL


def scene_vectors(key):
    scene = SCENES[key]
    s = system_for(key)
    k = np.array([p.default for p in scene.system.parameters], dtype=float)
    y0 = np.array(
        [scene.initial.get(q, 0.0) for q in s.coordinates] + [scene.initial.get(f"{q}_dot", 0.0) for q in s.coordinates]
    )
    return s, k, y0, min(scene.t_end, 3.0)


def check_conserved(key, method):
    s, k, y0, t_end = scene_vectors(key)
    out = simulate(s, k, y0, t_end, 61, method, RTOL, ATOL, estimate=False)
    assert out.trajectory.complete
    obs = build(s)
    summary = summarize(obs, out.trajectory.t, obs.evaluate(out.trajectory.t, out.trajectory.y, k), RTOL)
    assert set(summary["conserved_drift"]) == set(s.conserved)
    for name, drift in summary["conserved_drift"].items():
        print(key, method, name, f"{drift['relative']:.2e}")
        assert drift["relative"] <= LIMIT, (name, drift)


# One cheap problem per integrator: the simple pendulum is separable, so every method applies to it.
@pytest.mark.parametrize("method", sorted(METHODS))
def test_every_method_keeps_the_pendulums_energy(method):
    assert METHODS[method].applicable(system_for("simple-pendulum")) is None
    check_conserved("simple-pendulum", method)


# Every scene once, with the method a request gets when it names none.
@pytest.mark.parametrize("key", sorted(SCENES))
def test_every_scene_keeps_what_is_conserved_with_the_default_method(key):
    check_conserved(key, AUTO)


# The splitting methods need a separable h, T(p) + U(q); every other method integrates every scene.
SPLITTING = ("Verlet", "Yoshida4")


def test_only_the_splitting_methods_refuse_a_scene():
    refusing = {m for m in METHODS if any(METHODS[m].applicable(system_for(key)) for key in SCENES)}
    assert refusing == set(SPLITTING)


# A method that does not apply is refused with the reason, never run: each such method on one scene it refuses.
@pytest.mark.parametrize("method", SPLITTING)
def test_a_method_refuses_a_scene_it_cannot_integrate(method):
    key = next(key for key in sorted(SCENES) if METHODS[method].applicable(system_for(key)))
    s, k, y0, t_end = scene_vectors(key)
    with pytest.raises(SimulationError, match="cannot integrate this system"):
        simulate(s, k, y0, t_end, 61, method, RTOL, ATOL, estimate=False)


def test_every_scene_conserves_something_or_says_why_not():
    """The damped pendulum alone has no conserved quantity (Q = -b theta_dot acts); the others do."""
    empty = [key for key in SCENES if not system_for(key).conserved]
    assert empty == ["damped-pendulum"]


def test_verlet_and_yoshida_refuse_non_separable_systems():
    for key in ("spherical-pendulum", "tabletop-spring", "rotating-parabola", "damped-pendulum"):
        assert METHODS["Yoshida4"].applicable(system_for(key))
        assert METHODS["Verlet"].applicable(system_for(key))
        assert METHODS["Gauss-Legendre"].applicable(system_for(key)) is None
