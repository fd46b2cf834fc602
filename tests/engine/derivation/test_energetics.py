"""Why h differs from E, named from where T1 and T0 come from; h = E left undecided when only L is given (issue 19)."""

import pytest

from app.engine.derivation.derive import derive
from app.scenes.types import Parameter, Particle, System

P = tuple(Parameter(n, 1.0, min=0.1) for n in ("m", "c", "B", "omega", "v", "a", "g", "l"))


def energetics(**declaration):
    return derive(System(parameters=P, **declaration)).energetics


@pytest.mark.slow
def test_a_magnetic_term_in_T_is_named_and_no_moving_constraint_is_invented():
    # a charge in a uniform magnetic field B along z, the symmetric gauge A = B (-y, x, 0)/2
    en = energetics(
        coordinates=("x", "y"), kinetic="m*(x_dot**2 + y_dot**2)/2 + c*B*(x*y_dot - y*x_dot)/2", potential="0"
    )
    assert en.h_equals_e is False
    assert "linear in the velocities" in en.reason and "magnetic" in en.reason
    assert "time" not in en.reason and "moving" not in en.reason
    # nothing depends on time and no force acts: h is conserved (and equals T2 + U)
    assert en.h_conserved and [c.name for c in en.conserved if c.name in ("E", "h")] == ["h"]


@pytest.mark.slow
def test_a_moving_constraint_is_named_with_the_particle_that_moves():
    # a bead on a rod spun at a fixed rate
    en = energetics(
        coordinates=("r",), particles=(Particle("m", ("r*cos(omega*t)", "r*sin(omega*t)", "0")),), potential="0"
    )
    assert en.h_equals_e is False
    # one body: "the particle", not "particle 1"; the spun rod gives T a part T₀ and no T₁
    assert "moving constraint" in en.reason and "the position of the particle" in en.reason
    # T₁ is said to be absent (issue 40: a reader comparing E − h = T₁ + 2T₀ elsewhere asks where it went)
    assert "E − h = 2T₀" in en.reason and "(T₁ = 0)" in en.reason
    assert "magnetic" not in en.reason
    # two bodies, one of them on the spun rod: that one is named by its number
    two = energetics(
        coordinates=("r", "x"),
        particles=(Particle("m", ("r*cos(omega*t)", "r*sin(omega*t)", "0")), Particle("m", ("x", "0", "0"))),
        potential="0",
    )
    assert "the position of particle 1 contains t" in two.reason


@pytest.mark.slow
def test_both_sources_are_named():
    # a velocity-linear magnetic term and a drive that makes T depend on time (a moving support)
    en = energetics(
        coordinates=("x", "y"),
        kinetic="m*(x_dot**2 + y_dot**2)/2 + c*B*x*y_dot + m*v*cos(omega*t)*x_dot",
        potential="0",
    )
    assert en.h_equals_e is False
    assert "depends explicitly on time" in en.reason and "moving constraint" in en.reason
    assert "magnetic" in en.reason


def test_a_rotating_frame_names_its_velocity_linear_and_velocity_free_parts():
    en = energetics(
        coordinates=("x", "y"),
        kinetic="m*(x_dot**2 + y_dot**2)/2 + m*omega*(x*y_dot - y*x_dot) + m*omega**2*(x**2 + y**2)/2",
        potential="0",
    )
    assert en.h_equals_e is False
    assert "linear in the velocities" in en.reason and "without velocities" in en.reason
    assert "time" not in en.reason


def test_fixed_constraints_keep_h_equal_to_e():
    en = energetics(
        coordinates=("theta",),
        particles=(Particle("m", ("l*sin(theta)", "-l*cos(theta)", "0")),),
        potential="-m*g*l*cos(theta)",
    )
    assert en.h_equals_e is True and en.h_conserved
    assert [c.name for c in en.conserved] == ["E"]


def test_only_l_leaves_h_equals_e_undecided():
    en = energetics(coordinates=("x",), lagrangian="m*x_dot**2/2 - a*x**2/2")
    assert en.h_equals_e is None
    assert "only L was given" in en.reason.replace("Only", "only") and "cannot be told apart" in en.reason
    assert en.h_conserved and [c.name for c in en.conserved] == ["h"]


# the Kapitza pendulum (pivot driven vertically as a cos(omega t)) as L alone, terms in t only dropped
KAPITZA = "m*l**2*theta_dot**2/2 - m*l*a*omega*sin(omega*t)*sin(theta)*theta_dot + m*g*l*cos(theta)"


def test_a_time_dependent_l_says_h_is_not_conserved():
    en = energetics(coordinates=("theta",), lagrangian=KAPITZA)
    assert en.h_equals_e is None
    assert not en.h_conserved and "depends explicitly on time" in en.h_conserved_reason
    assert not [c for c in en.conserved if c.name in ("E", "h")]


def test_a_force_that_does_no_work_keeps_h_conserved():
    # the Lorentz force written as generalized forces: Q = c B (y_dot, -x_dot), power Q . q_dot = 0
    en = energetics(
        coordinates=("x", "y"),
        kinetic="m*(x_dot**2 + y_dot**2)/2",
        potential="0",
        forces={"x": "c*B*y_dot", "y": "-c*B*x_dot"},
    )
    assert en.h_equals_e is True and en.h_conserved
    assert [c.name for c in en.conserved] == ["E"]
    damped = energetics(coordinates=("x",), kinetic="m*x_dot**2/2", potential="0", forces={"x": "-c*x_dot"})
    assert not damped.h_conserved and "do work" in damped.h_conserved_reason
