"""Systems beyond the chapter with known equilibria, stabilities and frequencies (issue 32).

Each class the issue names is here: rotating hoop (both regimes), elastic pendulum in Cartesian
coordinates, free hoop, moving support, accelerating car, a gauge term added, Penning trap, L4/L5,
coupled pendula, masses 1e6 and 1e-6, symmetric top from body rates, Yukawa force, asymmetric
heavy top, and more.  The expected values live in test_equilibria_unseen.py, derived by hand there
(or computed there independently with numpy/scipy), never taken from the engine.
"""

from __future__ import annotations

from app.scenes.types import Parameter, Particle, System


def p(name: str, value: float, low: float | None = 0.0, high: float | None = 1e9) -> Parameter:
    return Parameter(name, value, "", low, high)


G = p("g", 9.81)
MU = 0.01

# the heavy top's body rates from Euler angles (phi, theta, psi), z-x-z
W1 = "(phi_dot*sin(theta)*sin(psi) + theta_dot*cos(psi))"
W2 = "(phi_dot*sin(theta)*cos(psi) - theta_dot*sin(psi))"
W3 = "(phi_dot*cos(theta) + psi_dot)"


def hoop(omega: float) -> System:
    # bead on a hoop turning at omega about the vertical; phi from the top (the bottom is phi = pi)
    return System(
        coordinates=("phi",),
        parameters=(p("m", 1.0), p("R", 1.0), p("w", omega), G),
        particles=(Particle("m", ("R*sin(phi)*cos(w*t)", "R*sin(phi)*sin(w*t)", "R*cos(phi)")),),
        potential="m*g*R*cos(phi)",
    )


SYSTEMS: dict[str, System] = {
    "hoop-slow": hoop(2.0),
    "hoop-fast": hoop(5.0),
    "elastic-pendulum-cartesian": System(
        coordinates=("x", "y"),
        parameters=(p("m", 1.0), p("k", 20.0), p("l0", 1.0), G),
        kinetic="m*(x_dot**2 + y_dot**2)/2",
        potential="k*(sqrt(x**2 + y**2) - l0)**2/2 + m*g*y",
    ),
    "free-hoop": System(
        # a hoop (moment of inertia J about the vertical) turning freely, a bead on it; theta from the bottom
        coordinates=("theta", "phi"),
        # (the values: its steady motions at p_phi = 1 are theta = +-1.1632 with omega^2 = 50.9)
        parameters=(p("m", 0.2), p("R", 0.5), p("J", 0.1), G),
        kinetic="(J + m*R**2*sin(theta)**2)*phi_dot**2/2 + m*R**2*theta_dot**2/2",
        potential="-m*g*R*cos(theta)",
    ),
    "support-on-a-circle": System(
        # Landau §5 problem 3a: the support moves uniformly on a vertical circle
        coordinates=("phi",),
        parameters=(p("m", 1.0), p("l", 1.0), p("a", 0.3), p("gamma", 2.0), G),
        particles=(Particle("m", ("a*cos(gamma*t) + l*sin(phi)", "-a*sin(gamma*t) - l*cos(phi)", "0")),),
        potential="m*g*(-a*sin(gamma*t) - l*cos(phi))",
    ),
    "accelerating-car": System(
        coordinates=("theta",),
        parameters=(p("m", 1.0), p("l", 1.0), p("A", 3.0), G),
        particles=(Particle("m", ("A*t**2/2 + l*sin(theta)", "-l*cos(theta)", "0")),),
        potential="-m*g*l*cos(theta)",
    ),
    "oscillator-with-a-gauge-term": System(
        # L + d/dt(c x^2 t) = L + 2 c x x_dot t + c x^2
        coordinates=("x",),
        parameters=(p("m", 2.0), p("k", 8.0), p("c", 3.0)),
        lagrangian="m*x_dot**2/2 - k*x**2/2 + 2*c*x*x_dot*t + c*x**2",
    ),
    "penning-trap": System(
        coordinates=("x", "y", "z"),
        parameters=(p("B", 3.0), p("k", 1.0)),
        lagrangian="(x_dot**2 + y_dot**2 + z_dot**2)/2 + B*(x*y_dot - y*x_dot)/2 - k*(2*z**2 - x**2 - y**2)/4",
    ),
    "restricted-three-body": System(
        # rotating frame, unit separation and angular velocity; the primaries at -mu and 1 - mu
        coordinates=("x", "y"),
        parameters=(p("mu", MU, 0.0, 0.5),),
        lagrangian="(x_dot**2 + y_dot**2)/2 + x*y_dot - y*x_dot + (x**2 + y**2)/2"
        " + (1 - mu)/sqrt((x + mu)**2 + y**2) + mu/sqrt((x - 1 + mu)**2 + y**2)",
    ),
    "rotating-frame-oscillator": System(
        # an isotropic oscillator seen from a frame turning at W faster than its frequency
        coordinates=("x", "y"),
        parameters=(p("k", 1.0), p("W", 2.0)),
        lagrangian="(x_dot**2 + y_dot**2)/2 + W*(x*y_dot - y*x_dot) + W**2*(x**2 + y**2)/2 - k*(x**2 + y**2)/2",
    ),
    "coupled-pendula": System(
        coordinates=("a", "b"),
        parameters=(p("m", 1.0), p("l", 1.0), p("k", 2.0), G),
        particles=(
            Particle("m", ("l*sin(a)", "-l*cos(a)", "0")),
            Particle("m", ("2 + l*sin(b)", "-l*cos(b)", "0")),
        ),
        potential="-m*g*l*(cos(a) + cos(b)) + k*l**2*(sin(a) - sin(b))**2/2",
    ),
    "coupled-pendula-soft-spring": System(
        coordinates=("a", "b"),
        parameters=(p("m", 1.0), p("l", 1.0), p("k", 0.01), G),
        particles=(
            Particle("m", ("l*sin(a)", "-l*cos(a)", "0")),
            Particle("m", ("2 + l*sin(b)", "-l*cos(b)", "0")),
        ),
        potential="-m*g*l*(cos(a) + cos(b)) + k*l**2*(sin(a) - sin(b))**2/2",
    ),
    "double-pendulum-extreme-masses": System(
        coordinates=("a", "b"),
        parameters=(p("m1", 1e6), p("m2", 1e-6), p("l1", 1.0), p("l2", 0.5), G),
        particles=(
            Particle("m1", ("l1*sin(a)", "-l1*cos(a)", "0")),
            Particle("m2", ("l1*sin(a) + l2*sin(b)", "-l1*cos(a) - l2*cos(b)", "0")),
        ),
        potential="-g*(m1 + m2)*l1*cos(a) - g*m2*l2*cos(b)",
    ),
    "symmetric-top-body-rates": System(
        coordinates=("phi", "theta", "psi"),
        parameters=(p("I1", 1.0), p("I3", 0.5), p("M", 1.0), p("l", 0.2), G),
        kinetic=f"I1*({W1}**2 + {W2}**2)/2 + I3*{W3}**2/2",
        potential="M*g*l*cos(theta)",
    ),
    "yukawa": System(
        coordinates=("r", "theta"),
        parameters=(p("m", 1.0), p("k", 1.0), p("a", 2.0)),
        particles=(Particle("m", ("r*cos(theta)", "r*sin(theta)", "0")),),
        potential="-k*exp(-r/a)/r",
        nonnegative=("r",),
    ),
    "asymmetric-heavy-top": System(
        coordinates=("phi", "theta", "psi"),
        parameters=(p("I1", 1.0), p("I2", 2.0), p("I3", 3.0), p("M", 1.0), p("l", 0.2), G),
        kinetic=f"I1*{W1}**2/2 + I2*{W2}**2/2 + I3*{W3}**2/2",
        potential="M*g*l*cos(theta)",
    ),
    "negative-kinetic-energy": System(
        # L = U - T: the oscillator's equations with both signs flipped
        coordinates=("x",),
        parameters=(p("m", 2.0), p("k", 8.0)),
        lagrangian="-m*x_dot**2/2 + k*x**2/2",
    ),
    "indefinite-mass-matrix": System(
        coordinates=("x", "y"),
        parameters=(p("k", 4.0),),
        lagrangian="(x_dot**2 - y_dot**2)/2 - k*(x**2 - y**2)/2",
    ),
    "double-well": System(
        coordinates=("x",),
        parameters=(p("m", 1.0), p("a", 2.0), p("b", 3.0)),
        kinetic="m*x_dot**2/2",
        potential="a*x**4/4 - b*x**2/2",
    ),
    "many-roots": System(
        # U = -cos x + x^2/(2 c): a root of sin x + x/c = 0 in every other half period up to |x| ~ c
        coordinates=("x",),
        parameters=(p("m", 1.0), p("c", 20.0)),
        kinetic="m*x_dot**2/2",
        potential="-cos(x) + x**2/(2*c)",
    ),
    "rotating-rod-bead": System(
        coordinates=("r",),
        parameters=(p("m", 1.0), p("W", 1.5)),
        particles=(Particle("m", ("r*cos(W*t)", "r*sin(W*t)", "0")),),
        potential="0",
    ),
    "damped-oscillator": System(
        coordinates=("x",),
        parameters=(p("m", 1.0), p("k", 4.0), p("c", 0.5)),
        kinetic="m*x_dot**2/2",
        potential="k*x**2/2",
        forces={"x": "-c*x_dot"},
    ),
    "vertically-driven-pendulum": System(
        # Kapitza: the support moves as a cos(gamma t); theta = 0 and pi stay at rest, with time-varying coefficients
        coordinates=("theta",),
        parameters=(p("m", 1.0), p("l", 1.0), p("a", 0.1), p("gamma", 30.0), G),
        particles=(Particle("m", ("l*sin(theta)", "a*cos(gamma*t) - l*cos(theta)", "0")),),
        potential="m*g*(a*cos(gamma*t) - l*cos(theta))",
    ),
}
