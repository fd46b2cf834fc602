"""Pendulum scenes: a bob on a string, in a plane and on a sphere."""

from app.scenes.types import Parameter, Particle, Scene, System

MASS = Parameter("m", 1.0, "kg", 0.01, 100.0, "mass of the bob")
GRAVITY = Parameter("g", 9.81, "m/s²", 0.1, 100.0, "gravitational acceleration")
LENGTH = Parameter("R", 1.0, "m", 0.05, 100.0, "length of the string")

SIMPLE_PENDULUM = Scene(
    id="simple-pendulum",
    title="Simple pendulum",
    section="4.3",
    summary="One angle, one equation: the Lagrangian recipe on the smallest example.",
    statement=(
        "A small bob of mass m hangs from a fixed pivot on a string of length R and swings in a "
        "vertical plane. The angle θ is measured from the lowest point. Derive the equation of "
        "motion and the frequency of small swings."
    ),
    figure="A pivot at the top, a string of length R, the bob at angle θ from the downward vertical.",
    system=System(
        coordinates=("theta",),
        parameters=(MASS, GRAVITY, LENGTH),
        # x horizontal, z vertical with the origin at the lowest point of the swing
        particles=(Particle("m", ("R*sin(theta)", "0", "R - R*cos(theta)"), "bob"),),
        potential="m*g*R*(1 - cos(theta))",
    ),
    initial={"theta": 1.0, "theta_dot": 0.0},
    t_end=10.0,
    panels=("animation-2d", "energy", "phase", "effective-potential", "small-oscillations"),
)

SPHERICAL_PENDULUM = Scene(
    id="spherical-pendulum",
    title="Spherical pendulum",
    section="4.4",
    summary="A cyclic azimuth, a conserved angular momentum and an effective potential.",
    statement=(
        "A ball of mass m on an inextensible string of length R moves anywhere on the sphere the "
        "string allows. The polar angle θ is measured from the upward vertical and φ is the "
        "azimuth. Derive the equations of motion and their first integrals."
    ),
    figure="A sphere of radius R about the pivot, the ball at polar angle θ from the upward axis and azimuth φ.",
    system=System(
        coordinates=("theta", "phi"),
        parameters=(MASS, GRAVITY, LENGTH),
        particles=(Particle("m", ("R*sin(theta)*cos(phi)", "R*sin(theta)*sin(phi)", "R*cos(theta)"), "ball"),),
        potential="m*g*R*cos(theta)",
    ),
    initial={"theta": 2.2, "theta_dot": 0.0, "phi": 0.0, "phi_dot": 2.0},
    t_end=10.0,
    panels=("animation-3d", "energy", "momenta", "phase", "effective-potential"),
)
