"""Rigid bodies: T = ½ M v_cm² + ½ I_cm θ̇² per body, against sympy.physics.mechanics's RigidBody and
LagrangesMethod, and the step that shows each body's two pieces."""

from dataclasses import replace

import pytest
import sympy as sp
import sympy.physics.mechanics as me

from app.engine.derivation.derive import derive
from app.engine.document.report import build_steps
from app.engine.errors import DerivationError
from app.scenes.types import Body, CoordinateChange, Parameter, Particle, System
from tests.reference import lagranges_method, numerically_equal, reference_accelerations

M, m, m1, m2, g, length, R, r, alpha = (
    Parameter(n, 1.0, min=0.1) for n in ("M", "m", "m1", "m2", "g", "l", "R", "r", "alpha")
)

SYSTEMS = {
    # a uniform rod pivoted at one end (the physical pendulum)
    "rod-pendulum": System(
        coordinates=("theta",),
        parameters=(M, g, length),
        bodies=(Body("rod", "M", "l", ("l*sin(theta)/2", "0", "-l*cos(theta)/2"), "theta", "rod"),),
        potential="-M*g*l*cos(theta)/2",
    ),
    # a disc rolling without slipping down a fixed incline: it turns by x/R as its centre moves x along the slope
    "rolling-disc": System(
        coordinates=("x",),
        parameters=(M, g, R, alpha),
        bodies=(Body("disc", "M", "R", ("x*cos(alpha)", "0", "-x*sin(alpha)"), "-x/R", "disc"),),
        potential="-M*g*x*sin(alpha)",
    ),
    # an Atwood machine whose pulley is a disc turning by y/R as the string runs without slipping
    "atwood-pulley": System(
        coordinates=("y",),
        parameters=(M, m1, m2, g, R),
        particles=(Particle("m1", ("-R", "0", "y"), "left mass"), Particle("m2", ("R", "0", "-y"), "right mass")),
        bodies=(Body("disc", "M", "R", ("0", "0", "0"), "y/R", "pulley"),),
        potential="m1*g*y - m2*g*y",
    ),
    # a ladder (a rod) sliding with its ends on a smooth wall and a smooth floor
    "ladder": System(
        coordinates=("theta",),
        parameters=(M, g, length),
        bodies=(Body("rod", "M", "l", ("l*sin(theta)/2", "0", "l*cos(theta)/2"), "theta", "ladder"),),
        potential="M*g*l*cos(theta)/2",
    ),
    # a solid ball rolling in a fixed trough of radius R: its centre on a circle of radius R - r, turning by
    # (R - r) phi / r the other way
    "ball-in-trough": System(
        coordinates=("phi",),
        parameters=(M, g, R, r),
        bodies=(Body("sphere", "M", "r", ("(R - r)*sin(phi)", "0", "-(R - r)*cos(phi)"), "-(R - r)*phi/r", "ball"),),
        potential="-M*g*(R - r)*cos(phi)",
    ),
    # a cart with a hoop hung from it on its rim: a point mass and a ring, two coordinates
    "cart-and-hoop": System(
        coordinates=("x", "theta"),
        parameters=(M, m, g, r),
        particles=(Particle("m", ("x", "0", "0"), "cart"),),
        bodies=(Body("ring", "M", "r", ("x + r*sin(theta)", "0", "-r*cos(theta)"), "theta", "hoop"),),
        potential="-M*g*r*cos(theta)",
    ),
}


def _symbols(*exprs):
    return sorted(set().union(*(e.free_symbols for e in exprs)) | {sp.Symbol("t", real=True)}, key=str)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_accelerations_match_lagranges_method_with_rigid_bodies(name):
    system = SYSTEMS[name]
    ours = derive(system).equations.accelerations
    theirs, _ = reference_accelerations(system)
    for a, b in zip(ours, theirs, strict=True):
        assert numerically_equal(a, b, _symbols(a, b)), (name, a, b)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_kinetic_energy_matches_the_rigid_bodies_of_sympy_mechanics(name):
    system = SYSTEMS[name]
    T = derive(system).mechanics.T
    lm, _, read = lagranges_method(system)
    # the reference T is its Lagrangian plus U, in the project's plain symbols
    _, back = reference_accelerations(system)
    theirs = (sp.Matrix([lm._L])[0] + read(system.potential)).subs(back)
    assert numerically_equal(T, theirs, _symbols(T, theirs)), (name, T, theirs)


@pytest.mark.slow
def test_each_body_has_its_translation_and_rotation_and_the_step_names_them():
    d = derive(SYSTEMS["atwood-pulley"])
    (pulley,) = d.mechanics.bodies
    y_dot, M_, R_ = (sp.Symbol(n, real=True) for n in ("y_dot", "M", "R"))
    # the pulley's centre does not move: all of its energy is its turning
    assert pulley.translation == 0 and sp.simplify(pulley.rotation - M_ * y_dot**2 / 4) == 0
    steps = {s["key"]: s for s in build_steps(d)}
    assert r"I_{\mathrm{cm}} &= \frac{M R^{2}}{2}" in steps["bodies"]["latex"]
    kinetic = steps["kinetic"]
    assert (
        r"T_{\mathrm{pulley}} &= \tfrac{1}{2} M v_{\mathrm{cm}}^2 + \tfrac{1}{2} I_{\mathrm{cm}} "
        r"\left(\frac{\dot{y}}{R}\right)^{2}" in kinetic["latex"]
    )
    # the turning rate is written as itself, never ω, which the pages keep for frequencies (issue 40, item 2)
    assert "the pulley turns at the rate ẏ/R" in steps["bodies"]["explanation"]
    assert "½ I_cm (ẏ/R)² = Mẏ²/4" in kinetic["explanation"]
    for step in (steps["bodies"], kinetic):
        assert r"\omega" not in step["latex"] and "ω" not in step["explanation"], step
    assert "pulley's is ½ M v_cm² = 0 for the motion of its centre" in kinetic["explanation"]
    assert "point mass" in kinetic["explanation"]


@pytest.mark.slow
def test_two_bodies_are_numbered():
    system = System(
        coordinates=("theta",),
        parameters=(M, m, g, length),
        bodies=(
            Body("rod", "M", "l", ("l*sin(theta)/2", "0", "-l*cos(theta)/2"), "theta", "rod"),
            Body("disc", "m", "l", ("0", "0", "0"), "theta", "wheel"),
        ),
        potential="-M*g*l*cos(theta)/2",
    )
    latex = {s["key"]: s["latex"] for s in build_steps(derive(system))}
    assert r"I_{\mathrm{cm},2}" in latex["bodies"] and r"I_{\mathrm{cm},2} \dot{\theta}^{2}" in latex["kinetic"]
    assert r"T_{\mathrm{wheel}}" in latex["kinetic"] and r"T_{\mathrm{rod}}" in latex["kinetic"]


def test_an_unknown_kind_of_body_is_refused_by_name():
    system = System(
        coordinates=("theta",),
        parameters=(M, length),
        bodies=(Body("cube", "M", "l", ("0", "0", "0"), "theta"),),
        potential="0",
    )
    with pytest.raises(DerivationError, match="a body is one of rod, disc, ring, sphere, not 'cube'"):
        derive(system)


def test_the_reference_rigid_body_is_not_a_particle():
    # the reference does turn its bodies: a disc spinning in place has T = ½ I ω² = M R² θ̇²/4, not 0
    system = System(
        coordinates=("theta",),
        parameters=(M, R),
        bodies=(Body("disc", "M", "R", ("0", "0", "0"), "theta"),),
        potential="0",
    )
    lm, qs, _ = lagranges_method(system)
    t = me.dynamicsymbols._t
    M_, R_ = sp.Symbol("M", real=True), sp.Symbol("R", real=True)
    assert sp.simplify(sp.Matrix([lm._L])[0] - M_ * R_**2 * qs[0].diff(t) ** 2 / 4) == 0


def test_a_change_of_coordinates_moves_the_bodies_too():
    # the rolling disc in the angle it has turned, s = x/R: the same T, written in s
    system = replace(SYSTEMS["rolling-disc"], coordinate_change=CoordinateChange(("s",), ("x/R",)))
    moved = derive(system).transformed
    assert moved.system.bodies[0].angle == "-s"
    s_dot, M_, R_ = (sp.Symbol(n, real=True) for n in ("s_dot", "M", "R"))
    # ½ M (R ṡ)² + ½ (M R²/2) ṡ²
    assert sp.simplify(moved.derivation.mechanics.T - sp.Rational(3, 4) * M_ * R_**2 * s_dot**2) == 0
