"""Central forces and systems of particles: the tabletop spring, the two-body rail, the pulleys."""

from app.scenes import reasons
from app.scenes.common import GRAVITY
from app.scenes.types import Constraint, CoordinateChange, Erratum, Parameter, Particle, Scene, System

# U_eff written out for the tabletop, used in the errata formulas below
_U_EFF = "p_theta**2/(2*m*r**2) + k*r**2/2"

TABLETOP_SPRING = Scene(
    id="tabletop-spring",
    coordinate_meanings={
        "r": "distance of the particle from the fixed centre",
        "theta": "angle of the particle about the fixed centre",
    },
    title="Particle on a tabletop with a central spring",
    section="4.4",
    family="tabletop-spring",
    reasons=reasons.TABLETOP_SPRING,
    # the time as an integral over r, the circular orbit and its radial frequency
    answers=("time-integral", "reduced-equilibria"),
    # the isotropic oscillator: x and y each oscillate at √(k/m), so r² = x² + y² returns at twice that rate; r itself
    # is periodic but not sinusoidal (only the frequency is exact)
    exact_frequency=(
        "Here the frequency is exact at every amplitude: the particle's x and y each oscillate at √(k/m), so r "
        "returns at 2√(k/m) however far it swings. The motion in r is periodic but not a sine wave, so away from "
        "small swings its shape differs from the dashed curve; only the frequency is exact."
    ),
    summary="A cyclic angle conserves angular momentum and folds the orbit into one radial coordinate.",
    statement=(
        "A particle of mass m moves on a frictionless horizontal table, tied to a fixed point of the table by a "
        "spring of zero rest length that pulls it toward that point with force −k r; U = 0 with the particle at "
        "that point, where the spring is unstretched. In polar coordinates (r, θ) "
        "about that point, derive the equations of motion, the conserved angular momentum, the effective "
        "potential, the energy integral and the time as an integral over r; then find the radius of the "
        "circular orbit for a given angular momentum and the frequency of small radial oscillations about it."
    ),
    figure="A table seen from above: the fixed centre, the particle at distance r and angle θ, a spring between them.",
    system=System(
        coordinates=("r", "theta"),
        parameters=(
            Parameter("m", 1.0, "kg", 0.01, 100.0, "mass of the particle"),
            Parameter("k", 4.0, "N/m", 0.01, 1000.0, "spring constant"),  # a tabletop spring, soft to stiff
        ),
        particles=(Particle("m", ("r*cos(theta)", "r*sin(theta)", "0"), "particle"),),
        potential="k*r**2/2",
        nonnegative=("r",),
    ),
    initial={"r": 1.0, "r_dot": 0.0, "theta": 0.0, "theta_dot": 1.0},
    t_end=10.0,
    panels=("effective-potential", "small-oscillations"),
    errata=(
        Erratum(
            chapter="F(r) = k r r_hat toward the origin; later F(r) = dU/dr = -k r",
            correct="F_r = -dU/dr = -k*r",
            reason=(
                "k r r̂ points away from the centre. A spring pulling inward is −k r r̂, the negative gradient of "
                "U = k r²/2, whose derivative dU/dr is +k r."
            ),
            check="potential-force:r",
        ),
        Erratum(
            chapter="F(r) = m r_ddot is the central force",
            correct="m*r_ddot = p_theta**2/(m*r**3) - k*r",
            reason=(
                "m r̈ also holds the centrifugal term p_θ²/(m r³): it equals the effective force −dU_eff/dr, of "
                "which the central force −k r is only a part."
            ),
            check="reduced-force:r",
        ),
        Erratum(
            chapter="r_dot = sqrt(2E/m - U_eff(r))",
            # E is the energy, the constant of this first integral; both signs of the root are motions
            correct=f"r_dot = ±sqrt(2*(E - ({_U_EFF}))/m)",
            reason="Solving E = m ṙ²/2 + U_eff for ṙ divides U_eff by m as well: ṙ = ±√(2(E − U_eff)/m).",
            check="radial-speed:r",
        ),
        Erratum(
            chapter="t = integral of sqrt(2E/m - U_eff(r)) dr",
            correct=f"dt/dr = ±1/sqrt(2*(E - ({_U_EFF}))/m)",
            reason="Separating dr/dt = ṙ(r) gives dt = dr/ṙ(r): the square root belongs in the denominator.",
            check="time-integrand",
        ),
        Erratum(
            chapter="Taylor series: U_eff(q0) + U_eff'(q0)(q - q0) + U_eff''(q0)(q - q0)^2",
            correct="coefficient of (r - r0)**2 = U_eff''(r0)/2 = 2*k",
            reason=(
                "Taylor's second-order term carries 1/2, which is what makes it k_eff (q − q0)²/2 with "
                "k_eff = U_eff''; for the tabletop orbit U_eff''(r0) = 4k."
            ),
            check="taylor-coefficient:0",
        ),
        Erratum(
            chapter="omega = sqrt(k_eff/m) = sqrt(U_eff'')",
            correct="omega**2 = U_eff''(r0)/m = 4*k/m",
            reason=(
                "The effective spring constant must still be divided by the mass. About the circular orbit "
                "ω = 2√(k/m), twice the orbital angular velocity √(k/m)."
            ),
            check="omega-squared:0",
        ),
    ),
)

RAIL_TWO_BODY = Scene(
    id="rail-two-body",
    coordinate_meanings={
        "x1": "position of mass m1 along the rail, from a fixed mark",
        "x2": "position of mass m2 along the rail, from a fixed mark",
    },
    title="Two masses on a rail joined by a spring",
    section="4.5",
    family="two-body-rail",
    reasons=reasons.RAIL_TWO_BODY,
    summary="Centre of mass and relative coordinate: one cyclic, one oscillating with the reduced mass.",
    statement=(
        "Two masses m1 and m2 slide without friction on a straight horizontal rail, at positions x1 and x2, joined "
        "by a spring of stiffness k and rest length l0; U = 0 when the spring has its rest length. "
        "Derive the equations of motion; then change to the centre "
        "of mass X and the separation x = x2 − x1 and show that X is cyclic, that the total momentum is "
        "conserved and that x oscillates like a single body of the reduced mass."
    ),
    figure=(
        "A horizontal rail with two masses m1 and m2 at x1 and x2, measured from a fixed mark, and a spring of "
        "stiffness k and rest length l0 between them."
    ),
    system=System(
        coordinates=("x1", "x2"),
        parameters=(
            Parameter("m1", 1.0, "kg", 0.01, 100.0, "mass at x₁"),
            Parameter("m2", 2.0, "kg", 0.01, 100.0, "mass at x₂"),
            Parameter("k", 10.0, "N/m", 0.01, 1.0e8, "spring constant"),
            Parameter("l0", 1.0, "m", 0.0, 100.0, "rest length of the spring"),
        ),
        particles=(Particle("m1", ("x1", "0", "0"), "mass 1"), Particle("m2", ("x2", "0", "0"), "mass 2")),
        potential="k*(x2 - x1 - l0)**2/2",
        coordinate_change=CoordinateChange(
            coordinates=("X", "x"),
            definitions=("(m1*x1 + m2*x2)/(m1 + m2)", "x2 - x1"),
            explanation=(
                "The centre of mass moves with the total mass; the separation carries the spring's energy alone."
            ),
            relative="x",
        ),
    ),
    initial={"x1": 0.0, "x1_dot": 0.5, "x2": 1.5, "x2_dot": 0.0},
    t_end=10.0,
    errata=(
        Erratum(
            # the chapter prints the two derivatives with nothing to differentiate, and equal rather than opposite
            chapter="action-reaction pairs ∂/∂x1 = ∂/∂x2",
            correct="∂L/∂x1 = -∂L/∂x2 = k*(x2 - x1 - l0)",
            reason=(
                "The chapter's ∂/∂x₁ = ∂/∂x₂ says neither what is differentiated nor with which sign. U depends on "
                "x₂ − x₁ only, so ∂L/∂x₁ = −∂L/∂x₂: the spring's forces on the two masses are equal and opposite, "
                "and cancel in the total momentum."
            ),
            check="dL/dq:x1",
        ),
        Erratum(
            chapter="P = ∂L/∂X_dot = M m1_dot x1_dot + m2 x2_dot",
            correct="P = (m1 + m2)*X_dot = m1*x1_dot + m2*x2_dot",
            reason=(
                "As printed, the chapter's right side has a dot on the mass m₁ (a mass does not change) and an M "
                "it never defines (the total mass, it seems). The momentum conjugate to the centre of mass is the "
                "total mass m₁ + m₂ times its velocity: the total momentum."
            ),
            check="transformed-momentum:X",
        ),
    ),
)

PULLEY = Scene(
    id="pulley",
    coordinate_meanings={
        "y1": "height of mass m1, measured upward",
        "y2": "height of mass m2, measured upward",
    },
    title="Three masses on pulleys",
    section="4.5",
    family="pulleys",
    reasons=reasons.PULLEY,
    summary="A string's fixed length removes a coordinate; two Euler–Lagrange equations give all three accelerations.",
    statement=(
        "A string runs over two fixed pulleys; its ends carry masses m1 and m2, each a horizontal distance d from "
        "the middle, and the loop between the pulleys holds a third, movable pulley from which a mass M hangs. "
        "Pulleys and string are massless, the string does not stretch, and every strand hangs vertically. Heights "
        "are measured upward from the "
        "level where U = 0, the end masses' level when y1 = y2 = 0. With the heights y1 and y2 of the end masses "
        "as coordinates, the string fixes the middle mass's height at Y = −(y1 + y2)/2 − c, where c, set by the "
        "string's length, is how far below that level M hangs when y1 = y2 = 0. Find the accelerations of all "
        "three masses and the tension in the string."
    ),
    figure=(
        "Two fixed pulleys at the top; m1 hangs on the left end, m2 on the right end, each a distance d from the "
        "middle, and the string's loop between them carries a movable pulley with M below it, every strand "
        "vertical; heights y1, y2, Y "
        "measured upward from the dashed line where U = 0, M below it (Y < 0); c reaches down from that line to "
        "the short dashed level where M would hang with y1 = y2 = 0."
    ),
    system=System(
        coordinates=("y1", "y2"),
        parameters=(
            Parameter("m1", 1.0, "kg", 0.01, 100.0, "mass on the left end"),
            Parameter("m2", 2.0, "kg", 0.01, 100.0, "mass on the right end"),
            Parameter("M", 2.5, "kg", 0.01, 100.0, "mass under the movable pulley"),
            GRAVITY,
            Parameter("d", 1.0, "m", 0.1, 10.0, "horizontal distance of each end mass from the middle mass"),
            Parameter("c", 1.0, "m", 0.0, 100.0, "depth of the middle mass below the level U = 0 when y1 = y2 = 0"),
        ),
        # The string's length is (H − y1) + 2(H − Y) + (H − y2) plus the fixed lengths round the wheels, H the fixed
        # pulleys' height: so y1 + y2 + 2Y is a constant, written −2c, and Y = −(y1 + y2)/2 − c.
        particles=(
            Particle("m1", ("-d", "0", "y1"), "left mass"),
            Particle("m2", ("d", "0", "y2"), "right mass"),
            Particle("M", ("0", "0", "-(y1 + y2)/2 - c"), "middle mass"),
        ),
        potential="m1*g*y1 + m2*g*y2 - M*g*(y1 + y2)/2 - M*g*c",
        cartesian_potential="m1*g*z1 + m2*g*z2 + M*g*z3",
        constraints=(
            Constraint(
                "string tension",
                "z1 + z2 + 2*z3 + 2*c",
                "The string's upward pull on each end mass (the movable pulley gets twice it); negative would "
                "mean the string has to push, so it goes slack.",
                on=1,
                slack_when_negative=True,
            ),
        ),
    ),
    initial={"y1": 0.0, "y1_dot": 0.0, "y2": 0.0, "y2_dot": 0.0},
    dependent={"Y": ("-(y1 + y2)/2 - c", "height of the middle mass M, measured upward")},
    t_end=2.0,
    errata=(
        Erratum(
            chapter="y1_dot = -g + (-4 m2 g)/(m1 + m4 m1 m2/M)",
            correct="y1_ddot = -g + 4*m2*g/(m1 + m2 + 4*m1*m2/M)",
            reason=(
                "The left side is an acceleration, not a velocity. The chapter's denominator names a mass m₄ the "
                "set-up does not have (m₂ + 4 m₁ m₂/M run together, it seems); it is m₁ + m₂ + 4 m₁ m₂/M. And the "
                "fraction is positive: a heavy M hauls the end masses up."
            ),
            check="acceleration:y1",
        ),
        Erratum(
            chapter="y2_dot = -g + (-4 m1 g)/(m1 + m4 m1 m2/M)",
            correct="y2_ddot = -g + 4*m1*g/(m1 + m2 + 4*m1*m2/M)",
            reason=(
                "As for y₁ with the two end masses swapped: an acceleration, a positive fraction, and the "
                "denominator m₁ + m₂ + 4 m₁ m₂/M in place of the chapter's m₁ + m₄ m₁ m₂/M."
            ),
            check="acceleration:y2",
        ),
        Erratum(
            chapter="Y_dot = g - (2(m1 + m2) g)/(m1 + m4 m1 m2/M)",
            correct="Y_ddot = g - 2*(m1 + m2)*g/(m1 + m2 + 4*m1*m2/M)",
            reason=(
                "Again an acceleration (Ÿ = −(ÿ₁ + ÿ₂)/2), and the denominator is m₁ + m₂ + 4 m₁ m₂/M, "
                "the fraction's denominator over a common one: 4m₁m₂ + M(m₁ + m₂)."
            ),
            check="point-acceleration:3:z",
        ),
    ),
)
