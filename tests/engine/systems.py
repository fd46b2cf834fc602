"""Systems declared only for tests (besides the chapter's scenes)."""

from app.scenes.types import Parameter, Particle, System

m, g, R, k, b, w = (Parameter(n, 1.0, min=0.1) for n in ("m", "g", "R", "k", "b", "omega"))
m1, m2, l1, l2 = (Parameter(n, 1.0, min=0.1) for n in ("m1", "m2", "l1", "l2"))

DOUBLE_PENDULUM = System(
    coordinates=("a", "c"),
    parameters=(m1, m2, l1, l2, g),
    particles=(
        Particle("m1", ("l1*sin(a)", "-l1*cos(a)", "0")),
        Particle("m2", ("l1*sin(a) + l2*sin(c)", "-l1*cos(a) - l2*cos(c)", "0")),
    ),
    potential="-m1*g*l1*cos(a) - m2*g*(l1*cos(a) + l2*cos(c))",
)

# A bead on a straight rod spun in a horizontal plane at a fixed rate: a moving constraint.
SPINNING_ROD = System(
    coordinates=("rho",),
    parameters=(m, w),
    particles=(Particle("m", ("rho*cos(omega*t)", "rho*sin(omega*t)", "0")),),
    potential="0",
)

TABLETOP = System(
    coordinates=("r", "theta"),
    parameters=(m, k),
    particles=(Particle("m", ("r*cos(theta)", "r*sin(theta)", "0")),),
    potential="k*r**2/2",
    nonnegative=("r",),
)

DAMPED_SPRING = System(
    coordinates=("x",),
    parameters=(m, k, b),
    kinetic="m*x_dot**2/2",
    potential="k*x**2/2",
    forces={"x": "-b*x_dot"},
)

LAGRANGIAN_ONLY = System(coordinates=("x",), parameters=(k,), lagrangian="x_dot**2/2 - k*x**2/2")

# A charge in a uniform magnetic field B (vector potential B x (-y, x)/2) held by an isotropic spring:
# L has terms linear in the velocities, so p = m v + q A and H = (p - q A)^2/(2m) + U.
CHARGE_IN_FIELD = System(
    coordinates=("x", "y"),
    parameters=(m, k, Parameter("B", 0.7, min=0.1)),
    lagrangian="m*(x_dot**2 + y_dot**2)/2 + B*(x*y_dot - y*x_dot)/2 - k*(x**2 + y**2)/2",
)

# Three unequal masses in a line, joined by two springs of rest length 1 and tied to a wall by a third:
# three coordinates, an equilibrium away from the origin, three normal modes.
SPRING_CHAIN = System(
    coordinates=("u", "v", "s"),
    parameters=(
        Parameter("m1", 1.0, min=0.1),
        Parameter("m2", 2.0, min=0.1),
        Parameter("m3", 0.5, min=0.1),
        Parameter("k", 3.0, min=0.1),
    ),
    kinetic="m1*u_dot**2/2 + m2*v_dot**2/2 + m3*s_dot**2/2",
    potential="k*(u - 1)**2/2 + k*(v - u - 1)**2/2 + 2*k*(s - v - 1)**2/2",
)

TEST_SYSTEMS = {
    "double-pendulum": DOUBLE_PENDULUM,
    "spinning-rod": SPINNING_ROD,
    "tabletop": TABLETOP,
    "damped-spring": DAMPED_SPRING,
    "lagrangian-only": LAGRANGIAN_ONLY,
    "charge-in-field": CHARGE_IN_FIELD,
    "spring-chain": SPRING_CHAIN,
}
