"""Fixed distances between particles (rods for a drawing), and the unit directions of the forces of constraint."""

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.derivation.rods import fixed_distances
from app.engine.document.contract import unit_gradient
from app.engine.equations.constraints import constraint_forces
from app.scenes import SCENES
from app.scenes.types import Parameter, Particle, System

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def test_the_double_pendulum_has_a_rod_to_the_pivot_and_one_between_the_bobs():
    assert fixed_distances(derive(SCENES["double-pendulum"].system)) == [{"from": None, "to": 0}, {"from": 0, "to": 1}]


@pytest.mark.parametrize("scene_id", ["rail-two-body", "coupled-oscillators", "tabletop-spring", "pulley"])
def test_springs_and_strings_over_pulleys_are_not_rods(scene_id):
    assert fixed_distances(derive(SCENES[scene_id].system)) == []


def test_a_rigid_pair_moving_in_time_is_found():
    # a dumbbell of length l whose centre is carried along x at speed v and which turns freely
    system = System(
        coordinates=("q",),
        parameters=(Parameter("l", 1.0), Parameter("v", 1.0)),
        particles=(
            Particle("1", ("v*t + l*cos(q)/2", "l*sin(q)/2", "0")),
            Particle("1", ("v*t - l*cos(q)/2", "-l*sin(q)/2", "0")),
        ),
        potential="0",
    )
    assert fixed_distances(derive(system)) == [{"from": 0, "to": 1}]


@pytest.mark.parametrize("scene_id", ["incline-block", "simple-pendulum", "pulley", "spherical-pendulum"])
def test_force_directions_are_unit_vectors_along_the_gradient(scene_id):
    d = derive(SCENES[scene_id].system)
    for f in constraint_forces(d.system, d.mechanics, d.equations):
        u = unit_gradient(f)
        assert sp.simplify(sum(e**2 for e in u) - 1) == 0
        # parallel to grad g and pointing the same way: u = grad g / |grad g|
        assert all(
            sp.simplify(a * sp.sqrt(sum(e**2 for e in f.gradient)) - b) == 0 for a, b in zip(u, f.gradient, strict=True)
        )


def test_the_incline_pushes_perpendicular_to_its_slope():
    d = derive(SCENES["incline-block"].system)
    (f,) = constraint_forces(d.system, d.mechanics, d.equations)
    assert [sp.sstr(e) for e in unit_gradient(f)] == ["-sin(alpha)", "0", "cos(alpha)"]
