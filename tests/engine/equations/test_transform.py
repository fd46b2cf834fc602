"""A declared change of coordinates: the engine derives the motion again in the new ones."""

import pytest
import sympy as sp

from app.engine.derivation.derive import derive, transform
from app.engine.errors import DerivationError
from app.scenes.types import CoordinateChange, Parameter, Particle, System
from tests.reference import numerically_equal

k, b, m, w = (Parameter(n, 1.0, min=0.1) for n in ("k", "b", "m", "omega"))


def test_no_change_declared():
    assert transform(System(coordinates=("x",), kinetic="x_dot**2/2", potential="0")) is None


@pytest.mark.slow
def test_forces_and_velocities_follow_the_chain_rule():
    # a damped spring, re-described by u = 2 x + 1: Q_u = Q_x dx/du = -b x_dot / 2
    system = System(
        coordinates=("x",),
        parameters=(m, k, b),
        kinetic="m*x_dot**2/2",
        potential="k*x**2/2",
        forces={"x": "-b*x_dot"},
        coordinate_change=CoordinateChange(("u",), ("2*x + 1",)),
    )
    tr = transform(system)
    d = tr.derivation
    u, u_dot = sp.Symbol("u", real=True), sp.Symbol("u_dot", real=True)
    assert tr.system.forces == {"u": "-b*u_dot/4"}
    # u_ddot = 2 x_ddot: the accelerations agree once mapped back
    x_dd = derive(system).equations.accelerations[0]
    back = tr.to_original(d.equations.accelerations[0])
    symbols = sorted(back.free_symbols | x_dd.free_symbols, key=str)
    assert numerically_equal(back, 2 * x_dd, symbols)
    assert tr.to_original(u_dot) == 2 * sp.Symbol("x_dot", real=True)
    assert tr.to_original(u) == 2 * sp.Symbol("x", real=True) + 1


def test_time_dependent_change_into_a_rotating_frame():
    # a free particle on a line seen from a frame moving at speed omega: s = x - omega t
    system = System(
        coordinates=("x",),
        parameters=(m, w),
        particles=(Particle("m", ("x", "0", "0")),),
        potential="0",
        coordinate_change=CoordinateChange(("s",), ("x - omega*t",)),
    )
    tr = transform(system)
    en = tr.derivation.energetics
    # the position now depends on t: T has a linear part and h differs from E
    assert tr.derivation.equations.accelerations[0] == 0
    assert not en.h_equals_e


@pytest.mark.slow
@pytest.mark.parametrize(
    ("change", "message"),
    [
        (CoordinateChange(("X",), ("x1 + x2",)), "one definition per new coordinate"),
        (CoordinateChange(("x1", "u"), ("x1", "x2")), "new names"),
        (CoordinateChange(("X", "u"), ("x1 + x2", "2*x1 + 2*x2")), "could not be inverted"),
        (CoordinateChange(("X", "u"), ("x1 + x2", "x2 - x1"), relative="v"), "not a new coordinate"),
        (CoordinateChange(("X", "u"), ("x1 + q", "x2")), "unknown name"),
    ],
)
def test_bad_changes_are_refused(change, message):
    system = System(
        coordinates=("x1", "x2"),
        parameters=(k,),
        particles=(Particle("1", ("x1", "0", "0")), Particle("1", ("x2", "0", "0"))),
        potential="k*(x2 - x1)**2/2",
        coordinate_change=change,
    )
    with pytest.raises(DerivationError, match=message):
        transform(system)
