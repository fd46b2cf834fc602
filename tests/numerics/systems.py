"""Systems declared for the numerics tests and benchmarks (besides the chapter's scenes)."""

from app.scenes.types import Parameter, Particle, System

# A bead on a stiff radial spring of rest length l0 on a frictionless table, in polar coordinates:
# the radial mode has omega^2 = k/m (fast), the orbit turns at the slow rate theta_dot.
STIFF_SPRING = System(
    coordinates=("r", "theta"),
    parameters=(
        Parameter("m", 1.0, "kg", 1e-3, 1e3),
        Parameter("k", 1e6, "N/m", 1e-3, 1e12),
        Parameter("l0", 1.0, "m", 1e-3, 1e3),
    ),
    particles=(Particle("m", ("r*cos(theta)", "r*sin(theta)", "0")),),
    potential="k*(r - l0)**2/2",
    nonnegative=("r",),
)

m1, m2, l1, l2, g = (
    Parameter("m1", 1.0, "kg", 0.01, 100.0),
    Parameter("m2", 1.0, "kg", 0.01, 100.0),
    Parameter("l1", 1.0, "m", 0.05, 100.0),
    Parameter("l2", 1.0, "m", 0.05, 100.0),
    Parameter("g", 9.81, "m/s²", 0.1, 100.0),
)

DOUBLE_PENDULUM = System(
    coordinates=("a", "c"),
    parameters=(m1, m2, l1, l2, g),
    particles=(
        Particle("m1", ("l1*sin(a)", "-l1*cos(a)", "0")),
        Particle("m2", ("l1*sin(a) + l2*sin(c)", "-l1*cos(a) - l2*cos(c)", "0")),
    ),
    potential="-m1*g*l1*cos(a) - m2*g*(l1*cos(a) + l2*cos(c))",
)

# Two decoupled damped oscillators, k/m = 1 (slow) and 1e8 (fast): a linear stiff system whose exact
# motion is the matrix exponential, y(t) = exp(A t) y0 with A the 4 x 4 first-order matrix.
TWO_MODES = System(
    coordinates=("x1", "x2"),
    parameters=(
        Parameter("m", 1.0, "kg", 1e-3, 1e3),
        Parameter("k1", 1.0, "N/m", 1e-3, 1e12),
        Parameter("k2", 1e8, "N/m", 1e-3, 1e12),
        Parameter("b1", 0.1, "N s/m", 0.0, 1e6),
        Parameter("b2", 2e3, "N s/m", 0.0, 1e6),
    ),
    kinetic="m*x1_dot**2/2 + m*x2_dot**2/2",
    potential="k1*x1**2/2 + k2*x2**2/2",
    forces={"x1": "-b1*x1_dot", "x2": "-b2*x2_dot"},
)


# The stiff user systems of issue 47, as a request to POST /api/simulate declares them (auto refused both
# with scipy's Radau under load): their fast modes start quiet, so auto steps over them.
LOPSIDED_CHAIN = {  # wall - spring - 1e-9 kg - spring - 1e9 kg - spring - wall, springs of 1e9 N/m
    # (the heavy mass swings at about 1.2 rad/s, the light one would at 1.4e9 rad/s)
    "coordinates": ["x1", "x2"],
    "parameters": [
        {"name": "m1", "value": 1e-9, "min": 1e-12},
        {"name": "m2", "value": 1e9, "min": 1e-12},
        {"name": "k", "value": 1e9, "min": 1e-3},
    ],
    "kinetic": "m1*x1_dot**2/2 + m2*x2_dot**2/2",
    "potential": "k*x1**2/2 + k*(x2 - x1)**2/2 + k*x2**2/2",
    # the light mass where the springs balance it (k x1 = k (x2 - x1)), both at rest
    "initial": {"x1": 0.5, "x2": 1.0, "x1_dot": 0.0, "x2_dot": 0.0},
    "t_end": 10.0,
}
STIFF_SOFT_CHAIN = {  # wall - stiff spring (1e8) - 1 kg - soft spring (1) - 1 kg
    "coordinates": ["x1", "x2"],
    "parameters": [
        {"name": "m", "value": 1.0, "min": 1e-3},
        {"name": "k1", "value": 1e8, "min": 1e-3},
        {"name": "k2", "value": 1.0, "min": 1e-3},
    ],
    "kinetic": "m*x1_dot**2/2 + m*x2_dot**2/2",
    "potential": "k1*x1**2/2 + k2*(x2 - x1)**2/2",
    # x1 where the springs balance (k1 x1 = k2 (x2 - x1)): the stiff mode at rest
    "initial": {"x1": 1.0 / (1e8 + 1.0), "x2": 1.0, "x1_dot": 0.0, "x2_dot": 0.0},
    "t_end": 5.0,
}
