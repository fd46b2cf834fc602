"""Pendulum scenes: a bob on a string, in a plane, on a sphere, and with damping."""

from app.scenes import reasons
from app.scenes.common import GRAVITY
from app.scenes.types import Constraint, Erratum, Parameter, Particle, Scene, System

MASS = Parameter("m", 1.0, "kg", 0.01, 100.0, "mass of the bob")
# the spherical pendulum's statement speaks of a ball
BALL = Parameter("m", 1.0, "kg", 0.01, 100.0, "mass of the ball")
LENGTH = Parameter("R", 1.0, "m", 0.05, 100.0, "length of the string")
DAMPING = Parameter("b", 0.3, "kg·m²/s", 0.0, 100.0, "damping coefficient: the drag's torque about the pivot is −b θ̇")

# The bob of the planar pendulums: x horizontal, z vertical, origin at the lowest point of the swing.
PLANAR_BOB = Particle("m", ("R*sin(theta)", "0", "R - R*cos(theta)"), "bob")
# The string keeps the bob at distance R from the pivot (0, 0, R); g grows toward the pivot,
# so the reported force is the tension (a string cannot push).
PLANAR_STRING = Constraint(
    "string tension",
    "R**2 - x**2 - (z - R)**2",
    "The string's pull on the bob, positive toward the pivot; a negative value means the string would have to "
    "push, so it goes slack.",
    slack_when_negative=True,
)

SIMPLE_PENDULUM = Scene(
    id="simple-pendulum",
    coordinate_meanings={
        "theta": "angle of the string from the downward vertical",
    },
    title="Simple pendulum",
    section="4.3",
    family="pendulum",
    reasons=reasons.SIMPLE_PENDULUM,
    summary="One angle, one equation: the Lagrangian recipe on the smallest example.",
    statement=(
        "A small bob of mass m hangs from a fixed pivot on a string of length R and swings in a "
        "vertical plane. The angle θ is measured from the downward vertical through the pivot. Positions are "
        "measured from the lowest point of the swing, x across and heights z measured upward, with U = 0 there. "
        "Derive the equation of motion and the frequency of small swings."
    ),
    figure=(
        "A pivot at the top, a string of length R, the bob at angle θ from the downward vertical; the axes x across "
        "and z up start at the lowest point of the swing, where positions are measured from."
    ),
    system=System(
        coordinates=("theta",),
        parameters=(MASS, GRAVITY, LENGTH),
        particles=(PLANAR_BOB,),
        potential="m*g*R*(1 - cos(theta))",
        cartesian_potential="m*g*z",
        constraints=(PLANAR_STRING,),
    ),
    initial={"theta": 1.0, "theta_dot": 0.0},
    t_end=10.0,
    panels=("effective-potential", "small-oscillations"),
    errata=(
        Erratum(
            chapter="v = x_dot^2 + y_dot^2 + z_dot^2",
            correct="v**2 = R**2*theta_dot**2",
            reason="A sum of squared velocity components is the squared speed, not the speed; for the bob it is R² θ̇².",
            check="speed-squared:1",
        ),
        Erratum(
            chapter="tau = I omega = m R^2 g/R = m g R",
            # the torque as Γ (Taylor's letter): τ on this page is the action panel's duration
            correct="Gamma = ∂L/∂theta = -m*g*R*sin(theta)",
            reason=(
                "I ω is an angular momentum, not a torque, and the ω put in, g/R, is not even an angular velocity: "
                "its unit is s⁻², not s⁻¹. "
                "The torque of gravity about the pivot, written Γ here (τ on this page is a duration), is "
                "∂L/∂θ = −m g R sin θ: it depends on the angle and vanishes at the bottom."
            ),
            check="dL/dq:theta",
        ),
        Erratum(
            chapter="theta_ddot + (g/R) sin(theta) = 0 is simple harmonic with omega = sqrt(g/R)",
            correct="theta_ddot = -g*theta/R",
            reason=(
                "Because of sin θ the chapter's equation is not linear, so it is not simple harmonic. Only small "
                "swings, where sin θ ≈ θ, obey the linear equation shown, simple harmonic with ω² = g/R; wide "
                "swings take longer."
            ),
            check="linear-acceleration:theta",
            approximate_for=r"|\theta| \ll 1",
        ),
    ),
)

SPHERICAL_PENDULUM = Scene(
    id="spherical-pendulum",
    coordinate_meanings={
        "theta": "polar angle of the string from the upward vertical",
        "phi": "azimuth of the string about the vertical",
    },
    title="Spherical pendulum",
    section="4.4",
    family="spherical-pendulum",
    reasons=reasons.SPHERICAL_PENDULUM,
    summary="A cyclic azimuth, a conserved angular momentum and an effective potential.",
    statement=(
        "A ball of mass m on an inextensible string of length R moves anywhere on the sphere the "
        "string allows. The polar angle θ is measured from the upward vertical and φ is the "
        "azimuth. Heights are measured upward from the pivot, where U = 0. Derive the equations of motion and "
        "their first integrals."
    ),
    figure="A sphere of radius R about the pivot, the ball at polar angle θ from the upward axis and azimuth φ.",
    system=System(
        coordinates=("theta", "phi"),
        parameters=(BALL, GRAVITY, LENGTH),
        particles=(Particle("m", ("R*sin(theta)*cos(phi)", "R*sin(theta)*sin(phi)", "R*cos(theta)"), "ball"),),
        potential="m*g*R*cos(theta)",
        cartesian_potential="m*g*z",
        constraints=(
            Constraint(
                "string tension",
                "R**2 - x**2 - y**2 - z**2",
                "The string's pull on the ball, positive toward the pivot at the origin; negative means slack.",
                slack_when_negative=True,
            ),
        ),
    ),
    initial={"theta": 2.2, "theta_dot": 0.0, "phi": 0.0, "phi_dot": 2.0},
    t_end=10.0,
    upward_angles=("theta",),
    panels=("effective-potential",),
    errata=(
        Erratum(
            chapter="s = (R, R theta, R sin(theta) phi)",
            correct="r = (R*sin(theta)*cos(phi), R*sin(theta)*sin(phi), R*cos(theta))",
            reason=(
                "The chapter's triple lists arc lengths along the spherical unit vectors, not a position; the "
                "Cartesian position is the one given here, and differentiating it yields the chapter's velocity."
            ),
            check="position:1",
        ),
        Erratum(
            chapter="theta_ddot - sin(theta) cos(theta) phi_dot^2 + (g/R) sin(theta) = 0",
            correct="theta_ddot = sin(theta)*cos(theta)*phi_dot**2 + g*sin(theta)/R",
            reason=(
                "With θ from the upward vertical, U = m g R cos θ and gravity drives θ away from the top, so its "
                "term enters with the opposite sign; the chapter's sign belongs to θ measured from the bottom."
            ),
            check="acceleration:theta",
        ),
        Erratum(
            chapter="theta_ddot - (p_theta/(m R^2))^2 sin(theta) cos(theta) + (g/R) sin(theta) = 0",
            correct="theta_ddot = p_phi**2*cos(theta)/(m**2*R**4*sin(theta)**3) + g*sin(theta)/R",
            reason=(
                "The conserved momentum is p_φ (φ is cyclic), not p_θ, and φ̇ = p_φ/(m R² sin²θ) leaves sin³θ in "
                "the denominator; the gravity term's sign is corrected as above."
            ),
            check="reduced-acceleration:theta",
        ),
    ),
)

DAMPED_PENDULUM = Scene(
    id="damped-pendulum",
    coordinate_meanings={
        "theta": "angle of the string from the downward vertical",
    },
    title="Damped pendulum",
    section="4.1",
    family="pendulum",
    marks=("drag",),
    reasons=reasons.DAMPED_PENDULUM,
    answers=("power",),  # the rate at which the energy decays
    summary="A force no potential describes enters as a generalized force Q and drains the energy.",
    statement=(
        "The simple pendulum again (bob of mass m, string of length R, θ from the bottom), now slowed by a drag "
        "whose torque about the pivot is −b θ̇: it opposes the swing in proportion to its rate, as friction in "
        "the pivot's bearing does. The constant b belongs to the pendulum and stays the same when R changes (air "
        "drag −c v on the bob alone would give b = c R²). On the bob the same torque is a force of magnitude "
        "(b/R) |θ̇| along the path, against the motion. Drag has no potential energy, so it cannot sit in L; "
        "its torque is the generalized force Q_θ = −b θ̇ on the right-hand side of the Euler–Lagrange equation. Find the equation of motion and the rate at which the "
        "energy decays. As for the simple pendulum, heights are measured upward from the lowest point, where "
        "U = 0."
    ),
    figure=(
        "The simple pendulum's pivot, string and bob moving with velocity v, and the drag on the bob: an arrow along "
        "the path against v, labelled with its magnitude; the axes x across and z up start at the lowest point."
    ),
    system=System(
        coordinates=("theta",),
        parameters=(MASS, GRAVITY, LENGTH, DAMPING),
        particles=(PLANAR_BOB,),
        potential="m*g*R*(1 - cos(theta))",
        forces={"theta": "-b*theta_dot"},
        cartesian_potential="m*g*z",
        constraints=(PLANAR_STRING,),
    ),
    initial={"theta": 1.5, "theta_dot": 0.0},
    t_end=20.0,
    # ours, not one of the chapter's examples: it illustrates 4.1's generalized forces on a system the chapter has
    beyond_chapter=True,
)
