"""Blocks on frictionless inclines: a fixed one, and a wedge free to slide on the floor; and a cylinder rolling
on such a wedge."""

from app.scenes import reasons
from app.scenes.common import GRAVITY
from app.scenes.types import Body, Constraint, Erratum, Event, Parameter, Particle, Scene, System

MASS = Parameter("m", 1.0, "kg", 0.001, 1000.0, "mass of the block")
ANGLE = Parameter("alpha", 0.5, "rad", 0.01, 1.5, "angle of the incline above the horizontal")

INCLINE_BLOCK = Scene(
    id="incline-block",
    coordinate_meanings={
        "X": "distance of the block up the slope from the foot of the ramp",
    },
    title="Block on a fixed incline",
    section="4.3",
    family="incline",
    reasons=reasons.INCLINE_BLOCK,
    summary="Newton's law along a slope recovered from L = T − U with a single coordinate.",
    statement=(
        "A block of mass m slides without friction on a plane tilted at the angle α to the horizontal; the plane "
        "is fixed. X is the distance of the block up the slope from the foot of the ramp. Heights are measured upward "
        "from the foot of the ramp, where U = 0. Find the Lagrangian, the "
        "equation of motion and the normal force of the plane."
    ),
    figure="A right-angled ramp rising at angle α, the block on its slope at distance X from the foot, X pointing uphill.",
    system=System(
        coordinates=("X",),
        parameters=(MASS, GRAVITY, ANGLE),
        particles=(Particle("m", ("X*cos(alpha)", "0", "X*sin(alpha)"), "block"),),
        potential="m*g*X*sin(alpha)",
        cartesian_potential="m*g*z",
        constraints=(
            Constraint(
                "normal force",
                "cos(alpha)*z - sin(alpha)*x",
                "The plane's push on the block, perpendicular to the slope and positive away from it; a negative "
                "value would mean the plane has to pull, so the block would leave it.",
                slack_when_negative=True,
            ),
        ),
    ),
    initial={"X": 0.0, "X_dot": 3.0},
    t_end=2.0,
    # X = 0 is the foot of the ramp: below it the block would be on the floor, which the model does not have
    events=(Event("foot of the ramp", "X", "The block reached the foot of the ramp; the run ends there."),),
    errata=(
        Erratum(
            # words only: the chapter's mistake here is its statement, not a formula
            chapter="The statement of the helix bead problem, repeated word for word.",
            correct="L = m*X_dot**2/2 - m*g*X*sin(alpha)",
            reason=(
                "The example's statement repeats the helix bead problem before it word for word, while its solution treats "
                "a block on a fixed frictionless incline; that block's Lagrangian is the one given here."
            ),
            check="lagrangian",
            words=True,
        ),
        Erratum(
            chapter="m a = -m g sin(alpha) in the horizontal direction",
            correct="X_ddot = -g*sin(alpha)",
            reason=(
                "The acceleration −g sin α is along the slope, the direction X measures; its horizontal part is "
                "only −g sin α cos α."
            ),
            check="acceleration:X",
        ),
    ),
)

MOVABLE_INCLINE = Scene(
    id="movable-incline",
    coordinate_meanings={
        "X": "displacement of the wedge along the floor from where it started",
        "D": "distance of the block down the slope from the wedge's top corner",
    },
    title="Block on a sliding wedge",
    section="4.5",
    family="wedge",
    reasons=reasons.MOVABLE_INCLINE,
    summary="Two bodies, two coordinates: the wedge recoils, and its conserved momentum shapes the block's fall.",
    statement=(
        "A block of mass m slides without friction down the slope of a wedge of mass M and angle α; the wedge "
        "itself slides without friction on a horizontal floor. X is the horizontal displacement of the wedge and "
        "D the distance the block has slid down the slope, so the block sits at x = X + D cos α across and at "
        "height z = −D sin α, measured from where the wedge's top corner started. "
        "Heights are measured upward, and U = 0 with the block at that corner (D = 0); the wedge does not rise or "
        "fall. Find the accelerations of both, and the normal forces of the wedge "
        "on the block and of the floor on the wedge."
    ),
    figure=(
        "A wedge of angle α on a floor, its top corner displaced by X; the block on the slope at distance D below "
        "the corner along the slope; arrows mark D along the slope and X from where the wedge started, and g."
    ),
    system=System(
        coordinates=("X", "D"),
        parameters=(MASS, Parameter("M", 3.0, "kg", 0.001, 1000.0, "mass of the wedge"), GRAVITY, ANGLE),
        # the wedge's top corner, and the block on its slope
        particles=(
            Particle("M", ("X", "0", "0"), "wedge"),
            Particle("m", ("X + D*cos(alpha)", "0", "-D*sin(alpha)"), "block"),
        ),
        potential="-m*g*D*sin(alpha)",
        cartesian_potential="M*g*z1 + m*g*z2",
        constraints=(
            Constraint(
                "normal force on the block",
                "sin(alpha)*(x2 - x1) + cos(alpha)*(z2 - z1)",
                "The wedge's push on the block, perpendicular to the slope and positive away from it (the block "
                "pushes the wedge back with the opposite force); negative would mean the block lifts off.",
                on=2,
                slack_when_negative=True,
            ),
            Constraint(
                "floor force on the wedge",
                "z1",
                "The floor's upward push on the wedge; negative would mean the wedge lifts off the floor.",
                on=1,
                slack_when_negative=True,
            ),
        ),
    ),
    initial={"X": 0.0, "X_dot": 0.0, "D": 0.0, "D_dot": 0.0},
    t_end=1.5,
    # D = 0 is the wedge's top corner: above it the block would leave the slope, which the model does not have
    events=(Event("top corner", "D", "The block reached the wedge's top corner and leaves its slope; the run ends there."),),
    errata=(
        Erratum(
            chapter="x = X_dot + D cos(alpha)",
            correct="x = X + D*cos(alpha)",
            reason=(
                "A position adds the wedge's displacement X, not its velocity; differentiating the corrected "
                "position gives the chapter's (right) ẋ = Ẋ + Ḋ cos α."
            ),
            check="position:2:x",
        ),
        Erratum(
            chapter="U = U_plane - m g y",
            correct="U = m*g*z = -m*g*D*sin(alpha)",
            reason=(
                "With z the block's height (the chapter's y) its potential energy is +m g z; the chapter's own Lagrangian, with "
                "+m g D sin α, already uses this sign."
            ),
            check="potential",
        ),
        Erratum(
            chapter="0 = m g sin(alpha) - m X_ddot cos(alpha) + m D_ddot",
            correct="0 = m*g*sin(alpha) - m*X_ddot*cos(alpha) - m*D_ddot",
            reason=(
                "The whole of d/dt ∂L/∂Ḋ = m Ẍ cos α + m D̈ is subtracted, so D̈ enters with a minus sign; the "
                "chapter's next line has the right signs again."
            ),
            check="equation:D",
        ),
        Erratum(
            chapter="y_ddot = -D_ddot cos(alpha)",
            correct="z_ddot = -D_ddot*sin(alpha) = -(M + m)*g*sin(alpha)**2/(M + m*sin(alpha)**2)",
            reason=(
                "The block's height (the chapter's y) is z = −D sin α, so z̈ = −D̈ sin α; the chapter's final line "
                "does use sin² α."
            ),
            check="point-acceleration:2:z",
        ),
    ),
)

ROLLING_CYLINDER_WEDGE = Scene(
    id="rolling-cylinder-wedge",
    coordinate_meanings={
        "X": "displacement of the wedge along the floor from where it started",
        "s": "distance the cylinder's centre has moved down the slope, measured along the wedge from where it started",
    },
    title="Cylinder rolling on a sliding wedge",
    section="4.5",
    family="rolling-wedge",
    reasons=reasons.ROLLING_CYLINDER_WEDGE,
    beyond_chapter=True,
    # the comparison the statement asks for, with a block and with a fixed wedge, first in the Results
    answers=("comparison",),
    summary="The sliding wedge again, with a cylinder that rolls: part of its energy goes into turning, and it falls slower.",
    statement=(
        "A uniform solid cylinder of mass m and radius r rolls without slipping down the slope of a wedge of mass M "
        "and angle α; the wedge slides without friction on a horizontal floor. X is the horizontal displacement of "
        "the wedge from where it started, and s the distance the cylinder's centre has moved down the slope, "
        "measured along the wedge; rolling without slipping, the cylinder has turned through the angle s/r. "
        "Heights are measured upward, and U = 0 with the cylinder where it started (s = 0); the wedge does not rise "
        "or fall. Find the accelerations of the cylinder along the slope and of the wedge, say which momentum is "
        "conserved, and compare them with those of a block that slides without friction on the same wedge."
    ),
    figure=(
        "A wedge of angle α on a floor, its top corner displaced by X; a cylinder of radius r resting on the slope, "
        "its centre s down the slope from where it started, turned by s/r as it rolls; arrows mark s along the slope "
        "and X from where the wedge started, and g."
    ),
    system=System(
        coordinates=("X", "s"),
        parameters=(
            Parameter("m", 1.0, "kg", 0.001, 1000.0, "mass of the cylinder"),
            Parameter("M", 3.0, "kg", 0.001, 1000.0, "mass of the wedge"),
            Parameter("r", 0.3, "m", 0.01, 10.0, "radius of the cylinder"),
            GRAVITY,
            ANGLE,
        ),
        # the wedge's top corner, as for the sliding wedge
        particles=(Particle("M", ("X", "0", "0"), "wedge"),),
        # the centre is s down the slope from the corner and r out from the slope along its normal (sin α, cos α);
        # rolling down the slope, to the right in the picture, the cylinder turns clockwise: its angle is −s/r
        bodies=(
            Body(
                "disc",
                "m",
                "r",
                ("X + s*cos(alpha) + r*sin(alpha)", "0", "r*cos(alpha) - s*sin(alpha)"),
                "-s/r",
                "cylinder",
            ),
        ),
        potential="-m*g*s*sin(alpha)",
    ),
    initial={"X": 0.0, "X_dot": 0.0, "s": 0.0, "s_dot": 0.0},
    t_end=1.5,
    # s = 0 puts the cylinder against the top corner: above it the cylinder would leave the slope
    events=(
        Event(
            "top corner", "s", "The cylinder reached the wedge's top corner and leaves its slope; the run ends there."
        ),
    ),
)
