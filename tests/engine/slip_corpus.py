"""Realistic slips: what second-year students write, each with the mistake a teacher would name.

Written before the code that names them (issue 41), from the kinds of slip students make rather than
from the engine's own mistake families.  Each slip: (system, step, coordinate, answer, named) where
``named`` is a regular expression, matched case-insensitively against the mistake's key, name and
hint together, that a right naming must contain.  ``CORRECT`` lists correct answers in unusual forms
(trigonometric identities, other zeros of U, equations scaled through): every one must be accepted.

The systems beyond the twelve scenes are ``tests.engine.check_corpus.USER_SYSTEMS`` (a cart with a
pendulum, given as particles; a bead on a spun rod, given by L alone) and two typed with T and U
here: a uniform rod pivoted at one end (a physical pendulum) and a disc rolling down an incline on a
spring.
"""

from __future__ import annotations

from tests.engine.check_corpus import CART_PENDULUM, SPRING_ROD

# A uniform rod of mass m and length l pivoted at one end: I about the pivot m l²/3, centre at l/2.
ROD_PENDULUM = {
    "coordinates": ["theta"],
    "parameters": [
        {"name": "m", "value": 1.0, "min": 0.1, "unit": "kg"},
        {"name": "l", "value": 1.0, "min": 0.1, "unit": "m"},
        {"name": "g", "value": 9.81, "min": 0.1, "unit": "m/s²"},
    ],
    "kinetic": "m*l**2*theta_dot**2/6",
    "potential": "-m*g*l*cos(theta)/2",
}

# A uniform disc (mass M, radius R) rolling without slipping down an incline of angle alpha, held by a
# spring k from the top: x along the incline, downward.  T = ½ M ẋ² + ½ (½ M R²)(ẋ/R)².
ROLLING_DISC = {
    "coordinates": ["x"],
    "parameters": [
        {"name": "M", "value": 1.0, "min": 0.1, "unit": "kg"},
        {"name": "R", "value": 0.5, "min": 0.1, "unit": "m"},
        {"name": "k", "value": 10.0, "min": 0.1, "unit": "N/m"},
        {"name": "g", "value": 9.81, "min": 0.1, "unit": "m/s²"},
        {"name": "alpha", "value": 0.5, "min": 0.1, "max": 1.5, "unit": "rad"},
    ],
    "kinetic": "3*M*x_dot**2/4",
    "potential": "k*x**2/2 - M*g*x*sin(alpha)",
}

# The elastic pendulum a student typed in the playground (review student-d): a particle on a spring of natural
# length l swinging in a vertical plane.
ELASTIC_PENDULUM = {
    "coordinates": ["r", "phi"],
    "parameters": [
        {"name": "m", "value": 1.0, "min": 0.1, "unit": "kg"},
        {"name": "g", "value": 9.81, "min": 0.1, "unit": "m/s²"},
        {"name": "k", "value": 10.0, "min": 0.1, "unit": "N/m"},
        {"name": "l", "value": 1.0, "min": 0.1, "unit": "m"},
    ],
    "particles": [{"mass": "m", "position": ["r*sin(phi)", "-r*cos(phi)", "0"], "label": "bob"}],
    "potential": "-m*g*r*cos(phi) + k*(r - l)**2/2",
}

UNITS = {
    "cart-pendulum": {"M": "kg", "m": "kg", "l": "m", "k": "N/m", "g": "m/s²", "c": "kg/s"},
    "spring-rod": {"m": "kg", "k": "N/m", "a": "m", "w": "rad/s"},
}


def _with_units(spec: dict, units: dict[str, str]) -> dict:
    return {**spec, "parameters": [{**p, "unit": units[p["name"]]} for p in spec["parameters"]]}


# The cart with a pendulum a student typed in the playground (review student-e): no spring, no drag.
FREE_CART = {
    "coordinates": ["X", "theta"],
    "parameters": [
        {"name": "M", "value": 2.0, "min": 0.1, "unit": "kg"},
        {"name": "m", "value": 1.0, "min": 0.1, "unit": "kg"},
        {"name": "l", "value": 1.0, "min": 0.1, "unit": "m"},
        {"name": "g", "value": 9.81, "min": 0.1, "unit": "m/s²"},
    ],
    "particles": [
        {"mass": "M", "position": ["X", "0", "0"], "label": "cart"},
        {"mass": "m", "position": ["X + l*sin(theta)", "0", "-l*cos(theta)"], "label": "bob"},
    ],
    "potential": "-m*g*l*cos(theta)",
}

SYSTEMS = {
    "cart-pendulum": _with_units(CART_PENDULUM, UNITS["cart-pendulum"]),
    "spring-rod": _with_units(SPRING_ROD, UNITS["spring-rod"]),
    "rod-pendulum": ROD_PENDULUM,
    "rolling-disc": ROLLING_DISC,
    "elastic-pendulum": ELASTIC_PENDULUM,
    "free-cart": FREE_CART,
}

TWICE = r"twice|doubled"
SWAP = r"sin.*cos|cos.*sin|swapp"
SIGN = r"sign|revers"
UNITS_WORDS = r"unit|dimension"
HALF = r"½|half"
SMALL = r"small|approximat"

SLIPS = [
    # ---- the simple pendulum: T = ½ m R² θ̇², U = m g R (1 − cos θ)
    ("simple-pendulum", "equation", "theta", "m*R**2*theta_ddot + 2*m*g*R*sin(theta)", TWICE),
    ("simple-pendulum", "equation", "theta", "theta_ddot + 2*g*sin(theta)/R", TWICE),
    ("simple-pendulum", "kinetic", None, "R**2*theta_dot**2/2", r"divid|mass|\bm\b"),
    ("simple-pendulum", "kinetic", None, "m*R*theta_dot**2/2", UNITS_WORDS + r"|R²"),
    ("simple-pendulum", "potential", None, "m*g*R*sin(theta)", SWAP),
    # d(−cos θ)/dθ taken as cos θ, with T and U right: the derivative is named, not the positions (review 41, 9)
    ("simple-pendulum", "equation", "theta", "m*R**2*theta_ddot + m*g*R*cos(theta)", r"derivative of cos θ is −sin θ"),
    ("simple-pendulum", "acceleration", "theta", "-g*cos(theta)/R", r"derivative of cos θ is −sin θ"),
    ("simple-pendulum", "omega_squared", None, "(m + g)/R", UNITS_WORDS),
    ("simple-pendulum", "omega_squared", None, "R/g", UNITS_WORDS + r"|upside|invert"),
    ("simple-pendulum", "equation", "theta", "m*R**2*theta_ddot + m*g*sin(theta)", UNITS_WORDS),
    ("simple-pendulum", "equation", "theta", "m*R**2*theta_ddot - m*g*R*sin(theta)", SIGN),
    ("simple-pendulum", "acceleration", "theta", "-g*theta/R", SMALL),
    # ---- the damped pendulum: the same with Q = −b θ̇
    ("damped-pendulum", "equation", "theta", "theta_ddot + g*sin(theta)/R + b*theta_dot", UNITS_WORDS),
    ("damped-pendulum", "equation", "theta", "m*R**2*theta_ddot + m*g*R*theta + b*theta_dot", SMALL),
    ("damped-pendulum", "equation", "theta", "m*R**2*theta_ddot + m*g*R*sin(theta) + 2*b*theta_dot", TWICE),
    ("damped-pendulum", "acceleration", "theta", "-g*sin(theta)/R - b*theta_dot/m", UNITS_WORDS),
    ("damped-pendulum", "kinetic", None, "m*R**2*theta_dot**2", HALF),
    # ---- the bead on a helix: x = R cos(α z), y = R sin(α z)
    ("helix-bead", "kinetic", None, "m*(1 + R*alpha)*z_dot**2/2", r"R² ?α²|square|chain"),
    ("helix-bead", "kinetic", None, "m*(1 + alpha**2)*z_dot**2/2", UNITS_WORDS),
    ("helix-bead", "kinetic", None, "m*(1 + R**2)*z_dot**2/2", UNITS_WORDS),
    ("helix-bead", "equation", "z", "m*(1 + R**2*alpha**2)*z_ddot - m*g", SIGN),
    ("helix-bead", "acceleration", "z", "-g", r"circle|around|horizontal|R α ż|xy|x and y"),
    ("helix-bead", "potential", None, "m*g*alpha*z", UNITS_WORDS),
    # ---- the block on a fixed incline: X along the slope
    ("incline-block", "equation", "X", "m*X_ddot + m*g*cos(alpha)", SWAP),
    ("incline-block", "equation", "X", "m*X_ddot + 2*m*g*sin(alpha)", TWICE),
    ("incline-block", "potential", None, "m*g*X*cos(alpha)", SWAP),
    ("incline-block", "potential", None, "m*g*X", r"sin ?\(?α"),
    ("incline-block", "acceleration", "X", "-g", r"sin ?\(?α"),
    ("incline-block", "equation", "X", "X_ddot + m*g*sin(alpha)", UNITS_WORDS),
    # ---- the puck on a table held by a spring through a hole
    ("tabletop-spring", "equation", "r", "m*r_ddot + k*r + m*r*theta_dot**2", SIGN + r"|centrifugal"),
    ("tabletop-spring", "equation", "r", "m*r_ddot + k*r - m*r**2*theta_dot**2", UNITS_WORDS),
    ("tabletop-spring", "omega_squared", None, "k/m", r"centrifugal|U_eff|angular momentum|p_θ"),
    ("tabletop-spring", "kinetic", None, "m*(r_dot**2 + r*theta_dot**2)/2", UNITS_WORDS),
    ("tabletop-spring", "momentum", "theta", "m*r*theta_dot", r"factor|\br\b"),
    ("tabletop-spring", "equation", "theta", "m*r**2*theta_ddot + m*r*r_dot*theta_dot", HALF + r"|chain"),
    ("tabletop-spring", "potential", None, "k*r**2", HALF),
    # ---- the spherical pendulum: T = ½ m R² (θ̇² + sin²θ φ̇²), U = m g R cos θ
    ("spherical-pendulum", "kinetic", None, "m*R**2*(theta_dot**2 + phi_dot**2)/2", r"sin²|sin\(θ\)"),
    ("spherical-pendulum", "kinetic", None, "m*R**2*(theta_dot**2 + cos(theta)**2*phi_dot**2)/2", SWAP),
    # student-h 158: sin θ where T needs sin²θ, named with the rate it multiplies (φ̇)
    ("spherical-pendulum", "kinetic", None, "m*R**2*(theta_dot**2 + phi_dot**2*sin(theta))/2",
     r"sin θ where T needs its square sin² θ.*sin θ·φ̇"),
    (
        "spherical-pendulum",
        "equation",
        "theta",
        "m*R**2*theta_ddot - m*R**2*sin(theta)*cos(theta)*phi_dot**2 + m*g*R*sin(theta)",
        SIGN,
    ),
    (
        "spherical-pendulum",
        "equation",
        "phi",
        "m*R**2*sin(theta)**2*phi_ddot + m*R**2*sin(theta)*cos(theta)*theta_dot*phi_dot",
        HALF + r"|chain",
    ),
    ("spherical-pendulum", "momentum", "phi", "m*R**2*phi_dot", r"sin²|factor"),
    ("spherical-pendulum", "equation", "theta", "m*R**2*theta_ddot - m*g*R*sin(theta)", r"φ̇|sin²|T depends"),
    ("spherical-pendulum", "potential", None, "m*g*R*sin(theta)", SWAP),
    # ---- two bodies on a rail joined by a spring of natural length l0
    ("rail-two-body", "potential", None, "k*(x2 - x1 + l0)**2/2", r"natural length|l₀"),
    ("rail-two-body", "equation", "x1", "m1*x1_ddot + k*(x2 - x1 - l0)", SIGN),
    ("rail-two-body", "potential", None, "k*(x1 + x2 - l0)**2/2", r"stretch|x₂ − x₁|x₁ \+ x₂"),
    ("rail-two-body", "kinetic", None, "m1*x1_dot**2 + m2*x2_dot**2", HALF),
    ("rail-two-body", "equation", "x2", "m2*x2_ddot + k*(x2 - x1)", r"natural length|l₀"),
    ("rail-two-body", "potential", None, "k*(x2 - x1 - l0)", r"square|" + UNITS_WORDS),
    # ---- the movable pulley: it moves half as far as the masses
    (
        "pulley",
        "kinetic",
        None,
        "M*(y1_dot + y2_dot)**2/2 + m1*y1_dot**2/2 + m2*y2_dot**2/2",
        r"half|½|pulley|middle",
    ),
    ("pulley", "potential", None, "m1*g*y1 + m2*g*y2 - M*g*(y1 + y2)", r"half|½|pulley|middle"),
    # student-i 1: the pulley's M term doubled in T was called "the spring term" (the pulley has no spring)
    ("pulley", "kinetic", None, "m1*y1_dot**2/2 + m2*y2_dot**2/2 + M*(y1_dot + y2_dot)**2/4",
     r"the M terms, M \(ẏ₁ \+ ẏ₂\)²/4, twice"),
    # student-i 2: the sign of U in h explained by the centrifugal term's reason; student-i 6: ω for Ω
    ("rotating-parabola", "hamiltonian", None,
     "m*(1 + 4*alpha**2*rho**2)*rho_dot**2/2 - m*omega**2*rho**2/2 - m*g*alpha*rho**2",
     r"U enters h = T₂ − T₀ \+ U with its own sign"),
    ("rotating-parabola", "omega_squared", None, "sqrt(2*g*alpha - omega**2)", r"Ω in place of Ω²"),
    # student-h 60: the middle mass's energy left out was named "the gravitational energy in y₁ and y₂"
    ("pulley", "potential", None, "m1*g*y1 + m2*g*y2", r"gravitational energy of the middle mass"),
    ("pulley", "equation", "y1", "m1*y1_ddot + g*m1 - M*g/2", r"middle|pulley|\bM\b"),
    (
        "pulley",
        "kinetic",
        None,
        "M*(y1_dot**2 + y2_dot**2)/8 + m1*y1_dot**2/2 + m2*y2_dot**2/2",
        r"cross|ẏ₁ ẏ₂|product",
    ),
    # ---- the block on a movable wedge
    ("movable-incline", "kinetic", None, "M*X_dot**2/2 + m*D_dot**2/2", r"wedge|Ẋ"),
    (
        "movable-incline",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + D_dot**2 + 2*X_dot*D_dot*sin(alpha))/2",
        SWAP,
    ),
    ("movable-incline", "equation", "D", "m*D_ddot - m*g*sin(alpha)", r"Ẍ|Ẋ|wedge"),
    ("movable-incline", "equation", "X", "(M + m)*X_ddot", r"D̈|block"),
    ("movable-incline", "momentum", "X", "M*X_dot + m*X_dot", r"Ḋ"),
    ("movable-incline", "equation", "D", "m*D_ddot + m*X_ddot*cos(alpha) - m*g*cos(alpha)", SWAP),
    # ---- the bead on a spinning parabola z = α ρ²
    ("rotating-parabola", "omega_squared", None, "2*alpha*g", r"centrifugal|U_eff|ω²|rotation"),
    ("rotating-parabola", "omega_squared", None, "2*alpha*g + omega**2", SIGN + r"|centrifugal"),
    ("rotating-parabola", "equation", "rho", "m*rho_ddot + 2*alpha*g*m*rho - m*omega**2*rho", r"ż|vertical|height|z"),
    (
        "rotating-parabola",
        "kinetic",
        None,
        "m*(rho_dot**2*(1 + 2*alpha*rho) + omega**2*rho**2)/2",
        r"square|4 ?α² ?ρ²|chain|ż",
    ),
    (
        "rotating-parabola",
        "equation",
        "rho",
        "m*(1 + 4*alpha**2*rho**2)*rho_ddot + 2*alpha*g*m*rho - m*omega**2*rho",
        r"chain|ρ̇²|along the motion",
    ),
    # ---- two masses between three springs
    (
        "coupled-oscillators",
        "potential",
        None,
        "k*(x1**2 + x2**2)/2 + kappa*(x1 + x2)**2/2",
        r"stretch|x₂ − x₁|x₁ \+ x₂",
    ),
    ("coupled-oscillators", "equation", "x1", "m*x1_ddot + k*x1 + kappa*(x2 - x1)", SIGN),
    ("coupled-oscillators", "equation", "x1", "m*x1_ddot + (k + kappa)*x1", r"κ|x₂|coupling"),
    ("coupled-oscillators", "kinetic", None, "m*(x1_dot**2 + x2_dot**2)", HALF),
    ("coupled-oscillators", "potential", None, "k*(x1**2 + x2**2)/2 + kappa*(x2 - x1)/2", r"square|" + UNITS_WORDS),
    # student-h 131: the square of the sum of the velocities, where each mass has its own ½ m v²
    ("coupled-oscillators", "kinetic", None, "m*(x1_dot + x2_dot)**2/2", r"cross term m ẋ₁ ẋ₂ added, which the correct T"),
    # student-i 3: every spring's ½ lost at once got the step's rule
    ("coupled-oscillators", "potential", None, "k*x1**2 + k*x2**2 + kappa*(x2 - x1)**2",
     r"½ of ½ k × stretch² left out of every spring"),
    # student-h 126: the coupling spring left out was named "the spring energy in x₁ and x₂"
    ("coupled-oscillators", "potential", None, "k*x1**2/2 + k*x2**2/2", r"energy of the spring κ"),
    # ---- the double pendulum
    (
        "double-pendulum",
        "kinetic",
        None,
        "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2"
        " + 2*m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2)",
        r"cross|doubled|twice",
    ),
    (
        "double-pendulum",
        "kinetic",
        None,
        "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2"
        " + m2*l1*l2*theta1_dot*theta2_dot*sin(theta1 - theta2)",
        SWAP,
    ),
    (
        "double-pendulum",
        "kinetic",
        None,
        "m1*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2 + m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2)",
        r"m₂|m₁ \+ m₂|lower",
    ),
    ("double-pendulum", "potential", None, "-m1*g*l1*cos(theta1) - m2*g*l2*cos(theta2)", r"m₂|m₁ \+ m₂|lower"),
    ("double-pendulum", "potential", None, "-(m1 + m2)*g*l1*sin(theta1) - m2*g*l2*sin(theta2)", SWAP),
    (
        "double-pendulum",
        "equation",
        "theta1",
        "(m1 + m2)*l1**2*theta1_ddot + m2*l1*l2*cos(theta1 - theta2)*theta2_ddot"
        " + m2*l1*l2*sin(theta1 - theta2)*theta2_dot**2 + m1*g*l1*sin(theta1)",
        r"m₂|m₁ \+ m₂|lower",
    ),
    (
        "double-pendulum",
        "equation",
        "theta2",
        "m2*l2**2*theta2_ddot + m2*l1*l2*theta1_ddot + m2*g*l2*theta2",
        SMALL,
    ),
    # ---- a cart on a spring with a pendulum and drag (particles)
    (
        "cart-pendulum",
        "kinetic",
        None,
        "(M + m)*x_dot**2/2 + m*l**2*phi_dot**2/2 + m*l*sin(phi)*x_dot*phi_dot",
        SWAP,
    ),
    (
        "cart-pendulum",
        "equation",
        "x",
        "(M + m)*x_ddot + m*l*cos(phi)*phi_ddot - m*l*sin(phi)*phi_dot**2 + k*x - c*x_dot",
        SIGN,
    ),
    ("cart-pendulum", "equation", "phi", "m*l**2*phi_ddot + m*l*cos(phi)*x_ddot + m*g*sin(phi)", UNITS_WORDS),
    (
        "cart-pendulum",
        "kinetic",
        None,
        "M*x_dot**2/2 + m*l**2*phi_dot**2/2 + m*l*cos(phi)*x_dot*phi_dot",
        r"ẋ²|M \+ m|bob",
    ),
    ("cart-pendulum", "potential", None, "k*x**2/2 + m*g*l*cos(phi)", SIGN),
    # ---- a bead on a spun rod with a spring (L alone)
    ("spring-rod", "omega_squared", None, "k/m", r"centrifugal|w|rotation|U_eff"),
    ("spring-rod", "omega_squared", None, "k/m + w**2", SIGN + r"|centrifugal"),
    ("spring-rod", "equation", "r", "m*r_ddot + k*(r - a)", r"w|centrifugal|∂L/∂r"),
    ("spring-rod", "equation", "r", "m*r_ddot - m*w**2*r + k*(r + a)", r"natural length|\ba\b"),
    ("spring-rod", "hamiltonian", None, "m*(r_dot**2 + w**2*r**2)/2 + k*(r - a)**2/2", r"h_is_e|energy|\bE\b"),
    # ---- a rod pivoted at one end (T and U typed)
    ("rod-pendulum", "kinetic", None, "m*l**2*theta_dot**2/2", r"point mass|moment of inertia|rod"),
    ("rod-pendulum", "kinetic", None, "m*l**2*theta_dot**2/24", r"centre|pivot|axis"),
    ("rod-pendulum", "potential", None, "-m*g*l*cos(theta)", r"l/2|centre|half"),
    ("rod-pendulum", "equation", "theta", "m*l**2*theta_ddot/3 + m*g*l*sin(theta)", r"l/2|centre|half"),
    ("rod-pendulum", "omega_squared", None, "g/l", r"point mass|rod|moment of inertia|centre"),
    ("rod-pendulum", "kinetic", None, "m*(l/2)**2*theta_dot**2/2", r"spin|moment of inertia|centre"),
    ("rod-pendulum", "equation", "theta", "m*l**2*theta_ddot/12 + m*g*l*sin(theta)/2", r"centre|pivot|axis"),
    ("rod-pendulum", "kinetic", None, "m*l**2*theta_dot**2/12", r"centre|pivot|axis|½|half"),
    # the same rod as a scene, declared as a rigid body (issue 42): the same slips named the same way
    ("physical-pendulum", "kinetic", None, "M*l**2*theta_dot**2/2", r"point mass|moment of inertia|rod"),
    ("physical-pendulum", "kinetic", None, "M*l**2*theta_dot**2/24", r"centre|pivot|axis"),
    ("physical-pendulum", "kinetic", None, "M*(l/2)**2*theta_dot**2/2", r"spin|moment of inertia|centre"),
    ("physical-pendulum", "potential", None, "-M*g*l*cos(theta)", r"l/2|centre|half"),
    ("physical-pendulum", "equation", "theta", "M*l**2*theta_ddot/3 + M*g*l*sin(theta)", r"l/2|centre|half"),
    ("physical-pendulum", "equation", "theta", "M*l**2*theta_ddot/12 + M*g*l*sin(theta)/2", r"centre|pivot|axis"),
    ("physical-pendulum", "omega_squared", None, "g/l", r"point mass|rod|moment of inertia|centre"),
    # an Atwood machine on a disc pulley (issue 42): the pulley's turning forgotten, taken as a ring's (or its whole
    # mass as moving with the string), its centre taken to move; one mass's U of the wrong sign
    ("massive-pulley", "kinetic", None, "(m1 + m2)*z_dot**2/2", r"pulley's turning energy ½ I \(ż/R\)² left out"),
    ("massive-pulley", "kinetic", None, "(m1 + m2 + M)*z_dot**2/2", r"pulley.*ring \(I = M R²\).*moved with the string"),
    ("massive-pulley", "kinetic", None, "(m1 + m2 + M/2)*z_dot**2/2 + M*z_dot**2/2", r"pulley's centre.*fixed axle"),
    ("massive-pulley", "potential", None, "-(m1 + m2)*g*z", r"sign of your term −m₂ g z"),
    ("massive-pulley", "potential", None, "(m1 + m2)*g*z", r"sign of your term m₁ g z"),
    ("massive-pulley", "equation", "z", "(m1 + m2)*z_ddot - (m1 - m2)*g", r"pulley's turning energy .* left out"),
    ("massive-pulley", "equation", "z", "(m1 + m2 + M)*z_ddot - (m1 - m2)*g", r"pulley.*ring"),
    ("massive-pulley", "acceleration", "z", "(m1 - m2)*g/(m1 + m2)", r"pulley's turning energy .* left out"),
    ("massive-pulley", "acceleration", "z", "(m1 - m2)*g/(m1 + m2 + M)", r"pulley.*ring"),
    ("massive-pulley", "momentum", "z", "(m1 + m2)*z_dot", r"pulley's turning energy .* left out"),
    # ---- a disc rolling on an incline, on a spring (T and U typed)
    ("rolling-disc", "kinetic", None, "M*x_dot**2/2", r"spin|roll|rotation|moment of inertia"),
    ("rolling-disc", "kinetic", None, "M*x_dot**2/2 + M*R**2*x_dot**2/4", UNITS_WORDS),
    ("rolling-disc", "kinetic", None, "M*x_dot**2", r"ring|disc|moment of inertia"),
    ("rolling-disc", "omega_squared", None, "k/M", r"spin|roll|rotation|moment of inertia|effective mass"),
    ("rolling-disc", "equation", "x", "3*M*x_ddot/2 + k*x + M*g*sin(alpha)", SIGN),
    ("rolling-disc", "potential", None, "k*x**2/2 - M*g*x*cos(alpha)", SWAP),
    # ---- an answer that is another coordinate's (review 41, 15): named as that, with the velocity used
    (
        "double-pendulum",
        "momentum",
        "theta2",
        "(m1 + m2)*l1**2*theta1_dot + m2*l1*l2*theta2_dot*cos(theta1 - theta2)",
        r"conjugate to θ₁.*θ̇₁",
    ),
    ("movable-incline", "momentum", "D", "(M + m)*X_dot + m*D_dot*cos(alpha)", r"conjugate to X.*Ẋ"),
    ("cart-pendulum", "momentum", "x", "m*l**2*phi_dot + m*l*x_dot*cos(phi)", r"conjugate to φ.*φ̇"),
    # ---- the answer of a limit (review 41, 11): a body infinitely heavy, as if held still
    ("movable-incline", "acceleration", "D", "g*sin(alpha)", r"wedge.*held still|M → ∞"),
    ("cart-pendulum", "acceleration", "phi", "-g*sin(phi)/l", r"cart.*held still|M → ∞"),
    # the upper bob swinging as a simple pendulum: the lower bob's pull left out, as if it had no mass
    ("double-pendulum", "acceleration", "theta1", "-g*sin(theta1)/l1", r"lower bob.*no mass|m₂ → 0"),
    # ---- a second-year student's practice session (review student-d): each named by its cause
    ("movable-incline", "acceleration", "X", "0", r"wedge.*(held still|fixed).*M → ∞"),
    ("movable-incline", "equation", "D", "m*D_ddot - m*g*sin(alpha)", r"wedge.*(held still|fixed).*M → ∞"),
    ("double-pendulum", "acceleration", "theta1", "-g*theta1/l1", SMALL),
    (
        "movable-incline",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(D_dot**2 + 2*D_dot*X_dot*cos(alpha))/2",
        r"block.*moves with the wedge.*Ẋ",
    ),
    (
        "double-pendulum",
        "potential",
        None,
        "-m1*g*l1*cos(theta1) - m2*g*l2*cos(theta2)",
        r"lower bob.*moves with the upper bob.*θ₁",
    ),
    (
        "double-pendulum",
        "kinetic",
        None,
        "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2"
        " + m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 + theta2)",
        r"θ₁ \+ θ₂: the sign of θ₂",
    ),
    ("elastic-pendulum", "potential", None, "-m*g*r*cos(phi) + k*(r - l)**2", r"spring.*½ k"),
    # ---- a second-year student's practice session (review student-e)
    # the wedge's recoil the wrong way: X is cyclic (∂L/∂X = 0), so the sign is the whole answer's
    ("movable-incline", "acceleration", "X", "m*g*sin(alpha)*cos(alpha)/(M + m*sin(alpha)**2)", r"^(?!.*∂L/∂q).*the sign of the whole answer"),
    # divided through by m l: the term is quoted as the student wrote it, g sin θ (never −m g l sin θ)
    ("free-cart", "equation", "theta", "l*theta_ddot + X_ddot*cos(theta) - g*sin(theta)", r"the sign of your g sin\(θ\) term"),
    # a position where its velocity belongs: the right factors kept, the slip named
    ("simple-pendulum", "momentum", "theta", "m*R**2*theta", r"θ where θ̇ belongs.*mass times a velocity"),
    ("movable-incline", "momentum", "D", "m*D + m*X_dot*cos(alpha)", r"D where Ḋ belongs|adds a quantity in kg·m \(m D\)"),
    ("elastic-pendulum", "momentum", "phi", "m*r*phi_dot", r"factor r is missing"),
    ("elastic-pendulum", "kinetic", None, "m*(r_dot**2 + r*phi_dot**2)/2", UNITS_WORDS),
    ("simple-pendulum", "hamiltonian", None, "m*R**2*theta_dot**2/2 - m*g*R*cos(theta) + 7", r"7 has no unit.*energy"),
    ("simple-pendulum", "momentum", "theta", "m*R*theta_dot", r"factor R is missing"),
    # the wrong mass in one term: another body's, or the total (only the block changes height)
    ("movable-incline", "potential", None, "-(m + M)*g*D*sin(alpha)", r"wrong mass in your term.*block alone.*total mass"),
    (
        "free-cart",
        "kinetic",
        None,
        "(M + m)*X_dot**2/2 + m*l**2*theta_dot**2/2 + M*l*X_dot*theta_dot*cos(theta)",
        r"wrong mass in your term M l θ̇ Ẋ cos\(θ\).*the bob \(mass m\).*M belongs to the cart",
    ),
    ("movable-incline", "equation", "D", "m*D_ddot + M*X_ddot*cos(alpha) - m*g*sin(alpha)", r"wrong mass.*M where m belongs"),
    (
        "double-pendulum",
        "potential",
        None,
        "-(m1 + m2)*g*l1*cos(theta1) - m1*g*l2*cos(theta2)",
        r"wrong mass in your term −m₁ g l₂ cos\(θ₂\).*m₁ belongs to the upper bob",
    ),
    # review student-f, A: each reason fits its problem (a fixed angle is no coordinate; no spring, no stretch;
    # the set-up's own letters; a units factor pointed at; the term quoted as typed)
    ("incline-block", "acceleration", "X", "-g*cos(alpha)", r"sin and cos swapped.*component of gravity"),
    ("spherical-pendulum", "acceleration", "theta", "sin(theta)*cos(theta)*phi_dot**2 - g*sin(theta)/R", SIGN),
    (
        "spherical-pendulum",
        "lagrangian",
        None,
        "m*R**2*(theta_dot**2 + cos(theta)**2*phi_dot**2)/2 - m*g*R*sin(theta)",
        r"swapped throughout.*along the line its angle is measured from",
    ),
    (
        "pulley",
        "kinetic",
        None,
        "m1*y1_dot**2/2 + m1*y2_dot**2/2 + M*(y1_dot + y2_dot)**2/8",
        r"wrong mass.*this term comes from the right mass \(mass m₂\), and m₁ belongs",
    ),
    ("pulley", "potential", None, "M*g*(y1 + y2)/2 + m1*g*y1 + m2*g*y2", r"sign of your gravitational energy"),
    ("simple-pendulum", "kinetic", None, "m*g*R**2*theta_dot**2/2", r"a factor g \(m/s²\) too many\."),
    ("simple-pendulum", "equation", "theta", "theta_ddot + g*cos(theta)/R", r"swapped in your term g cos\(θ\)/R"),
    # review student-f, B: slips named that went unnamed (the ½ of a spring's U, a wrong mass in an acceleration,
    # a momentum's cross term in words, gravity counted twice without a Q)
    ("rail-two-body", "potential", None, "k*(x2 - x1 - l0)**2", r"the ½ of ½ k × stretch² left out"),
    ("rail-two-body", "acceleration", "x2", "-k*(x2 - x1 - l0)/m1", r"wrong mass: m₁ where m₂ belongs"),
    ("pulley", "momentum", "y2", "m2*y2_dot + M*y2_dot/4", r"the ẏ₁ term missing.*momentum conjugate to y₂"),
    ("simple-pendulum", "acceleration", "theta", "-g*sin(theta)/R - g*sin(theta)/R", r"gravity, counted twice"),
    # a rod's formulas typed for a bob (review student-f, 14): named as the rod's, with the rod's reason
    ("simple-pendulum", "kinetic", None, "m*R**2*theta_dot**2/6", r"a rod's T for a bob.*⅓ m × length²"),
    ("simple-pendulum", "potential", None, "m*g*(R/2)*(1 - cos(theta))", r"half.*a rod's centre is at half its length"),
    # a stretch's sign quoted as typed (review student-f, 15); the right one is kept for the student to ask for
    ("rail-two-body", "potential", None, "k*(x1 - x2 - l0)**2/2", r"x₁ − x₂ − l₀: the sign of l₀"),
    # a cross term's sign, explained from the geometry that gives it (student-e, 11)
    (
        "movable-incline",
        "kinetic",
        None,
        "(M + m)*X_dot**2/2 + m*D_dot**2/2 - m*X_dot*D_dot*cos(alpha)",
        r"the sign of your term.*block's position, x = X \+ D cos\(α\): ẋ = Ẋ \+ Ḋ cos\(α\)",
    ),
    # the fixed wedge's T: the wedge moves and carries the block
    ("movable-incline", "kinetic", None, "(1/2)*m*D_dot**2", r"wedge treated as fixed.*M → ∞.*carries the block"),
    # ---- positions (issue 41, item 1): one Cartesian component of one body, x across, y, z up, as the figure
    # draws them; where students go wrong first (a student's review)
    ("simple-pendulum", "position", "x", "R*cos(theta)", SWAP),
    ("simple-pendulum", "position", "z", "R*cos(theta)", SIGN + r"|up|below"),
    # student-h 188: the bob's height to second order in θ, where the exact z is asked
    ("simple-pendulum", "position", "z", "R*theta**2/2", r"z of the bob for small displacements"),
    ("damped-pendulum", "position", "x", "-R*sin(theta)", SIGN),
    ("spherical-pendulum", "position", "x", "R*cos(theta)*cos(phi)", SWAP),
    ("spherical-pendulum", "position", "z", "R*sin(theta)", SWAP),
    ("spherical-pendulum", "position", "y", "R*sin(theta)*cos(phi)", r"\bx\b|other component|swapp|sin.*cos"),
    ("helix-bead", "position", "y", "R*cos(alpha*z)", SWAP),
    ("helix-bead", "position", "x", "R*cos(z)", UNITS_WORDS),
    ("rotating-parabola", "position", "z", "alpha*rho", UNITS_WORDS),
    ("rotating-parabola", "position", "x", "rho*sin(omega*t)", SWAP),
    ("incline-block", "position", "x", "X*sin(alpha)", SWAP),
    ("incline-block", "position", "z", "-X*sin(alpha)", SIGN + r"|up"),
    # the wedge's X missing from the block's x: the block rides on the wedge
    ("movable-incline", "position", "x2", "D*cos(alpha)", r"wedge.*(carr|rides|moves)|X.*left out"),
    ("movable-incline", "position", "z2", "D*sin(alpha)", SIGN + r"|down|below"),
    ("movable-incline", "position", "x2", "X + D*sin(alpha)", SWAP),
    ("movable-incline", "position", "x2", "X - D*cos(alpha)", SIGN),
    ("tabletop-spring", "position", "x", "r*sin(theta)", SWAP),
    ("tabletop-spring", "position", "y", "sin(theta)", UNITS_WORDS),
    # the middle mass moving as far as the end masses, not half as far
    ("pulley", "position", "z3", "-(y1 + y2)", r"half|twice|doubled"),
    ("pulley", "position", "z3", "(y1 + y2)/2", SIGN),
    ("double-pendulum", "position", "x2", "l2*sin(theta2)", r"upper bob.*(carr|moves)|θ₁.*left out"),
    ("double-pendulum", "position", "x1", "l1*cos(theta1)", SWAP),
    ("double-pendulum", "position", "z2", "l1*cos(theta1) + l2*cos(theta2)", SIGN + r"|up|below"),
    ("double-pendulum", "position", "z2", "-l1*cos(theta1) - l2*cos(theta1)", r"θ₁ where θ₂ belongs|θ₂"),
    ("free-cart", "position", "x2", "l*sin(theta)", r"cart.*(carr|moves)|X.*left out"),
    ("elastic-pendulum", "position", "x", "r*cos(phi)", SWAP),
    ("cart-pendulum", "position", "z2", "l*cos(phi)", SIGN + r"|up|below"),
    # ---- diagnoses that blamed a right step (issue 41, student's review: 1)
    # the helix's z̈ term right, gravity times 1 + α²R²: the part that is wrong, never a T without the x–y motion
    ("helix-bead", "equation", "z", "m*(1+alpha**2*R**2)*z_ddot + m*g*(1+alpha**2*R**2)", r"^(?!.*a T that).*terms without a velocity multiplied by an extra factor 1 \+ R² α²"),
    # the coupling force's sign, typed as m ẍ₁ = −k x₁ − κ(x₂ − x₁): the force is named, not a U never typed here
    ("coupled-oscillators", "equation", "x1", "m*x1_ddot - (-k*x1 - kappa*(x2 - x1))", r"^(?!.*a U with).*sign of the force \(x₁ − x₂\) κ.*is −∂/∂x₁ of it, \(x₂ − x₁\) κ"),
    # ---- a solved acceleration or ω² read against the truth (issue 41, student's review: 2): the part that differs
    ("pulley", "acceleration", "y1", "(m2-m1)*g/(m1+m2)", r"denominator m₁ \+ m₂\b.*(solved|solving their equations) together"),
    ("movable-incline", "acceleration", "X", "-m*g*sin(alpha)*cos(alpha)/(M+m)", r"denominator M \+ m\b.*solved together"),
    ("helix-bead", "acceleration", "z", "-g*(1+alpha**2*R**2)", r"1 \+ R² α² upside down"),
    ("coupled-oscillators", "acceleration", "x1", "-(k+2*kappa)/m*x1", r"term of x₂ left out"),
    ("rotating-parabola", "omega_squared", None, "g*alpha - omega**2", r"factor 2 lost in the term 2 g α"),
    ("rotating-parabola", "omega_squared", None, "omega**2 - 2*g*alpha", r"sign of the whole answer"),
    # ---- the small-angle form where the exact U, L or h is asked (issue 41, 3)
    ("simple-pendulum", "potential", None, "m*g*R*theta**2/2", SMALL),
    ("simple-pendulum", "lagrangian", None, "m*R**2*theta_dot**2/2 - m*g*R*theta**2/2", SMALL),
    ("simple-pendulum", "hamiltonian", None, "m*R**2*theta_dot**2/2 + m*g*R*theta**2/2", SMALL),
]


# Slips a fresh student review found named badly or not at all (issue 41, the tutor names more slips): each must be
# named, never left to the step's rule
NAMED = [
    # issue 41, 1: the middle spring stretched by x₂ alone got the step's rule: its stretch is x₂ − x₁
    ("coupled-oscillators", "potential", None, "k*(x1**2 + x2**2)/2 + kappa*x2**2/2",
     r"x₂ as the stretch of the spring κ: x₁ left out"),
    # issue 41, 5: the middle mass given the end masses' speed sum: it moves at half of it, (ẏ₁ + ẏ₂)/2
    ("pulley", "kinetic", None, "M*(y1_dot + y2_dot)**2/2 + m1*y1_dot**2/2 + m2*y2_dot**2/2",
     r"the middle mass moves at \(ẏ₁ \+ ẏ₂\)/2, half as fast as ẏ₁ \+ ẏ₂"),
    # issue 41, 3: the wall spring's force counted twice was "a U that leaves out the ½ of ½ k × stretch² left out
    # of your term k x₂²": named as the force counted twice, with the U that would give it as the other cause
    ("coupled-oscillators", "equation", "x2", "m*x2_ddot - (-k*x2 - kappa*(x2 - x1) - k*x2)",
     r"the force −k x₂ counted twice.*or it came from a U with k x₂² where ½ k x₂² belongs"),
    # issue 41, 4: sharper names. A sum whose terms differ in units by one factor: what would fix it
    ("helix-bead", "kinetic", None, "m*z_dot**2*(1 + alpha*R**2)/2",
     r"1 has no unit.*α is in 1/m, so R² α is a length: did you mean R² α²\?"),
    ("helix-bead", "kinetic", None, "m*(z_dot**2 + R**2*alpha**2)/2",
     r"velocity factor is missing from R² α²: did you mean R² α² ż², the square of the speed R α ż\?"),
    # a whole factor missing is a factor, not "a ż term left out"
    ("helix-bead", "momentum", "z", "m*z_dot", r"A factor 1 \+ α²R² is missing from your momentum"),
    # every velocity-squared term of the equation left out, named as the double pendulum's is: by the chain rule
    ("rotating-parabola", "equation", "rho", "m*(1 + 4*alpha**2*rho**2)*rho_ddot + 2*alpha*g*m*rho - m*omega**2*rho",
     r"the chain-rule terms of d/dt\(∂L/∂ρ̇\) left out.*together 4 m α² ρ ρ̇²"),
    # m₁ where m₁ + m₂ belongs in the gravity term: the lower bob's weight, not "a term with g, l₁, m₂, θ₁"
    (
        "double-pendulum",
        "equation",
        "theta1",
        "(m1 + m2)*l1**2*theta1_ddot + m2*l1*l2*cos(theta1 - theta2)*theta2_ddot"
        " + m2*l1*l2*sin(theta1 - theta2)*theta2_dot**2 + m1*g*l1*sin(theta1)",
        r"the lower bob's weight left out.*its weight also acts on θ₁: the gravity term is \(m₁ \+ m₂\) g l₁ sin\(θ₁\)",
    ),
    # issue 41, 2: the wedge given a height got the step's rule: it slides on the floor, so M has no term in U
    ("movable-incline", "potential", None, "-m*g*D*sin(alpha) - M*g*X*sin(alpha)",
     r"added for the wedge, whose height never changes.*its height does not change.*M has no term in U"),
    # review student-k 5: a whole acceleration negated is one slip on every system (the pulley's was "the sign of
    # ∂L/∂q", the wedge's "the sign of the whole answer"), with its likely cause, a reversed U
    ("pulley", "acceleration", "y1", "g*(M*m1 - 3*M*m2 + 4*m1*m2)/(M*m1 + M*m2 + 4*m1*m2)",
     r"^(?!.*∂L/∂q).*the sign of the whole answer.*U with its sign reversed"),
    ("movable-incline", "acceleration", "X", "m*g*sin(alpha)*cos(alpha)/(M + m*sin(alpha)**2)",
     r"^(?!.*∂L/∂q).*the sign of the whole answer.*U with its sign reversed"),
    # −g/R for ω²: the other equilibrium's, and as likely a U of the wrong sign at θ = 0
    ("simple-pendulum", "omega_squared", None, "-g/R", r"θ = π.*Or, at θ = 0, your U has its sign reversed"),
    # review student-k 1: a solved answer's number upside down or a factor squared is named so, before any
    # denominator is compared, and no one-coordinate answer is told of "equations solved together" or an
    # "effective mass" its denominator is not
    ("physical-pendulum", "omega_squared", None, "2*g/(3*l)",
     r"^(?!.*(solved together|denominator)).*the number 2/3 upside down"),
    ("helix-bead", "acceleration", "z", "-g/(1 + R**2*alpha**2)**2",
     r"^(?!.*(solved together|effective mass|R⁴)).*the factor 1 \+ R² α² squared"),
    ("coupled-oscillators", "acceleration", "x1", "(-k*x1 - kappa*(x1 - x2))/(2*m)",
     r"^(?!.*(solved together|effective mass)).*the denominator 2 m.*coefficient of the acceleration"),
    # review student-k 2: two slips, the units' named and the lost ½ said after it
    ("simple-pendulum", "kinetic", None, "m*R*theta_dot**2",
     r"a length such as R.*at least one more difference: the ½ of ½ m v² left out"),
    # review student-k 3: the helix's winding factor put into U; the parallel-axis term counted twice
    ("helix-bead", "potential", None, "m*g*(1 + R**2*alpha**2)*z",
     r"the factor 1 \+ R² α², which belongs to T.*more inertia, not more weight"),
    ("physical-pendulum", "kinetic", None, "M*(l/2)**2*theta_dot**2/2 + (M*l**2/3)*theta_dot**2/2",
     r"the parallel-axis term M l²/4 counted twice, since I about the pivot, M l²/3, already holds it"),
    # review student-k 6: a rigid body's slip of U is explained by U, never by T
    ("physical-pendulum", "potential", None, "-M*g*l*cos(theta)",
     r"^(?!.*v_centre).*centre at l in place of l/2.*the height of its centre"),
    # review student-l 5: the coupling forgotten was "the force from spring energy (its ∂/∂x₁) (in the equation for
    # x₁)": which spring, and its force over the mass
    ("coupled-oscillators", "acceleration", "x1", "-k/m*x1",
     r"^(?!.*\) \().*the coupling spring's force κ \(x₂ − x₁\)/m left out.*joins x₁ to x₂"),
    ("coupled-oscillators", "equation", "x1", "m*x1_ddot + k*x1", r"the coupling spring's force κ \(x₂ − x₁\) left out"),
    # review student-l 5: U written with another axis for the height, or a height's cosine squared, got the step's rule
    ("helix-bead", "potential", None, "m*g*R*sin(alpha*z)",
     r"the bead's y, R sin\(α z\), taken for its height.*U is m g times the height.*its z"),
    ("simple-pendulum", "potential", None, "-m*g*R*cos(theta)**2",
     r"cos\(θ\) squared in the bob's height.*a height is linear in cos\(θ\)"),
    # review student-l 5: ż = 2αρρ̇ entered unsquared, typed as one term, got "the ρ̇² terms do not agree": named as the
    # helix's is, the part and its square
    ("rotating-parabola", "kinetic", None, "1/2*m*(rho_dot**2 + rho**2*omega**2 + 2*alpha*rho*rho_dot**2)",
     r"You wrote 2αρ where T needs its square 4α²ρ²"),
    # review student-l 5: the pulley's ÿ₁ as an Atwood machine, the right mass held still: named by that cause
    ("pulley", "acceleration", "y1", "g*(M/2 - m1)/(m1 + M/4)",
     r"^(?!.*denominator).*equation for y₁ alone, with ÿ₂ = 0, as if the right mass were held still"
     r".*middle mass moves with both y₁ and y₂"),
    # review student-l 5: the rail's two masses as one body got "no part of your answer agrees"
    ("rail-two-body", "kinetic", None, "1/2*(m1+m2)*(x1_dot+x2_dot)**2",
     r"^(?!.*Everything else).*the bodies taken as one, ½ \(m₁ \+ m₂\) \(ẋ₁ \+ ẋ₂\)², without each body's own ½ m v²"),
    # review student-l 9: the pendulum's θ̈ without 1/R, said in units
    ("simple-pendulum", "acceleration", "theta", "-g*sin(theta)",
     r"without a factor 1/R.*θ̈ is a squared rate, but −g sin\(θ\) is an acceleration, so it must still be divided by a "
     r"length \(R\)"),
    # issue 42: a solid cylinder rolling on a sliding wedge, declared as a rigid body: its turning forgotten, taken as
    # a hoop, the wedge's motion left out of its velocity, the cross term's sign, each named in T and in the equation
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2",
        r"cylinder's turning forgotten.*½ I_cm \(ṡ/r\)²",
    ),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2 + m*s_dot**2/2",
        r"taken as a hoop.*I = m r²",
    ),
    ("rolling-cylinder-wedge", "kinetic", None, "M*X_dot**2/2 + 3*m*s_dot**2/4", r"wedge's motion left out.*Ẋ"),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "(M + m)*X_dot**2/2 - m*X_dot*s_dot*cos(alpha) + 3*m*s_dot**2/4",
        rf"({SIGN}).*Ẋ cos\(α\)",
    ),
    ("rolling-cylinder-wedge", "equation", "s", "m*s_ddot + m*X_ddot*cos(alpha) - m*g*sin(alpha)", r"turning forgotten"),
    ("rolling-cylinder-wedge", "equation", "s", "2*m*s_ddot + m*X_ddot*cos(alpha) - m*g*sin(alpha)", r"hoop"),
    ("rolling-cylinder-wedge", "equation", "s", "3*m*s_ddot/2 - m*g*sin(alpha)", r"wedge's motion left out"),
    ("rolling-cylinder-wedge", "equation", "s", "3*m*s_ddot/2 - m*X_ddot*cos(alpha) - m*g*sin(alpha)", SIGN),
    # review prof-q 6: a rigid body's slip of T is printed as the derivation prints it (½ M (l/2)² θ̇², never
    # Ml²/4θ̇²/2), and its rule in the page's own symbols: the body's mass letter, v_cm, its own turning rate, never ω
    (
        "physical-pendulum",
        "kinetic",
        None,
        "M*(l/2)**2*theta_dot**2/2",
        r"^(?!.*(ω|v_centre|l²/4 θ̇²/2|M l²/12)).*only the motion of the rod's centre, ½ M \(l/2\)² θ̇² = M l² θ̇²/8"
        r".*the rod's T is ½ M v_cm² \+ ½ I_cm θ̇²",
    ),
    (
        "physical-pendulum",
        "kinetic",
        None,
        "M*l**2*theta_dot**2/2",
        r"^(?!.*(ω|v_centre)).*point mass.*the rod's T is ½ M v_cm² \+ ½ I_cm θ̇²",
    ),
    (
        "rod-pendulum",
        "kinetic",
        None,
        "m*(l/2)**2*theta_dot**2/2",
        r"^(?!.*(ω|v_centre)).*½ m \(l/2\)² θ̇² = m l² θ̇²/8.*T is ½ m v_cm² \+ ½ I_cm θ̇²",
    ),
    ("rolling-disc", "kinetic", None, "M*x_dot**2/2", r"^(?!.*(ω|v_centre)).*spin forgotten.*½ I_cm \(ẋ/R\)²"),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2",
        r"^(?!.*(ω|v_centre)).*the cylinder's T is ½ m v_cm² \+ ½ I_cm \(ṡ/r\)²",
    ),
    # review prof-q 7: another kind's moment of inertia named as that, without the body's own I_cm: a disc's for the
    # rod's (with the parallel-axis term), a sphere's for the cylinder's, in T and carried into the equation
    (
        "physical-pendulum",
        "kinetic",
        None,
        "M*l**2*theta_dot**2/8 + M*l**2*theta_dot**2/4",
        r"^(?!.*M l²/12).*the turning energy with the wrong moment of inertia: I_cm of a uniform disc, M l²/2, in place "
        r"of a uniform rod's",
    ),
    (
        "physical-pendulum",
        "equation",
        "theta",
        "3*M*l**2*theta_ddot/4 + M*g*l*sin(theta)/2",
        r"wrong moment of inertia: I_cm of a uniform disc",
    ),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2 + (2*m*r**2/5)*(s_dot/r)**2/2",
        r"^(?!.*m r²/2).*the turning energy with the wrong moment of inertia: I_cm of a solid sphere, 2 m r²/5, in "
        r"place of a solid cylinder's",
    ),
    (
        "rolling-cylinder-wedge",
        "equation",
        "s",
        "7*m*s_ddot/5 + m*X_ddot*cos(alpha) - m*g*sin(alpha)",
        r"wrong moment of inertia: I_cm of a solid sphere",
    ),
    # review prof-q 7: the cross term's sign explained by the square it comes from, read from the body's velocity;
    # prof-r 3: without printing v_cm², the step's answer
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "(M + m)*X_dot**2/2 - m*X_dot*s_dot*cos(alpha) + 3*m*s_dot**2/4",
        r"^(?!.*(sum of squares|v_cm² =|ṡ sin)).*½ m v_cm²: write v⃗_cm component by component \(Ẋ and ṡ both appear "
        r"in one of them\), square each and add",
    ),
    # review prof-q 1: the fixed wedge's s̈ = 2g sin α/3 is the answer with the wedge held fixed (never "another
    # system's, such as an Atwood machine's"), and a sliding block's s̈ and Ẍ are the cylinder's turning forgotten
    ("rolling-cylinder-wedge", "acceleration", "s", "2*g*sin(alpha)/3",
     r"^(?!.*Atwood).*wedge held fixed \(M → ∞\).*the wedge recoils, so the X and s equations are solved together"),
    ("rolling-cylinder-wedge", "acceleration", "s", "(M + m)*g*sin(alpha)/(M + m*sin(alpha)**2)",
     r"cylinder's turning forgotten.*slides without turning, such as a block"),
    ("rolling-cylinder-wedge", "acceleration", "X", "-m*g*sin(alpha)*cos(alpha)/(M + m*sin(alpha)**2)",
     r"cylinder's turning forgotten.*slides without turning, such as a block"),
    # review prof-q 3: the cylinder's centre is asked, where the wedge's motion enters: its X left out, sin and cos
    # swapped
    ("rolling-cylinder-wedge", "position", "x2", "s*cos(alpha) + r*sin(alpha)", r"wedge's x left out.*carries"),
    ("rolling-cylinder-wedge", "position", "x2", "X + s*sin(alpha) + r*cos(alpha)", SWAP),
    ("rolling-cylinder-wedge", "position", "z2", "r*sin(alpha) - s*cos(alpha)", SWAP),
]
SLIPS += NAMED

# Correct answers in unusual forms: every one must be accepted ("correct", or "equivalent" where the
# step's relation allows another zero of U or a nonzero factor).
CORRECT = [
    ("simple-pendulum", "equation", "theta", "theta_ddot + (g/R)*sin(theta)"),
    ("simple-pendulum", "equation", "theta", "-R*theta_ddot - g*sin(theta)"),
    ("simple-pendulum", "potential", None, "-m*g*R*cos(theta)"),
    ("simple-pendulum", "potential", None, "2*m*g*R*sin(theta/2)**2"),
    ("simple-pendulum", "kinetic", None, "m*(R*theta_dot)**2/2"),
    ("simple-pendulum", "acceleration", "theta", "-g*sin(theta)/R"),
    ("simple-pendulum", "omega_squared", None, "g/R"),
    ("simple-pendulum", "hamiltonian", None, "m*R**2*theta_dot**2/2 + m*g*R*(1 - cos(theta))"),
    ("simple-pendulum", "lagrangian", None, "m*R**2*theta_dot**2/2 + m*g*R*cos(theta)"),
    ("damped-pendulum", "equation", "theta", "theta_ddot + b*theta_dot/(m*R**2) + g*sin(theta)/R"),
    ("damped-pendulum", "acceleration", "theta", "-(b*theta_dot + m*g*R*sin(theta))/(m*R**2)"),
    ("helix-bead", "kinetic", None, "m*(R**2*alpha**2*z_dot**2 + z_dot**2)/2"),
    ("helix-bead", "equation", "z", "z_ddot + g/(1 + R**2*alpha**2)"),
    ("helix-bead", "potential", None, "m*g*(z - R)"),
    ("incline-block", "equation", "X", "X_ddot + g*sin(alpha)"),
    ("incline-block", "potential", None, "m*g*X*cos(pi/2 - alpha)"),
    ("incline-block", "kinetic", None, "m*X_dot**2*(sin(alpha)**2 + cos(alpha)**2)/2"),
    ("tabletop-spring", "equation", "r", "r_ddot - r*theta_dot**2 + k*r/m"),
    ("tabletop-spring", "equation", "theta", "r*theta_ddot + 2*r_dot*theta_dot"),
    ("tabletop-spring", "momentum", "theta", "m*r**2*theta_dot"),
    ("tabletop-spring", "kinetic", None, "m*(r_dot**2 + (r*theta_dot)**2)/2"),
    ("spherical-pendulum", "kinetic", None, "m*R**2*(theta_dot**2 + (1 - cos(theta)**2)*phi_dot**2)/2"),
    ("spherical-pendulum", "equation", "phi", "sin(theta)*phi_ddot + 2*cos(theta)*theta_dot*phi_dot"),
    ("spherical-pendulum", "equation", "theta", "theta_ddot - sin(2*theta)*phi_dot**2/2 - g*sin(theta)/R"),
    ("spherical-pendulum", "potential", None, "m*g*R*(cos(theta) + 1)"),
    ("rail-two-body", "potential", None, "k*(x1 - x2 + l0)**2/2"),
    ("rail-two-body", "equation", "x2", "m2*x2_ddot + k*(x2 - x1 - l0)"),
    ("rail-two-body", "kinetic", None, "(m1*x1_dot**2 + m2*x2_dot**2)/2"),
    ("pulley", "kinetic", None, "M*(y1_dot + y2_dot)**2/8 + m1*y1_dot**2/2 + m2*y2_dot**2/2"),
    ("pulley", "potential", None, "g*(m1*y1 + m2*y2) - M*g*(y1 + y2 + 3*c)/2"),
    ("pulley", "equation", "y1", "(4*m1 + M)*y1_ddot + M*y2_ddot + 4*g*m1 - 2*M*g"),
    ("movable-incline", "momentum", "X", "(M + m)*X_dot + m*D_dot*cos(alpha)"),
    ("movable-incline", "equation", "D", "D_ddot + X_ddot*cos(alpha) - g*sin(alpha)"),
    (
        "movable-incline",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*((X_dot + D_dot*cos(alpha))**2 + D_dot**2*sin(alpha)**2)/2",
    ),
    ("rotating-parabola", "omega_squared", None, "2*alpha*g - omega**2"),
    ("rotating-parabola", "kinetic", None, "m*(rho_dot**2 + (2*alpha*rho*rho_dot)**2 + (omega*rho)**2)/2"),
    ("rotating-parabola", "potential", None, "m*g*alpha*rho**2"),
    ("coupled-oscillators", "potential", None, "(k + kappa)*(x1**2 + x2**2)/2 - kappa*x1*x2"),
    ("coupled-oscillators", "equation", "x2", "m*x2_ddot + (k + kappa)*x2 - kappa*x1"),
    (
        "double-pendulum",
        "kinetic",
        None,
        "m1*l1**2*theta1_dot**2/2 + m2*((l1*theta1_dot*cos(theta1) + l2*theta2_dot*cos(theta2))**2"
        " + (l1*theta1_dot*sin(theta1) + l2*theta2_dot*sin(theta2))**2)/2",
    ),
    ("double-pendulum", "potential", None, "-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)"),
    (
        "double-pendulum",
        "equation",
        "theta2",
        "l2*theta2_ddot + l1*cos(theta1 - theta2)*theta1_ddot - l1*sin(theta1 - theta2)*theta1_dot**2 + g*sin(theta2)",
    ),
    (
        "double-pendulum",
        "kinetic",
        None,
        "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2"
        " + m2*l1*l2*theta1_dot*theta2_dot*(cos(theta1)*cos(theta2) + sin(theta1)*sin(theta2))",
    ),
    ("cart-pendulum", "equation", "phi", "l*phi_ddot + cos(phi)*x_ddot + g*sin(phi)"),
    (
        "cart-pendulum",
        "kinetic",
        None,
        "M*x_dot**2/2 + m*((x_dot + l*cos(phi)*phi_dot)**2 + (l*sin(phi)*phi_dot)**2)/2",
    ),
    ("spring-rod", "equation", "r", "r_ddot + (k/m - w**2)*r - k*a/m"),
    ("spring-rod", "omega_squared", None, "k/m - w**2"),
    ("rod-pendulum", "kinetic", None, "(m*l**2/3)*theta_dot**2/2"),
    ("rod-pendulum", "equation", "theta", "2*l*theta_ddot + 3*g*sin(theta)"),
    ("rod-pendulum", "omega_squared", None, "3*g/(2*l)"),
    ("rod-pendulum", "potential", None, "m*g*l*(1 - cos(theta))/2"),
    ("physical-pendulum", "kinetic", None, "(M*l**2/3)*theta_dot**2/2"),
    ("physical-pendulum", "equation", "theta", "2*l*theta_ddot + 3*g*sin(theta)"),
    ("physical-pendulum", "omega_squared", None, "3*g/(2*l)"),
    ("physical-pendulum", "potential", None, "M*g*l*(1 - cos(theta))/2"),
    ("massive-pulley", "kinetic", None, "(m1 + m2)*z_dot**2/2 + (M*R**2/2)*(z_dot/R)**2/2"),
    ("massive-pulley", "potential", None, "-m1*g*(d + z) - m2*g*(d - z)"),  # heights from the axle
    ("massive-pulley", "equation", "z", "(2*m1 + 2*m2 + M)*z_ddot + 2*(m2 - m1)*g"),
    ("massive-pulley", "acceleration", "z", "2*(m1 - m2)*g/(2*m1 + 2*m2 + M)"),
    ("rolling-disc", "kinetic", None, "M*x_dot**2/2 + (M*R**2/2)*(x_dot/R)**2/2"),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2 + (m*r**2/2)*(s_dot/r)**2/2",
    ),
    ("rolling-cylinder-wedge", "equation", "s", "3*s_ddot + 2*X_ddot*cos(alpha) - 2*g*sin(alpha)"),
    ("rolling-cylinder-wedge", "acceleration", "s", "2*(M + m)*g*sin(alpha)/(3*M + m + 2*m*sin(alpha)**2)"),
    ("rolling-cylinder-wedge", "position", "x2", "X + s*cos(alpha)"),
    ("rolling-disc", "omega_squared", None, "2*k/(3*M)"),
    ("rolling-disc", "equation", "x", "x_ddot + 2*k*x/(3*M) - 2*g*sin(alpha)/3"),
    ("elastic-pendulum", "potential", None, "k*(l - r)**2/2 - m*g*r*cos(phi)"),
    ("elastic-pendulum", "equation", "phi", "r*phi_ddot + 2*r_dot*phi_dot + g*sin(phi)"),
    ("simple-pendulum", "potential", None, "m*g*R*(1 - cos(theta))"),
    ("free-cart", "equation", "theta", "l*theta_ddot + X_ddot*cos(theta) + g*sin(theta)"),
    ("free-cart", "kinetic", None, "(M + m)*X_dot**2/2 + m*l**2*theta_dot**2/2 + m*l*X_dot*theta_dot*cos(theta)"),
    # positions: another origin is the page's plus a constant; identities are the same component
    ("simple-pendulum", "position", "z", "-R*cos(theta)"),
    ("simple-pendulum", "position", "z", "2*R*sin(theta/2)**2"),
    ("movable-incline", "position", "x2", "X + D*sin(pi/2 - alpha)"),
    ("double-pendulum", "position", "z2", "-(l1*cos(theta1) + l2*cos(theta2))"),
    ("coupled-oscillators", "position", "x1", "x1"),
    ("pulley", "position", "z3", "-(y1 + y2)/2"),
]
