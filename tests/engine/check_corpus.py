"""A corpus of student answers with the verdict, difference and hint the checker must give.

Each entry: (system, step, coordinate, answer, verdict, difference, hint).
``system`` is a scene id or one of the two systems below; ``difference`` is
answer − truth as an expression in the API's syntax (``None`` when there is
none); ``hint`` is ``"key:<mistake key>"`` (a mistake generated from the
system's derivation, app/engine/tutor/mistake_families.py, which the answer must be
diagnosed as), a mistake of ``app.engine.tutor.mistakes.RULES``, ``"pointer"`` (the
step's general rule), ``"omega"``, ``"missing_factor:<factor>"`` or
``"constant_factor:<factor>"``, or ``None``.  ``TYPICAL`` adds at least three
typical mistakes for every scene and both systems, each with the diagnosis it must
name: (system, step, coordinate, answer, mistake key).
"""

from __future__ import annotations

# A cart on a spring with a pendulum hanging from it, and drag on the cart (particles, U and a force).
CART_PENDULUM = {
    "coordinates": ["x", "phi"],
    "parameters": [{"name": n, "value": 1.0, "min": 0.1} for n in ("M", "m", "l", "k", "g", "c")],
    "particles": [
        {"mass": "M", "position": ["x", "0", "0"], "label": "cart"},
        {"mass": "m", "position": ["x + l*sin(phi)", "0", "-l*cos(phi)"], "label": "bob"},
    ],
    "potential": "k*x**2/2 - m*g*l*cos(phi)",
    "forces": {"x": "-c*x_dot"},
}

# A bead on a rod spun at the rate w in a horizontal plane, held by a spring of natural length a
# anchored on the axis, given by L alone.
SPRING_ROD = {
    "coordinates": ["r"],
    "parameters": [{"name": n, "value": 1.0, "min": 0.1} for n in ("m", "k", "a", "w")],
    "lagrangian": "m*(r_dot**2 + w**2*r**2)/2 - k*(r - a)**2/2",
}

USER_SYSTEMS = {"cart-pendulum": CART_PENDULUM, "spring-rod": SPRING_ROD}

CORPUS = [
    # a position: one component of one body, up to another origin
    ("movable-incline", "position", "x2", "D*cos(alpha)", "incorrect", "-X", "key:position.x2.carried.1"),
    ("simple-pendulum", "position", "z", "-R*cos(theta)", "equivalent", None, None),
    ("double-pendulum", "position", "z2", "-l1*cos(theta1) - l2*cos(theta2)", "correct", None, None),
    # simple pendulum
    ("simple-pendulum", "kinetic", None, "m*R**2*theta_dot**2/2", "correct", None, None),
    ("simple-pendulum", "kinetic", None, "m*(R*theta_dot)**2*(sin(theta)**2 + cos(theta)**2)/2", "correct", None, None),
    ("simple-pendulum", "kinetic", None, "m*R**2*theta_dot**2", "incorrect", "m*R**2*theta_dot**2/2", "missing_half"),
    (
        "simple-pendulum",
        "kinetic",
        None,
        "m*R*theta_dot/2",
        "incorrect",
        "m*R*theta_dot/2 - m*R**2*theta_dot**2/2",
        "speed_not_squared",
    ),
    ("simple-pendulum", "potential", None, "-m*g*R*cos(theta)", "equivalent", None, None),
    ("simple-pendulum", "potential", None, "m*g*R*cos(theta)", "incorrect", "2*m*g*R*cos(theta)", "sign_of_u"),
    (
        "simple-pendulum",
        "lagrangian",
        None,
        "m*R**2*theta_dot**2/2 + m*g*R*(1 - cos(theta))",
        "incorrect",
        "-2*m*g*R*cos(theta)",
        "t_plus_u",
    ),
    ("simple-pendulum", "equation", "theta", "theta_ddot + g*sin(theta)/R", "correct", None, None),
    ("simple-pendulum", "equation", "theta", "-m*R*theta_ddot - m*g*sin(theta)", "correct", None, None),
    (
        "simple-pendulum",
        "equation",
        "theta",
        "theta_ddot - g*sin(theta)/R",
        "incorrect",
        "-2*g*sin(theta)/R",
        "sign_of_dl_dq",
    ),
    (
        "simple-pendulum",
        "equation",
        "theta",
        "theta_ddot + g*sin(theta)",
        "incorrect",
        None,  # terms of different units: the units are the mistake, and no difference is shown
        "units",
    ),
    ("simple-pendulum", "acceleration", "theta", "-2*g*sin(theta/2)*cos(theta/2)/R", "correct", None, None),
    ("simple-pendulum", "omega_squared", None, "sqrt(g/R)", "incorrect", "sqrt(g/R) - g/R", "omega"),
    ("simple-pendulum", "omega_squared", None, "g/R", "correct", None, None),
    ("simple-pendulum", "hamiltonian", None, "m*R**2*theta_dot**2/2 - m*g*R*cos(theta)", "equivalent", None, None),
    (
        "simple-pendulum",
        "hamiltonian",
        None,
        "m*R**2*theta_dot**2/2 - m*g*R*(1 - cos(theta))",
        "incorrect",
        "2*m*g*R*cos(theta)",
        "h_is_l",
    ),
    # damped pendulum
    (
        "damped-pendulum",
        "equation",
        "theta",
        "m*R**2*theta_ddot + m*g*R*sin(theta) + b*theta_dot",
        "correct",
        None,
        None,
    ),
    (
        "damped-pendulum",
        "equation",
        "theta",
        "m*R**2*theta_ddot + 2*m*g*R*sin(theta) + b*theta_dot",
        "incorrect",
        "m*g*R*sin(theta)",
        "force_counted_twice",
    ),
    (
        "damped-pendulum",
        "equation",
        "theta",
        "m*R**2*theta_ddot + m*g*R*sin(theta)",
        "incorrect",
        "-b*theta_dot",
        "forgot_force",
    ),
    (
        "damped-pendulum",
        "acceleration",
        "theta",
        "-(2*m*g*R*sin(theta) + b*theta_dot)/(m*R**2)",
        "incorrect",
        "-g*sin(theta)/R",
        "force_counted_twice",
    ),
    (
        "damped-pendulum",
        "momentum",
        "theta",
        "m*R*theta_dot",
        "incorrect",
        "m*R*theta_dot - m*R**2*theta_dot",
        "constant_factor:R",
    ),
    # helix bead
    ("helix-bead", "kinetic", None, "m*(1 + R**2*alpha**2)*z_dot**2/2", "correct", None, None),
    ("helix-bead", "potential", None, "-m*g*z", "incorrect", "-2*m*g*z", "sign_of_u"),
    ("helix-bead", "acceleration", "z", "-g/(1 + alpha**2*R**2)", "correct", None, None),
    # incline block
    # a "constant" of the wrong units (a force, a mass, a bare number) is no other zero of U: a units mistake
    ("incline-block", "lagrangian", None, "m*X_dot**2/2 - m*g*X*sin(alpha) + 3*m*g", "incorrect", None, "units"),
    ("incline-block", "acceleration", "X", "-g*sin(alpha)", "correct", None, None),
    # a whole acceleration negated is the sign of the whole answer on every system (review student-k 5)
    ("incline-block", "acceleration", "X", "g*sin(alpha)", "incorrect", "2*g*sin(alpha)", "key:acceleration.whole_sign"),
    # tabletop spring
    (
        "tabletop-spring",
        "acceleration",
        "theta",
        "0",
        "incorrect",
        "2*r_dot*theta_dot/r",
        "key:acceleration.chain_rule.r.theta",
    ),
    ("tabletop-spring", "acceleration", "theta", "-2*r_dot*theta_dot/r", "correct", None, None),
    (
        "tabletop-spring",
        "momentum",
        "theta",
        "m*theta_dot",
        "incorrect",
        "m*theta_dot - m*r**2*theta_dot",
        "missing_factor:r²",
    ),
    ("tabletop-spring", "omega_squared", None, "4*k/m", "correct", None, None),
    ("tabletop-spring", "omega_squared", None, "2*sqrt(k/m)", "incorrect", "2*sqrt(k/m) - 4*k/m", "omega"),
    # spherical pendulum
    (
        "spherical-pendulum",
        "momentum",
        "phi",
        "m*R**2*phi_dot",
        "incorrect",
        "m*R**2*phi_dot*cos(theta)**2",
        "missing_factor:sin² θ",
    ),
    (
        "spherical-pendulum",
        "equation",
        "phi",
        "m*R**2*sin(theta)**2*phi_ddot",
        "incorrect",
        "-2*m*R**2*sin(theta)*cos(theta)*theta_dot*phi_dot",
        "key:equation.chain_rule.theta",
    ),
    (
        "spherical-pendulum",
        "equation",
        "phi",
        "sin(theta)*phi_ddot + 2*cos(theta)*theta_dot*phi_dot",
        "equivalent",
        None,
        None,
    ),
    ("spherical-pendulum", "acceleration", "phi", "-2*theta_dot*phi_dot/tan(theta)", "correct", None, None),
    ("spherical-pendulum", "potential", None, "-m*g*R*cos(theta)", "incorrect", "-2*m*g*R*cos(theta)", "sign_of_u"),
    # rail and two bodies
    ("rail-two-body", "potential", None, "k*(x1 - x2 + l0)**2/2", "correct", None, None),
    ("rail-two-body", "equation", "x1", "m1*x1_ddot - k*(x2 - x1 - l0)", "correct", None, None),
    # pulley
    (
        "pulley",
        "kinetic",
        None,
        "M*(y1_dot**2 + y2_dot**2)/8 + m1*y1_dot**2/2 + m2*y2_dot**2/2",
        "incorrect",
        "-M*y1_dot*y2_dot/4",
        "key:kinetic.cross_term.y1_dot.y2_dot",
    ),
    ("pulley", "kinetic", None, "M*(y1_dot + y2_dot)**2/8 + m1*y1_dot**2/2 + m2*y2_dot**2/2", "correct", None, None),
    # movable incline
    (
        "movable-incline",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + D_dot**2)/2",
        "incorrect",
        "-m*X_dot*D_dot*cos(alpha)",
        "key:kinetic.cross_term.X_dot.D_dot",
    ),
    (
        "movable-incline",
        "lagrangian",
        None,
        "M*X_dot**2/2 + m*((X_dot + D_dot*cos(alpha))**2 + (D_dot*sin(alpha))**2)/2 + m*g*D*sin(alpha) + 7*m",
        "incorrect",
        None,
        "units",
    ),
    ("movable-incline", "momentum", "X", "(M + m)*X_dot + m*D_dot*cos(alpha)", "correct", None, None),
    # rotating parabola
    (
        "rotating-parabola",
        "hamiltonian",
        None,
        "m*rho_dot**2*(1 + 4*alpha**2*rho**2)/2 + m*omega**2*rho**2/2 + alpha*g*m*rho**2",
        "incorrect",
        "m*omega**2*rho**2",
        "h_is_e",
    ),
    (
        "rotating-parabola",
        "hamiltonian",
        None,
        "m*rho_dot**2*(1 + 4*alpha**2*rho**2)/2 - m*omega**2*rho**2/2 + alpha*g*m*rho**2",
        "correct",
        None,
        None,
    ),
    ("rotating-parabola", "omega_squared", None, "2*alpha*g - omega**2", "correct", None, None),
    # a cart with a hanging pendulum, a spring and drag (a system of our own)
    (
        "cart-pendulum",
        "kinetic",
        None,
        "(M + m)*x_dot**2/2 + m*l**2*phi_dot**2/2",
        "incorrect",
        "-m*l*cos(phi)*x_dot*phi_dot",
        "key:kinetic.cross_term.x_dot.phi_dot",
    ),
    (
        "cart-pendulum",
        "lagrangian",
        None,
        "(M + m)*x_dot**2/2 + m*l*cos(phi)*x_dot*phi_dot + m*l**2*phi_dot**2/2 - k*x**2/2 + m*g*l*cos(phi)",
        "correct",
        None,
        None,
    ),
    ("cart-pendulum", "equation", "phi", "l*phi_ddot + cos(phi)*x_ddot + g*sin(phi)", "correct", None, None),
    (
        "cart-pendulum",
        "equation",
        "phi",
        "m*l**2*phi_ddot + m*l*cos(phi)*x_ddot + m*g*l*sin(phi) - m*l*sin(phi)*x_dot*phi_dot",
        "incorrect",
        "-m*l*sin(phi)*x_dot*phi_dot",
        "key:equation.dl_dq_part.phi_dot_x_dot",
    ),
    (
        "cart-pendulum",
        "equation",
        "x",
        "(M + m)*x_ddot + m*l*cos(phi)*phi_ddot + k*x + c*x_dot",
        "incorrect",
        "m*l*sin(phi)*phi_dot**2",
        "key:equation.chain_rule.phi",
    ),
    (
        "cart-pendulum",
        "equation",
        "x",
        "(M + m)*x_ddot + m*l*cos(phi)*phi_ddot - m*l*sin(phi)*phi_dot**2 + k*x",
        "incorrect",
        "-c*x_dot",
        "forgot_force",
    ),
    ("cart-pendulum", "momentum", "x", "(M + m)*x_dot + m*l*cos(phi)*phi_dot", "correct", None, None),
    # a bead on a spun rod with a spring, given by L alone (a system of our own)
    ("spring-rod", "hamiltonian", None, "m*(r_dot**2 - w**2*r**2)/2 + k*(r - a)**2/2", "correct", None, None),
    (
        "spring-rod",
        "hamiltonian",
        None,
        "m*(r_dot**2 + w**2*r**2)/2 - k*(r - a)**2/2",
        "incorrect",
        "m*w**2*r**2 - k*r**2 + 2*k*a*r",
        "h_is_l",
    ),
    ("spring-rod", "momentum", "r", "m*r_dot", "correct", None, None),
    ("spring-rod", "equation", "r", "r_ddot + (k/m - w**2)*r - k*a/m", "correct", None, None),
    ("spring-rod", "omega_squared", None, "(k - m*w**2)/m", "correct", None, None),
    ("spring-rod", "omega_squared", None, "sqrt(k/m - w**2)", "incorrect", "sqrt(k/m - w**2) - k/m + w**2", "omega"),
    # beyond the chapter: a rigid rod (issue 42), its T the centre's motion plus the turning about the centre
    ("physical-pendulum", "kinetic", None, "M*l**2*theta_dot**2/6", "correct", None, None),
    (
        "physical-pendulum",
        "kinetic",
        None,
        "M*l**2*theta_dot**2/2",
        "incorrect",
        "M*l**2*theta_dot**2/3",
        "key:kinetic.rigid.rod_point_mass",
    ),
    ("physical-pendulum", "omega_squared", None, "3*g/(2*l)", "correct", None, None),
    # beyond the chapter: a cylinder rolling on a sliding wedge (issue 42), its T the centre's motion, carried by the
    # wedge, plus its turning; the turning forgotten leaves out ¼ m ṡ²
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "(M + m)*X_dot**2/2 + m*X_dot*s_dot*cos(alpha) + 3*m*s_dot**2/4",
        "correct",
        None,
        None,
    ),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2",
        "incorrect",
        "-m*s_dot**2/4",
        "key:kinetic.rigid.turning_forgotten.0",
    ),
    (
        "rolling-cylinder-wedge",
        "acceleration",
        "s",
        "2*(M + m)*g*sin(alpha)/(3*M + m + 2*m*sin(alpha)**2)",
        "correct",
        None,
        None,
    ),
    # beyond the chapter: an Atwood machine on a disc pulley (issue 42), the pulley turning with the string
    ("massive-pulley", "kinetic", None, "(m1 + m2 + M/2)*z_dot**2/2", "correct", None, None),
    (
        "massive-pulley",
        "kinetic",
        None,
        "(m1 + m2)*z_dot**2/2",
        "incorrect",
        "-M*z_dot**2/4",
        "key:kinetic.rigid.axle_turning_forgotten",
    ),
    ("massive-pulley", "acceleration", "z", "2*(m1 - m2)*g/(2*m1 + 2*m2 + M)", "correct", None, None),
    # beyond the chapter: the double pendulum and two masses between three springs
    (
        "double-pendulum",
        "kinetic",
        None,
        "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2",
        "incorrect",
        "-m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2)",
        "key:kinetic.cross_term.theta1_dot.theta2_dot",
    ),
    (
        "double-pendulum",
        "kinetic",
        None,
        "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2 + m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2)",
        "correct",
        None,
        None,
    ),
    (
        "coupled-oscillators",
        "potential",
        None,
        "k*(x1**2 + x2**2)/2 + kappa*(x2 - x1)**2/2 + 7",
        "incorrect",
        None,
        "units",
    ),
    ("coupled-oscillators", "equation", "x1", "m*x1_ddot + (k + kappa)*x1 - kappa*x2", "correct", None, None),
    (
        "coupled-oscillators",
        "equation",
        "x1",
        "m*x1_ddot + k*x1",
        "incorrect",
        "kappa*(x2 - x1)",
        "key:equation.force_left_out.kappa_x1_x2",
    ),
]

# Typical mistakes, each with the diagnosis (the mistake's key) the checker must name.
TYPICAL = [
    ("simple-pendulum", "equation", "theta", "m*R**2*theta_ddot + m*g*R*theta", "equation.small_angle"),
    # d/dt(½ m R² θ̇²) taken as ½ m R² θ̈: the 2 of the square lost, not a force counted twice
    ("simple-pendulum", "equation", "theta", "m*R**2*theta_ddot/2 + m*g*R*sin(theta)", "equation.half_momentum"),
    ("simple-pendulum", "potential", None, "m*g*R*cos(theta)", "sign_of_u"),
    (
        "damped-pendulum",
        "equation",
        "theta",
        "m*R**2*theta_ddot + m*g*R*sin(theta) - b*theta_dot",
        "equation.force_sign",
    ),
    ("damped-pendulum", "equation", "theta", "m*R**2*theta_ddot + b*theta_dot", "equation.force_left_out.R_g_m_theta"),
    ("damped-pendulum", "equation", "theta", "m*R**2*theta_ddot + m*g*R*sin(theta)", "forgot_force"),
    ("helix-bead", "kinetic", None, "m*z_dot**2/2", "kinetic.velocity_axis.bead.xy"),
    ("helix-bead", "kinetic", None, "m*R**2*alpha**2*z_dot**2/2", "kinetic.velocity_axis.bead.z"),
    ("helix-bead", "potential", None, "-m*g*z", "sign_of_u"),
    ("incline-block", "kinetic", None, "m*X_dot**2*cos(alpha)**2/2", "kinetic.velocity_axis.block.z"),
    ("incline-block", "equation", "X", "m*X_ddot", "equation.force_left_out.X_alpha_g_m"),
    ("incline-block", "acceleration", "X", "g*sin(alpha)", "acceleration.whole_sign"),
    ("tabletop-spring", "kinetic", None, "m*r_dot**2/2", "kinetic.velocity_part.particle.theta"),
    ("tabletop-spring", "equation", "r", "m*r_ddot + k*r", "equation.dl_dq_part.theta_dot_2"),
    ("tabletop-spring", "equation", "theta", "m*r**2*theta_ddot", "equation.chain_rule.r"),
    # the spherical pendulum without the φ̇ part of the ball's velocity, R sin θ φ̇
    ("spherical-pendulum", "kinetic", None, "m*R**2*theta_dot**2/2", "kinetic.velocity_part.ball.phi"),
    (
        "spherical-pendulum",
        "equation",
        "theta",
        "m*R**2*theta_ddot - m*g*R*sin(theta)",
        "equation.dl_dq_part.phi_dot_2",
    ),
    ("spherical-pendulum", "equation", "phi", "R**2*m*sin(theta)**2*phi_ddot", "equation.chain_rule.theta"),
    ("rail-two-body", "potential", None, "k*(x2 - x1)**2/2", "potential.natural_length.k_l0_x1_x2"),
    ("rail-two-body", "kinetic", None, "m1*x1_dot**2/2", "kinetic.body_forgotten.mass_2"),
    ("rail-two-body", "equation", "x1", "m1*x1_ddot", "equation.force_left_out.k_l0_x1_x2"),
    ("pulley", "kinetic", None, "m1*y1_dot**2/2 + m2*y2_dot**2/2", "kinetic.body_forgotten.middle_mass"),
    ("pulley", "potential", None, "m1*g*y1 + m2*g*y2 + M*g*(y1 + y2)/2", "potential.term_sign.M_g_y1_y2"),
    ("pulley", "potential", None, "m1*g*y1 + m2*g*y2", "potential.term_left_out.M_g_y1_y2"),
    # the wedge's Ẋ left out of the block's velocity
    ("movable-incline", "kinetic", None, "M*X_dot**2/2 + m*D_dot**2/2", "kinetic.velocity_part.block.X"),
    ("movable-incline", "kinetic", None, "M*X_dot**2/2", "kinetic.body_forgotten.block"),
    ("movable-incline", "potential", None, "m*g*D*sin(alpha)", "sign_of_u"),
    # the rotating parabola without ω ρ, the example's whole point
    ("rotating-parabola", "kinetic", None, "m*rho_dot**2*(1 + 4*alpha**2*rho**2)/2", "kinetic.moving_constraint.bead"),
    ("rotating-parabola", "kinetic", None, "m*(rho_dot**2 + omega**2*rho**2)/2", "kinetic.velocity_axis.bead.z"),
    (
        "rotating-parabola",
        "hamiltonian",
        None,
        "m*rho_dot**2*(1 + 4*alpha**2*rho**2)/2 + m*omega**2*rho**2/2 + alpha*g*m*rho**2",
        "h_is_e",
    ),
    ("coupled-oscillators", "potential", None, "k*(x1**2 + x2**2)/2", "potential.term_left_out.kappa_x1_x2"),
    ("coupled-oscillators", "kinetic", None, "m*x1_dot**2/2", "kinetic.body_forgotten.right_mass"),
    ("coupled-oscillators", "equation", "x2", "m*x2_ddot + k*x2", "equation.force_left_out.kappa_x1_x2"),
    (
        "double-pendulum",
        "kinetic",
        None,
        "m1*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2",
        "kinetic.velocity_part.lower_bob.theta1",
    ),
    # the θ̇₁² term of the θ₂ equation, and the θ̇₂² term of the θ₁ equation, left out
    (
        "double-pendulum",
        "equation",
        "theta2",
        "m2*l2**2*theta2_ddot + m2*l1*l2*cos(theta1 - theta2)*theta1_ddot + m2*g*l2*sin(theta2)",
        "equation.chain_rule.theta1",
    ),
    (
        "double-pendulum",
        "equation",
        "theta1",
        "(m1 + m2)*l1**2*theta1_ddot + m2*l1*l2*cos(theta1 - theta2)*theta2_ddot + (m1 + m2)*g*l1*sin(theta1)",
        "equation.chain_rule.theta2",
    ),
    # the cylinder rolling on a sliding wedge: its turning forgotten, taken as a hoop, the wedge's motion left out of
    # its velocity, each carried into the equation for s
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2",
        "kinetic.rigid.turning_forgotten.0",
    ),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2 + m*s_dot**2/2",
        "kinetic.rigid.taken_as_ring.0",
    ),
    ("rolling-cylinder-wedge", "kinetic", None, "M*X_dot**2/2 + 3*m*s_dot**2/4", "kinetic.rigid.carrier_left_out.0.0"),
    (
        "rolling-cylinder-wedge",
        "equation",
        "s",
        "m*s_ddot + m*X_ddot*cos(alpha) - m*g*sin(alpha)",
        "equation.rigid.turning_forgotten.0",
    ),
    # the rod's spin about its centre forgotten, its I about the centre put for its I about the pivot, the rod
    # taken as a bob at its end
    ("physical-pendulum", "kinetic", None, "M*l**2*theta_dot**2/8", "kinetic.rigid.rod_spin_forgotten"),
    ("physical-pendulum", "kinetic", None, "M*l**2*theta_dot**2/24", "kinetic.rigid.rod_centre_axis"),
    ("physical-pendulum", "kinetic", None, "M*l**2*theta_dot**2/2", "kinetic.rigid.rod_point_mass"),
    # another kind's I_cm for the rod's, the cylinder's, the pulley's (review prof-q 7): a disc's, a sphere's
    ("physical-pendulum", "kinetic", None, "3*M*l**2*theta_dot**2/8", "kinetic.rigid.rod_taken_as_disc"),
    (
        "rolling-cylinder-wedge",
        "kinetic",
        None,
        "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2 + m*s_dot**2/5",
        "kinetic.rigid.taken_as_sphere.0",
    ),
    # the pulley's turning forgotten, the pulley taken as a ring (or its mass as moving with the string), its centre
    # taken to move with the string, one mass's U with the wrong sign, the turning forgotten carried into ÿ and p
    ("massive-pulley", "kinetic", None, "(m1 + m2)*z_dot**2/2", "kinetic.rigid.axle_turning_forgotten"),
    ("massive-pulley", "kinetic", None, "(m1 + m2 + M)*z_dot**2/2", "kinetic.rigid.axle_ring"),
    ("massive-pulley", "kinetic", None, "(m1 + m2)*z_dot**2/2 + 3*M*z_dot**2/4", "kinetic.rigid.axle_centre_moving"),
    ("massive-pulley", "potential", None, "-(m1 + m2)*g*z", "potential.piece.sign.g_m2_z"),
    ("massive-pulley", "acceleration", "z", "(m1 - m2)*g/(m1 + m2)", "acceleration.rigid.axle_turning_forgotten"),
    ("massive-pulley", "momentum", "z", "(m1 + m2)*z_dot", "momentum.rigid.axle_turning_forgotten"),
    ("cart-pendulum", "kinetic", None, "M*x_dot**2/2 + m*l**2*phi_dot**2/2", "kinetic.velocity_part.bob.x"),
    (
        "cart-pendulum",
        "equation",
        "x",
        "(M + m)*x_ddot + m*l*cos(phi)*phi_ddot - m*l*sin(phi)*phi_dot**2 + k*x",
        "forgot_force",
    ),
    ("cart-pendulum", "equation", "phi", "m*l**2*phi_ddot + m*l*x_ddot + m*g*l*phi", "equation.small_angle"),
    ("spring-rod", "equation", "r", "m*r_ddot + k*(r - a)", "equation.dl_dq_part.m_r_r_dot_w"),
    ("spring-rod", "hamiltonian", None, "m*(r_dot**2 + w**2*r**2)/2 - k*(r - a)**2/2", "h_is_l"),
    ("spring-rod", "omega_squared", None, "sqrt(k/m - w**2)", "omega_not_squared"),
]
