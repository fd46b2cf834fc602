"""Beads on wires: a fixed helix, and a parabola spun about its axis (a moving constraint)."""

from app.scenes import reasons
from app.scenes.common import GRAVITY
from app.scenes.types import Constraint, Erratum, Event, Parameter, Particle, Scene, System

MASS = Parameter("m", 0.1, "kg", 0.001, 100.0, "mass of the bead")
# the rotating wire is finite: its two ends lie this far from the axis, at ρ = ±WIRE_REACH (in metres); a bead
# that the turning flings outward leaves the wire there, and the run ends (the animation draws the wire to them)
WIRE_REACH = 1.0
# the reach in words: "m" is the bead's mass in this statement, so the unit is written out
REACH_WORDS = f"{WIRE_REACH:g} metre" + ("" if WIRE_REACH == 1 else "s")

HELIX_BEAD = Scene(
    id="helix-bead",
    coordinate_meanings={
        "z": "height of the bead on the helix",
    },
    title="Bead on a vertical helix",
    section="4.3",
    family="helix",
    reasons=reasons.HELIX_BEAD,
    summary="A wire leaves one degree of freedom: the height z, along which the winding adds inertia, not weight.",
    statement=(
        "A bead of mass m slides without friction along a wire bent into a helix of radius R whose axis is "
        "vertical. Going up the wire, the bead turns about the axis by the angle φ = α z, so α sets how tightly "
        "the helix is wound. Heights z are measured upward, with U = 0 at z = 0. Using the height z as the "
        "only coordinate, find the Lagrangian, the equation of "
        "motion and the forces the wire exerts on the bead."
    ),
    figure=(
        "A helix of radius R wound round a vertical axis, the bead on it at height z and azimuth φ = α z, "
        "gravity pointing down along the axis."
    ),
    system=System(
        coordinates=("z",),
        parameters=(
            MASS,
            GRAVITY,
            Parameter("R", 0.5, "m", 0.01, 10.0, "radius of the helix"),
            Parameter("alpha", 4.0, "rad/m", 0.01, 100.0, "winding of the helix: φ = α z, in radians of turn per metre of height"),
        ),
        particles=(Particle("m", ("R*cos(alpha*z)", "R*sin(alpha*z)", "z"), "bead"),),
        potential="m*g*z",
        cartesian_potential="m*g*z",
        # The wire is a curve, the meeting of two surfaces: the cylinder of radius R and the
        # twisted surface that holds the bead at azimuth alpha*z.  Each pushes along its normal.
        constraints=(
            Constraint(
                "wire force toward the axis",
                "R**2 - x**2 - y**2",
                "The wire's push on the bead perpendicular to the cylinder, positive toward the axis "
                "(it supplies the centripetal force of the turning bead).",
            ),
            Constraint(
                "wire force across the helix",
                "x*sin(alpha*z) - y*cos(alpha*z)",
                "The wire's push within the cylinder's surface and perpendicular to the wire, positive when it "
                "points upward (it holds the bead up against the part of gravity the slope does not take).",
            ),
        ),
    ),
    initial={"z": 0.0, "z_dot": 3.0},
    t_end=4.0,
)

ROTATING_PARABOLA = Scene(
    id="rotating-parabola",
    coordinate_meanings={
        "rho": "signed distance of the bead from the axis, negative on the other branch of the wire",
    },
    title="Bead on a rotating parabolic wire",
    section="4.6–4.7",
    family="rotating-wire",
    reasons=reasons.ROTATING_PARABOLA,
    summary="A constraint that moves with time: the energy function h is conserved while the energy E is not.",
    statement=(
        "A wire shaped as the parabola z = α ρ² (ρ the signed horizontal distance from the vertical axis, "
        "positive on one branch of the wire and negative on the other) is turned about that axis "
        "by a motor at the constant rate ω; at t = 0 the wire lies in the x–z plane, its branch ρ > 0 along +x, "
        "so that the wire's plane makes the angle ω t with the x axis. A bead of mass m slides on it without "
        "friction. Heights z are "
        "measured upward from the bottom of the parabola, where U = 0. The wire ends "
        f"{REACH_WORDS} from the axis on either side (ρ = ±{REACH_WORDS}): a bead that reaches an end flies "
        "off, and the motion studied here ends there. With ρ as the "
        "coordinate, derive the equation of motion, compare the energy function h with the energy E, and explain "
        "which one is conserved."
    ),
    figure=(
        "A vertical axis with a parabolic wire through its lowest point, turning at rate ω; the bead on the wire "
        "at distance ρ from the axis and height α ρ²."
    ),
    system=System(
        coordinates=("rho",),
        parameters=(
            MASS,
            GRAVITY,
            Parameter("alpha", 1.0, "1/m", 0.01, 100.0, "shape coefficient of the wire, z = α ρ² (its curvature at the bottom is 2α)"),
            Parameter("omega", 4.0, "rad/s", 0.0, 100.0, "angular velocity of the wire about its axis"),
        ),
        # The wire's plane turns at the rate omega: phi = omega t is imposed, so the position depends on t.
        particles=(Particle("m", ("rho*cos(omega*t)", "rho*sin(omega*t)", "alpha*rho**2"), "bead"),),
        potential="m*g*alpha*rho**2",
        cartesian_potential="m*g*z",
        constraints=(
            Constraint(
                "wire force in its plane",
                "z - alpha*(x**2 + y**2)",
                "The wire's push perpendicular to it within the turning vertical plane, positive on the upper "
                "(concave) side of the parabola.",
            ),
            Constraint(
                "wire force across its plane",
                "y*cos(omega*t) - x*sin(omega*t)",
                "The wire's push perpendicular to its turning plane, positive in the sense of rotation (it is what "
                "drags the bead round, and it does the work that changes E).",
            ),
        ),
    ),
    # a small swing: the bead's inertia along the wire is m(1 + 4α²ρ²), so from ρ = 0.5 m (4α²ρ² = 1) the swing ran
    # 18 % slower than the small-oscillation Ω; from 0.15 m (4α²ρ² = 0.09) it is 2.2 % slower
    initial={"rho": 0.15, "rho_dot": 0.0},
    t_end=10.0,
    # ρ² < WIRE_REACH²: the bead is still on the wire
    events=(
        Event("end of the wire", f"{WIRE_REACH!r}**2 - rho**2", "The bead reached the end of the wire; the run ends there."),
    ),
    panels=("effective-potential", "small-oscillations"),
    errata=(
        Erratum(
            # the chapter's H is this page's h (its Hamiltonian, written in the velocities)
            chapter="H = E if ∂r/∂t = 0 (the particle is not moving)",
            correct="E - h = m*omega**2*rho**2",
            reason=(
                "The chapter's H is the energy function h of this page. ∂r/∂t = 0 asks that the constraint stand "
                "still, not the particle: here the wire turns, ∂r/∂t ≠ 0, and E − h = p·∂r/∂t = m ω² ρ² even for "
                "a bead at rest on the wire."
            ),
            check="energy-minus-h",
        ),
    ),
)
