"""Systems from outside the chapter, as an outside physicist would type them (issue 19).

Textbook and SymPy/PyDy-style examples in all three declaration forms (particles, T and U, L),
with generalized forces, moving constraints, velocity-linear terms and every allowed function
family.  Each comes with a start (q, q_dot) and a short run time; parameters carry units so the
scaling tests can rescale masses ("kg") and lengths ("m").
"""

from __future__ import annotations

from dataclasses import dataclass

from app.scenes.types import Parameter, Particle, System


def kg(name: str, value: float = 1.0) -> Parameter:
    return Parameter(name, value, "kg", 1e-3, 1e3)


def metre(name: str, value: float = 1.0) -> Parameter:
    return Parameter(name, value, "m", 1e-3, 1e3)


def other(name: str, value: float, unit: str = "") -> Parameter:
    return Parameter(name, value, unit, 0.0, 1e3)


G = Parameter("g", 9.81, "m/s²", 0.1, 100.0)


@dataclass(frozen=True)
class Unseen:
    system: System
    start: dict[str, tuple[float, float]]  # coordinate -> (q, q_dot) at t = 0
    t_end: float = 2.0


def planar(mass: str, x: str, y: str) -> Particle:
    return Particle(mass, (x, y, "0"))


UNSEEN: dict[str, Unseen] = {
    "double-pendulum": Unseen(
        System(
            coordinates=("a", "b"),
            parameters=(kg("m1"), kg("m2", 0.5), metre("l1"), metre("l2", 0.7), G),
            particles=(
                planar("m1", "l1*sin(a)", "-l1*cos(a)"),
                planar("m2", "l1*sin(a) + l2*sin(b)", "-l1*cos(a) - l2*cos(b)"),
            ),
            potential="-g*(m1 + m2)*l1*cos(a) - g*m2*l2*cos(b)",
        ),
        {"a": (1.0, 0.0), "b": (0.0, 0.5)},
    ),
    "triple-pendulum": Unseen(
        System(
            coordinates=("a", "b", "c"),
            parameters=(kg("m1"), kg("m2"), kg("m3"), metre("l1"), metre("l2"), metre("l3"), G),
            particles=(
                planar("m1", "l1*sin(a)", "-l1*cos(a)"),
                planar("m2", "l1*sin(a) + l2*sin(b)", "-l1*cos(a) - l2*cos(b)"),
                planar("m3", "l1*sin(a) + l2*sin(b) + l3*sin(c)", "-l1*cos(a) - l2*cos(b) - l3*cos(c)"),
            ),
            potential="-g*((m1 + m2 + m3)*l1*cos(a) + (m2 + m3)*l2*cos(b) + m3*l3*cos(c))",
        ),
        {"a": (0.5, 0.0), "b": (-0.3, 0.0), "c": (0.2, 0.1)},
        1.0,
    ),
    "cart-pole": Unseen(
        System(
            coordinates=("x", "theta"),
            parameters=(kg("M", 2.0), kg("m", 0.3), metre("l", 0.8), G),
            particles=(planar("M", "x", "0"), planar("m", "x + l*sin(theta)", "-l*cos(theta)")),
            potential="-m*g*l*cos(theta)",
        ),
        {"x": (0.0, 0.2), "theta": (0.4, 0.0)},
    ),
    "cart-pole-on-a-spring": Unseen(
        System(
            coordinates=("x", "theta"),
            parameters=(kg("M", 2.0), kg("m", 0.3), metre("l", 0.8), other("k", 5.0, "N/m"), G),
            particles=(planar("M", "x", "0"), planar("m", "x + l*sin(theta)", "-l*cos(theta)")),
            potential="k*x**2/2 - m*g*l*cos(theta)",
        ),
        {"x": (0.1, 0.0), "theta": (0.4, 0.0)},
    ),
    "spring-pendulum": Unseen(
        System(
            coordinates=("r", "theta"),
            parameters=(kg("m"), other("k", 20.0, "N/m"), metre("l0"), G),
            particles=(planar("m", "r*sin(theta)", "-r*cos(theta)"),),
            potential="k*(r - l0)**2/2 - m*g*r*cos(theta)",
            nonnegative=("r",),
        ),
        {"r": (1.2, 0.0), "theta": (0.6, 0.0)},
    ),
    "atwood-machine": Unseen(
        System(
            coordinates=("x",),
            parameters=(kg("m1", 1.5), kg("m2"), metre("l", 3.0), G),
            particles=(planar("m1", "0", "-x"), planar("m2", "1", "x - l")),
            potential="-m1*g*x + m2*g*(x - l)",
        ),
        {"x": (1.0, 0.0)},
    ),
    "double-atwood-machine": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(kg("m1", 3.0), kg("m2"), kg("m3", 1.5), metre("l1", 4.0), metre("l2", 2.0), G),
            particles=(
                planar("m1", "0", "-x"),
                planar("m2", "1", "-(l1 - x) - y"),
                planar("m3", "2", "-(l1 - x) - (l2 - y)"),
            ),
            potential="g*(-m1*x - m2*(l1 - x + y) - m3*(l1 - x + l2 - y))",
        ),
        {"x": (1.0, 0.0), "y": (1.0, 0.0)},
    ),
    "swinging-atwood-machine": Unseen(
        System(
            coordinates=("r", "theta"),
            parameters=(kg("M", 3.0), kg("m"), metre("l", 5.0), G),
            particles=(planar("m", "r*sin(theta)", "-r*cos(theta)"), planar("M", "-1", "r - l")),
            potential="-m*g*r*cos(theta) + M*g*(r - l)",
            nonnegative=("r",),
        ),
        {"r": (1.0, 0.0), "theta": (0.5, 0.0)},
    ),
    "bead-on-a-spinning-hoop": Unseen(
        System(
            coordinates=("theta",),
            parameters=(kg("m"), metre("R", 0.5), other("omega", 6.0, "rad/s"), G),
            particles=(Particle("m", ("R*sin(theta)*cos(omega*t)", "R*sin(theta)*sin(omega*t)", "-R*cos(theta)")),),
            potential="-m*g*R*cos(theta)",
        ),
        {"theta": (0.3, 0.0)},
    ),
    "charge-in-a-field-symmetric-gauge": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(kg("m"), other("c", 1.0, "C"), other("B", 2.0, "T")),
            kinetic="m*(x_dot**2 + y_dot**2)/2 + c*B*(x*y_dot - y*x_dot)/2",
            potential="0",
        ),
        {"x": (0.0, 1.0), "y": (0.0, 0.0)},
    ),
    "charge-in-a-field-landau-gauge-with-a-trap": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(kg("m"), other("c", 1.0, "C"), other("B", 2.0, "T"), other("k", 3.0, "N/m")),
            kinetic="m*(x_dot**2 + y_dot**2)/2 + c*B*x*y_dot",
            potential="k*(x**2 + y**2)/2",
        ),
        {"x": (0.5, 0.0), "y": (0.0, 0.4)},
    ),
    "charge-in-a-field-lorentz-force": Unseen(
        System(
            coordinates=("x", "y", "z"),
            parameters=(kg("m"), other("c", 1.0, "C"), other("B", 2.0, "T"), other("Ez", 0.5, "V/m")),
            kinetic="m*(x_dot**2 + y_dot**2 + z_dot**2)/2",
            potential="-c*Ez*z",
            forces={"x": "c*B*y_dot", "y": "-c*B*x_dot"},
        ),
        {"x": (0.0, 1.0), "y": (0.0, 0.0), "z": (0.0, 0.1)},
    ),
    "kepler": Unseen(
        System(
            coordinates=("r", "phi"),
            parameters=(kg("m"), other("k", 1.0, "m³/s²")),
            particles=(planar("m", "r*cos(phi)", "r*sin(phi)"),),
            potential="-k*m/r",
            nonnegative=("r",),
        ),
        {"r": (1.0, 0.0), "phi": (0.0, 1.2)},
        5.0,
    ),
    # the same orbit in Cartesian coordinates: H = p²/2m + U(q) separates, so every integrator applies
    "kepler-cartesian": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(kg("m"), other("k", 1.0, "m³/s²")),
            particles=(planar("m", "x", "y"),),
            potential="-k*m/sqrt(x**2 + y**2)",
        ),
        {"x": (1.0, 0.0), "y": (0.0, 1.2)},
        5.0,
    ),
    # pivot driven vertically as a cos(omega t); the total derivative d/dt(m a omega l sin(omega t) cos(theta))
    # and the terms in t alone are dropped from L
    "kapitza-pendulum-as-L": Unseen(
        System(
            coordinates=("theta",),
            parameters=(kg("m"), metre("l"), metre("a", 0.1), other("omega", 80.0, "rad/s"), G),
            lagrangian="m*l**2*theta_dot**2/2 + m*l*(g - a*omega**2*cos(omega*t))*cos(theta)",
        ),
        {"theta": (2.8, 0.0)},
        1.0,
    ),
    "kapitza-pendulum-as-particle": Unseen(
        System(
            coordinates=("theta",),
            parameters=(kg("m"), metre("l"), metre("a", 0.1), other("omega", 80.0, "rad/s"), G),
            particles=(planar("m", "l*sin(theta)", "a*cos(omega*t) - l*cos(theta)"),),
            potential="m*g*(a*cos(omega*t) - l*cos(theta))",
        ),
        {"theta": (2.8, 0.0)},
        1.0,
    ),
    "pendulum-with-a-shaken-support": Unseen(
        System(
            coordinates=("theta",),
            parameters=(kg("m"), metre("l"), metre("a", 0.2), other("omega", 3.0, "rad/s"), G),
            particles=(planar("m", "a*cos(omega*t) + l*sin(theta)", "-l*cos(theta)"),),
            potential="-m*g*l*cos(theta)",
        ),
        {"theta": (0.2, 0.0)},
    ),
    "damped-driven-oscillator": Unseen(
        System(
            coordinates=("x",),
            parameters=(
                kg("m"),
                other("k", 4.0, "N/m"),
                other("b", 0.3, "kg/s"),
                other("F", 1.0, "N"),
                other("w", 1.7, "1/s"),
            ),
            kinetic="m*x_dot**2/2",
            potential="k*x**2/2",
            forces={"x": "F*cos(w*t) - b*x_dot"},
        ),
        {"x": (0.5, 0.0)},
        4.0,
    ),
    "driven-duffing-oscillator": Unseen(
        System(
            coordinates=("x",),
            parameters=(
                kg("m"),
                other("k", -1.0, "N/m"),
                other("K", 1.0, "N/m³"),
                other("b", 0.3, "kg/s"),
                other("F", 0.5, "N"),
                other("w", 1.2, "1/s"),
            ),
            kinetic="m*x_dot**2/2",
            potential="k*x**2/2 + K*x**4/4",
            forces={"x": "F*cos(w*t) - b*x_dot"},
        ),
        {"x": (1.0, 0.0)},
        4.0,
    ),
    "coupled-oscillators": Unseen(
        System(
            coordinates=("x1", "x2"),
            parameters=(kg("m1"), kg("m2", 2.0), other("k", 3.0, "N/m"), other("kc", 0.5, "N/m")),
            kinetic="m1*x1_dot**2/2 + m2*x2_dot**2/2",
            potential="k*x1**2/2 + kc*(x2 - x1)**2/2 + k*x2**2/2",
        ),
        {"x1": (0.3, 0.0), "x2": (0.0, 0.0)},
        4.0,
    ),
    "particle-on-a-cone": Unseen(
        System(
            coordinates=("r", "phi"),
            parameters=(kg("m"), other("alpha", 0.6, "rad"), G),
            particles=(Particle("m", ("r*cos(phi)", "r*sin(phi)", "r*cot(alpha)")),),
            potential="m*g*r*cot(alpha)",
            nonnegative=("r",),
        ),
        {"r": (1.0, 0.0), "phi": (0.0, 3.0)},
    ),
    "heavy-symmetric-top": Unseen(
        System(
            coordinates=("theta", "phi", "psi"),
            parameters=(other("I1", 0.8, "kg·m²"), other("I3", 0.3, "kg·m²"), kg("M"), metre("l", 0.4), G),
            kinetic="I1*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2 + I3*(psi_dot + phi_dot*cos(theta))**2/2",
            potential="M*g*l*cos(theta)",
        ),
        {"theta": (0.7, 0.0), "phi": (0.0, 1.0), "psi": (0.0, 20.0)},
    ),
    "cylinder-rolling-down-an-incline": Unseen(
        System(
            coordinates=("x",),
            parameters=(kg("m"), metre("R", 0.2), other("alpha", 0.4, "rad"), G),
            kinetic="m*x_dot**2/2 + (m*R**2/2)*(x_dot/R)**2/2",
            potential="-m*g*x*sin(alpha)",
        ),
        {"x": (0.0, 0.5)},
    ),
    "cylinder-rolling-inside-a-cylinder": Unseen(
        System(
            coordinates=("theta",),
            parameters=(kg("m"), metre("R", 1.0), metre("a", 0.2), G),
            kinetic="3*m*(R - a)**2*theta_dot**2/4",
            potential="-m*g*(R - a)*cos(theta)",
        ),
        {"theta": (0.9, 0.0)},
    ),
    "particle-in-a-rotating-frame": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(kg("m"), other("Omega", 1.0, "rad/s"), other("k", 4.0, "N/m")),
            kinetic="m*(x_dot**2 + y_dot**2)/2 + m*Omega*(x*y_dot - y*x_dot) + m*Omega**2*(x**2 + y**2)/2",
            potential="k*(x**2 + y**2)/2",
        ),
        {"x": (0.5, 0.0), "y": (0.0, 0.2)},
    ),
    "henon-heiles": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(other("lam", 1.0, "1/m"),),
            kinetic="(x_dot**2 + y_dot**2)/2",
            potential="(x**2 + y**2)/2 + lam*(x**2*y - y**3/3)",
        ),
        {"x": (0.1, 0.3), "y": (0.2, 0.1)},
        4.0,
    ),
    "oscillator-in-spherical-coordinates": Unseen(
        System(
            coordinates=("r", "theta", "phi"),
            parameters=(kg("m"), other("k", 2.0, "N/m")),
            particles=(Particle("m", ("r*sin(theta)*cos(phi)", "r*sin(theta)*sin(phi)", "r*cos(theta)")),),
            potential="k*r**2/2",
            nonnegative=("r",),
        ),
        {"r": (1.0, 0.1), "theta": (1.0, 0.3), "phi": (0.0, 0.8)},
    ),
    "bead-in-a-paraboloid": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(kg("m"), other("c", 0.5, "1/m"), G),
            particles=(Particle("m", ("x", "y", "c*(x**2 + y**2)")),),
            potential="m*g*c*(x**2 + y**2)",
        ),
        {"x": (0.5, 0.0), "y": (0.0, 0.8)},
    ),
    "physical-pendulum-rod": Unseen(
        System(
            coordinates=("theta",),
            parameters=(kg("m"), metre("l"), G),
            kinetic="m*l**2*theta_dot**2/6",
            potential="-m*g*l*cos(theta)/2",
        ),
        {"theta": (1.5, 0.0)},
    ),
    "anisotropic-trap-with-atan2": Unseen(
        System(
            coordinates=("x", "y"),
            parameters=(kg("m"), other("k", 2.0, "N/m"), other("e", 0.3, "")),
            kinetic="m*(x_dot**2 + y_dot**2)/2",
            potential="k*(x**2 + y**2)*(1 + e*sin(atan2(y, x))**2)/2",
        ),
        {"x": (0.8, 0.0), "y": (0.3, 0.6)},
    ),
    "bead-on-a-secant-wire": Unseen(
        System(
            coordinates=("u",),
            parameters=(kg("m"), metre("h", 0.5), G),
            particles=(planar("m", "u", "h*sec(u)"),),
            potential="m*g*h*sec(u)",
        ),
        {"u": (0.6, 0.0)},
    ),
}
