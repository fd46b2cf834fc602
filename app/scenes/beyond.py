"""Scenes beyond the chapter: normal modes of two coordinates, beats, chaos, and rigid bodies."""

from app.scenes import reasons
from app.scenes.common import GRAVITY
from app.scenes.types import Body, Event, Parameter, Particle, Scene, System

# the double pendulum's default run, in seconds: within its tolerance to here (the reasons at its t_end below)
DOUBLE_PENDULUM_RUN = 3.0  # s: the default run, which the statement names

DOUBLE_PENDULUM = Scene(
    id="double-pendulum",
    coordinate_meanings={
        "theta1": "angle of the first rod from the downward vertical",
        "theta2": "angle of the second rod from the downward vertical",
    },
    title="Double pendulum",
    section="4.9",
    family="double-pendulum",
    # what the statement asks: the four equilibria and the modes about each, stated in Results
    answers=("equilibria", "normal-modes"),
    beyond_chapter=True,
    summary="Two normal modes at the bottom, three unstable equilibria above it, and chaos at high energy.",
    statement=(
        "A bob of mass m₁ hangs from a fixed pivot on a rigid massless rod of length l₁; a second bob of mass m₂ "
        "hangs from the first on a rod of length l₂. Both swing in one vertical plane, with θ₁ and θ₂ measured "
        "from the downward vertical. Heights are measured upward from the pivot, where U = 0. Derive the "
        "equations of motion, find the four equilibria and the normal "
        "modes about each, and follow a swing wide enough that the motion becomes chaotic."
    ),
    # the sentence on its largest Lyapunov exponent, measured at this start over 100 s, opens the note
    lyapunov_seconds=100.0,
    run_note=(
        f"The default run lasts {DOUBLE_PENDULUM_RUN:g} s and stays within its "
        "tolerance; a longer one, set under Integration, is one of many paths close to the true one, and the "
        "page then says by how much its error exceeds the tolerance."
    ),
    figure=(
        "A pivot at the top, a rod of length l₁ to the first bob at angle θ₁ from the downward vertical, a rod "
        "of length l₂ from it to the second bob at angle θ₂."
    ),
    system=System(
        coordinates=("theta1", "theta2"),
        parameters=(
            Parameter("m1", 1.0, "kg", 0.01, 100.0, "mass of the upper bob"),
            Parameter("m2", 1.0, "kg", 0.01, 100.0, "mass of the lower bob"),
            Parameter("l1", 1.0, "m", 0.05, 100.0, "length of the upper rod"),
            Parameter("l2", 1.0, "m", 0.05, 100.0, "length of the lower rod"),
            GRAVITY,
        ),
        # pivot at the origin, z upward
        particles=(
            Particle("m1", ("l1*sin(theta1)", "0", "-l1*cos(theta1)"), "upper bob"),
            Particle("m2", ("l1*sin(theta1) + l2*sin(theta2)", "0", "-l1*cos(theta1) - l2*cos(theta2)"), "lower bob"),
        ),
        potential="-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)",
    ),
    initial={"theta1": 2.0, "theta1_dot": 0.0, "theta2": 2.0, "theta2_dot": 0.0},
    # chaotic from this start (nearby runs part as e^(λt), λ measured over 100 s: lyapunov_seconds; the run
    # errors below grow 3.2 times a second):
    # every step's error grows with them, so
    # at the default tolerance the run's error is within it at 3 s, 4.4 times it at 5 s and 450 times at 10 s;
    # the default run stops at 3 s, within its tolerance (a longer one is the reader's choice, and the
    # statement says what it shows)
    t_end=DOUBLE_PENDULUM_RUN,
    panels=("poincare",),
    reasons=reasons.DOUBLE_PENDULUM,
)

COUPLED_OSCILLATORS = Scene(
    id="coupled-oscillators",
    coordinate_meanings={
        "x1": "displacement of the first mass from its rest position",
        "x2": "displacement of the second mass from its rest position",
    },
    title="Two masses between three springs",
    section="4.9",
    family="three-springs",
    # what the statement asks: the modes, their frequencies and the beats, stated in Results
    answers=("normal-modes", "beats"),
    beyond_chapter=True,
    summary="Two normal modes, in phase and in opposition; a weak coupling trades the energy back and forth in beats.",
    statement=(
        "Two equal masses m slide without friction on a horizontal line between two walls, which stand 3d either "
        "side of the middle; at rest each mass sits a distance d from the middle. Each is tied to its "
        "wall by a spring of stiffness k, and a third spring of stiffness κ joins them; all springs are relaxed, and U = 0, "
        "when x1 = x2 = 0, x1 and x2 being the displacements of the masses. Find the normal modes and their "
        "frequencies, and show that when κ is small and only one mass is displaced at first, the motion passes "
        "from one mass to the other at the difference of the two frequencies."
    ),
    figure=(
        "A wall, a spring k, the first mass, a spring κ, the second mass, a spring k, a wall; x1 and x2 measured "
        "from the masses' rest positions, d either side of the middle; the walls stand 3d from the middle."
    ),
    system=System(
        coordinates=("x1", "x2"),
        parameters=(
            Parameter("m", 1.0, "kg", 0.01, 100.0, "mass of each body"),
            Parameter("k", 10.0, "N/m", 0.01, 1.0e6, "stiffness of the two outer springs"),
            Parameter("kappa", 1.0, "N/m", 0.0, 1.0e6, "stiffness of the coupling spring between the masses"),
            Parameter("d", 1.0, "m", 0.1, 10.0, "distance of each mass's rest position from the middle"),
        ),
        # rest positions at -d and +d, the walls at -3d and +3d: each spring is 2d long when relaxed
        particles=(Particle("m", ("x1 - d", "0", "0"), "left mass"), Particle("m", ("x2 + d", "0", "0"), "right mass")),
        potential="k*x1**2/2 + kappa*(x2 - x1)**2/2 + k*x2**2/2",
    ),
    initial={"x1": 0.2, "x1_dot": 0.0, "x2": 0.0, "x2_dot": 0.0},
    t_end=30.0,
    reasons=reasons.COUPLED_OSCILLATORS,
    # no Poincaré section: the equations are linear, so the motion is two normal modes and never chaotic
)

PHYSICAL_PENDULUM = Scene(
    id="physical-pendulum",
    coordinate_meanings={
        "theta": "angle of the rod from the downward vertical",
    },
    title="Physical pendulum",
    section="4.3",
    family="physical-pendulum",
    reasons=reasons.PHYSICAL_PENDULUM,
    # what the statement asks beyond the equation of motion (Results states it anyway): the small swings
    answers=("normal-modes",),
    beyond_chapter=True,
    summary="A rigid rod, not a bob: its kinetic energy is the centre's motion plus the turning about the centre.",
    statement=(
        "A uniform rod of mass M and length l hangs from a fixed pivot at one end and swings in a vertical plane. "
        "The angle θ is measured from the downward vertical. Heights are measured upward from the pivot, and "
        "U = 0 when the rod's centre is level with the pivot. Write the rod's kinetic energy as the motion of "
        "its centre plus its turning about the centre, derive the equation of motion, and find the frequency "
        "of small swings."
    ),
    figure=(
        "A pivot at the top, a rod of length l hanging from it at angle θ from the downward vertical, its centre "
        "of mass at the middle, l/2 from the pivot."
    ),
    system=System(
        coordinates=("theta",),
        parameters=(
            Parameter("M", 1.0, "kg", 0.01, 100.0, "mass of the rod"),
            Parameter("l", 1.0, "m", 0.05, 100.0, "length of the rod"),
            GRAVITY,
        ),
        # pivot at the origin, z upward: the centre of mass is l/2 down the rod, and the rod turns by θ
        bodies=(Body("rod", "M", "l", ("l*sin(theta)/2", "0", "-l*cos(theta)/2"), "theta", "rod"),),
        potential="-M*g*l*cos(theta)/2",
    ),
    initial={"theta": 1.0, "theta_dot": 0.0},
    # about four and a half swings (ω² = 3g/(2l), a period near 1.7 s): at 10 s the default run's error
    # grew to 1.2 times its tolerance, so the default run stops at 8 s, within it
    t_end=8.0,
    panels=("effective-potential", "small-oscillations"),
)

MASSIVE_PULLEY = Scene(
    id="massive-pulley",
    coordinate_meanings={
        "z": "height m2 has risen from its start (m1 has descended as far)",
    },
    title="Atwood machine with a massive pulley",
    section="4.5",
    family="disc-pulley",
    reasons=reasons.MASSIVE_PULLEY,
    beyond_chapter=True,
    # what the statement asks: the acceleration, compared with the massless pulley's (M → 0), stated in Results
    limits=(("M", 0.0),),
    answers=("limits",),
    summary="The pulley is a disc that turns with the string: its turning adds M/2 to the masses the weights pull.",
    statement=(
        "Two masses m₁ and m₂ hang on the ends of a light string that runs over a pulley, a uniform disc of mass "
        "M and radius R turning on a fixed frictionless horizontal axle. The string does not stretch and does not "
        "slip on the pulley, so the pulley's rim moves with the string. The masses hang from the two sides of the "
        "rim and are level at the start, a distance d below the axle. The coordinate z is the height m₂ has risen from its "
        "start: m₁ has then descended by z and the pulley has turned through the angle z/R. Heights are measured "
        "upward from the level where the masses start, and U = 0 at the start (z = 0); the "
        "pulley's centre does not move, so its weight adds nothing to U that changes. Derive the equation of motion, find the acceleration z̈, with which m₂ rises and m₁ falls, and "
        "compare it with the same machine on a massless pulley (M → 0)."
    ),
    figure=(
        "A disc pulley of mass M and radius R on a fixed axle; m₁ hangs from the left side of its rim, m₂ from the "
        "right, both on vertical strands; z measured upward for m₂ from the dashed level where both start (m₁ as "
        "far below it), a distance d below the axle, and the pulley's turning z/R marked on a spoke."
    ),
    system=System(
        coordinates=("z",),
        parameters=(
            Parameter("m1", 1.5, "kg", 0.01, 100.0, "mass on the left side"),
            Parameter("m2", 1.0, "kg", 0.01, 100.0, "mass on the right side"),
            Parameter("M", 1.0, "kg", 0.0, 100.0, "mass of the pulley"),
            Parameter("R", 0.2, "m", 0.01, 10.0, "radius of the pulley"),
            GRAVITY,
            Parameter("d", 1.0, "m", 0.1, 100.0, "depth of the masses below the axle at the start"),
        ),
        # heights upward from the masses' starting level, the axle d above it: m₂ on the right side of the rim
        # has gone up by z, m₁ on the left down by z, and the rim (with the string) moved by z, so the pulley
        # turned by z/R (counter-clockwise seen from the front, its left side going down)
        particles=(
            Particle("m1", ("-R", "0", "-z"), "mass m₁"),
            Particle("m2", ("R", "0", "z"), "mass m₂"),
        ),
        bodies=(Body("disc", "M", "R", ("0", "0", "d"), "z/R", "pulley"),),
        potential="m2*g*z - m1*g*z",
    ),
    initial={"z": 0.0, "z_dot": 0.0},
    # with the defaults z̈ = g/6 ≈ 1.6 m/s², so z = ½ z̈ t²: m₂ reaches the axle's level (z = d = 1 m) after about
    # 1.1 s, where the event below ends the default run; a lighter m₁ runs the other way to the same end
    t_end=1.5,
    # a mass that has risen to the axle's level has reached the pulley: the string can run no further
    events=(
        Event(
            "mass at the pulley",
            "d**2 - z**2",
            "A mass reached the pulley and the string can run no further; the run ends there.",
        ),
    ),
)
