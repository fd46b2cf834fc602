"""What the animation draws: points, links and fixed curves, as expression trees.

The browser (static/js/animation.js) evaluates every tree at each sample of a
run with the environment {parameters, q, q_dot, t}; so a run ships only the
state arrays and the drawing is built client-side.  Fixed curves (a wire, an
incline, a sphere) are parametrized by ``s`` and may use the extent of the run,
``qmin_<q>`` and ``qmax_<q>``, to size themselves.

Points are the particles as the scene declares them unless the family draws
something else (the rotating wire is drawn in its own turning plane).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from app.engine.document.model import ConstraintForce, FixedDistance
from app.engine.document.trees import TreeError, of_text
from app.scenes.beads import WIRE_REACH
from app.viz.exprtree import leaves
from app.viz.rods import rods, springs


@dataclass(frozen=True)
class Family:
    dim: int = 2
    axes: tuple[int, ...] = (0, 2)  # which Cartesian components the view shows
    fixed: tuple[tuple[str, tuple[str, str, str]], ...] = ()  # (label, position) drawn but not particles
    anchors: tuple[tuple[str, tuple[str, str, str]], ...] = ()  # (label, position) used by links, not drawn
    # (from label, to label, style: rod | spring | string | bar); a bar is a rigid body's own length (the physical
    # pendulum's rod), drawn wide as the set-up figure draws it, where a rod is a light link holding a bob
    links: tuple[tuple[str, str, str], ...] = ()
    # (label, s from, s to, position of s, style): a guide (dashed path), a wire (solid) or the ground
    # (solid, hatched on the side away from the motion: "ground" below, "ceiling" above); a curve whose
    # position uses t or a coordinate moves with the run and is drawn again at every frame
    curves: tuple[tuple[str, str, str, tuple[str, str, str], str], ...] = ()
    solids: tuple[tuple[str, tuple[str, ...]], ...] = ()  # (label, corner labels): a filled body (a ramp, a wedge)
    # (centre label, radius, "top" | "bottom" | "none": where a string wraps, if any[, the wheel's turning angle]):
    # a wheel given its angle (a massive pulley, a rolling cylinder) is drawn with a spoke turned by it, so that
    # its rotation is seen; the angle is counter-clockwise in the view, as the body's declared angle
    wheels: tuple[tuple[str, ...], ...] = ()
    points: tuple[tuple[str, tuple[str, str, str]], ...] = ()  # replaces the particles when given
    # the points (indices into the drawn bodies) that are a body's centre of mass, drawn as a small mark on the
    # body (a bar) rather than as a ball, which would read as a bob on a string
    centres: tuple[int, ...] = ()
    axis_names: tuple[str, ...] = ("x", "y", "z")
    slack: str = ""  # the constraint force whose negative value means the strings are slack
    caption: str = ""  # what the animation shows, in words
    # (particle index, slope angle in the view, counter-clockwise, base): a block drawn as a rectangle whose
    # base rests on that slope at the particle: "middle" (the particle is the middle of its base) or "ahead"
    # (the base runs from the particle along the slope's direction, so a block at the end of a ramp stays on it)
    blocks: tuple[tuple[int, str, str], ...] = ()
    applied: tuple[tuple[str, str], ...] = ()  # (constraint force, anchor label): where its arrow starts
    # 3-D: the view the page opens on, (yaw about the vertical, pitch: tilt toward looking down), in radians;
    # None keeps the browser's general one (static/js/camera.js)
    view: tuple[float, float] | None = None


def _span(q: str, pad: str = "0.25") -> tuple[str, str]:
    return (f"qmin_{q} - {pad}*(qmax_{q} - qmin_{q}) - 0.2", f"qmax_{q} + {pad}*(qmax_{q} - qmin_{q}) + 0.2")


def _max(a: str, b: str) -> str:
    # max(a, b) = (a + b + |a - b|)/2: the figure expressions have no Max
    return f"(({a}) + ({b}) + Abs(({a}) - ({b})))/2"


TRAIL = "a fading trail behind each moving body"
NO_PICTURE = (
    "No picture: this system is given by its Lagrangian or its energies alone, with no particle positions, so "
    "there is nothing to draw faithfully. The time slider and Play still move the cursors on the plots below; "
    "to see it move, declare it by its particles."
)
PENDULUM = Family(
    fixed=(("pivot", ("0", "0", "R")),),
    links=(("pivot", "#0", "string"),),
    curves=(("path", "0", "2*pi", ("R*sin(s)", "0", "R - R*cos(s)"), "guide"),),
    slack="string tension",
    caption=(
        f"Side view: the pivot, the string and the bob, the circle the bob can reach (dashed) and {TRAIL}. "
        "Where the string's tension would be negative it is drawn slack."
    ),
)

# The fixed incline: X is the distance up the slope from its foot at the origin; the ramp reaches a
# little above the highest point of the run, the floor runs out on both sides of the foot.
# the turning wire is drawn to its ends, a fixed distance from the axis whatever the run does (a run ends when the
# bead reaches one), so the view keeps the wire's scale
_RIM = f"{WIRE_REACH!r}"
_RAMP = "(1.15*(qmax_X + Abs(qmax_X))/2 + 0.5)"
# The pulleys: end masses drawn at x = -W and W, W the scene's spacing d unless the run's vertical extent
# is so large that the device would be a sliver in a tall frame; wheels of radius r = W/3 make every string
# vertical (end mass at -W, fixed wheel from -W to -W + 2r = -r, movable wheel from -r to r).
_W = _max("d", "0.3*(qmax_y1 - qmin_y1 + qmax_y2 - qmin_y2)")
_R = f"({_W})/3"
_HANG = f"1.6*{_R}"  # from the middle mass up to its wheel's centre: the mass hangs clear below the rim
_Y = "(-(y1 + y2)/2 - c)"  # the middle mass's height (the scene's particle), c set by the string's length
# the fixed wheels' height: above both end masses and above the movable wheel's highest reach
_TOP = _max(_max("qmax_y1", "qmax_y2"), f"-(qmin_y1 + qmin_y2)/2 - c + {_HANG} + 2*{_R}") + f" + {_R} + 0.5*{_R}"
# The sliding wedge: D along its slope from the top corner; the top is at D = min(qmin_D, 0) (a run that starts
# above the corner still has slope under it), the foot a little beyond the block's farthest reach.
_WEDGE_TOP = "((qmin_D - Abs(qmin_D))/2)"
_WEDGE_FOOT = "(1.15*Abs(qmax_D) + 0.5)"
# The rolling cylinder's wedge: as the sliding wedge's, with s for D, and its foot far enough down the slope for the
# cylinder's point of contact (its centre's s) at the farthest point of the run, and a diameter to spare.
_ROLL_TOP = "((qmin_s - Abs(qmin_s))/2)"
_ROLL_FOOT = "(1.15*Abs(qmax_s) + 0.5 + 2*r)"


def _wedge_middle(top: str, foot: str) -> tuple[str, tuple[str, str, str]]:
    """The sliding wedge's point, drawn at the centroid of its triangle (top corner, foot, right-angle corner),
    its slope running from ``top`` to ``foot`` along the slope (falling to the right at alpha), X its position."""
    return ("wedge", (f"X + ({top} + {top} + {foot})*cos(alpha)/3", "0", f"-({top} + 2*{foot})*sin(alpha)/3"))


def _wedge_corners(top: str, foot: str) -> tuple[tuple[str, tuple[str, str, str]], ...]:
    """The wedge's three corners, as anchors of its solid."""
    return (
        ("wedge top", (f"X + {top}*cos(alpha)", "0", f"-{top}*sin(alpha)")),
        ("wedge foot", (f"X + {foot}*cos(alpha)", "0", f"-{foot}*sin(alpha)")),
        ("wedge corner", (f"X + {top}*cos(alpha)", "0", f"-{foot}*sin(alpha)")),
    )


def _wedge_floor(top: str, foot: str) -> tuple[str, str, str, tuple[str, str, str], str]:
    """The floor under the wedge, as long as the wedge's whole run."""
    return (
        "floor",
        f"qmin_X + {top}*cos(alpha) - 0.5",
        f"qmax_X + {foot}*cos(alpha) + 0.5",
        ("s", "0", f"-{foot}*sin(alpha)"),
        "ground",
    )


# by family (the name a scene gives as ``Scene.family``), never by scene
FAMILIES: dict[str, Family] = {
    "pendulum": PENDULUM,
    "spherical-pendulum": Family(
        dim=3,
        axes=(0, 1, 2),
        fixed=(("pivot", ("0", "0", "0")),),
        links=(("pivot", "#0", "string"),),
        curves=(
            ("equator", "0", "2*pi", ("R*cos(s)", "R*sin(s)", "0"), "guide"),
            ("meridian", "0", "2*pi", ("R*sin(s)", "0", "R*cos(s)"), "guide"),
            ("meridian", "0", "2*pi", ("0", "R*sin(s)", "R*cos(s)"), "guide"),
        ),
        slack="string tension",
        caption=(
            f"The pivot, the string and the ball on the sphere it can reach (three great circles), with {TRAIL}; "
            "drag the background to turn the view. Where the tension would be negative the string is drawn slack."
        ),
    ),
    "helix": Family(
        dim=3,
        axes=(0, 1, 2),
        curves=(
            ("helix", *_span("z"), ("R*cos(alpha*s)", "R*sin(alpha*s)", "s"), "wire"),
            ("axis", *_span("z"), ("0", "0", "s"), "guide"),
        ),
        caption=f"The helical wire, its axis (dashed) and the bead, with {TRAIL}; drag the background to turn the view.",
        # looking down 0.9 rad (52°): a turn of radius R shows as an ellipse 2R sin 0.9 tall, against turns
        # (2π/α) cos 0.9 apart, so at the defaults (R = 0.5 m, α = 4 rad/m) the turns open into loops (0.78 m
        # against 0.98 m) where the general 0.35 rad drew a flat wave (0.34 m against 1.48 m)
        view=(-0.6, 0.9),
    ),
    "rotating-wire": Family(
        # the lab frame: the wire turns about the vertical axis at omega, carrying the bead
        dim=3,
        axes=(0, 1, 2),
        curves=(
            (
                "wire",
                f"-{_RIM}",
                _RIM,
                ("s*cos(omega*t)", "s*sin(omega*t)", "alpha*s**2"),
                "wire",
            ),
            (
                "rim",
                "0",
                "2*pi",
                (
                    f"{_RIM}*cos(s)",
                    f"{_RIM}*sin(s)",
                    f"alpha*{_RIM}**2",
                ),
                "guide",
            ),
            (
                "axis of rotation",
                "0",
                f"alpha*{_RIM}**2",
                ("0", "0", "s"),
                "guide",
            ),
        ),
        caption=(
            "Lab frame, in three dimensions: the parabolic wire turns about the vertical axis (dashed) at the "
            "angular velocity ω and carries the bead round, with a fading trail behind it; the dashed circle is the "
            "rim the wire's ends sweep. A run that reaches an end of the wire ends there. Drag the background to "
            "turn the view."
        ),
    ),
    "incline": Family(
        anchors=(
            ("foot", ("0", "0", "0")),
            ("top", (f"{_RAMP}*cos(alpha)", "0", f"{_RAMP}*sin(alpha)")),
            ("corner", (f"{_RAMP}*cos(alpha)", "0", "0")),
        ),
        solids=(("ramp", ("foot", "top", "corner")),),
        # the block lies up the slope from X: at X = 0 it sits on the foot, not half below the floor
        blocks=((0, "alpha", "ahead"),),
        curves=(("floor", f"-0.6*{_RAMP} - 0.3", f"{_RAMP}*cos(alpha) + 0.3", ("s", "0", "0"), "ground"),),
        caption=(
            f"Side view: the fixed ramp at angle α on the floor, and the block on its slope with {TRAIL}. "
            "A run that reaches the foot of the ramp ends there."
        ),
    ),
    "tabletop-spring": Family(
        axes=(0, 1),
        fixed=(("centre", ("0", "0", "0")),),
        links=(("centre", "#0", "spring"),),
        caption=f"The table seen from above: the fixed centre, the spring (drawn stretching) and the particle, with {TRAIL}.",
    ),
    "two-body-rail": Family(
        links=(("#0", "#1", "spring"),),
        curves=(("rail", "Min1 - 0.5", "Max2 + 0.5", ("s", "0", "0"), "wire"),),
        caption=f"The rail, the two bodies and the spring between them (drawn stretching), with {TRAIL}.",
    ),
    "pulleys": Family(
        points=(
            ("left mass", (f"-{_W}", "0", "y1")),
            ("right mass", (_W, "0", "y2")),
            ("middle mass", ("0", "0", _Y)),
        ),
        anchors=(
            ("left wheel", (f"-{_W} + {_R}", "0", _TOP)),
            ("left wheel, left", (f"-{_W}", "0", _TOP)),
            ("left wheel, right", (f"-{_R}", "0", _TOP)),
            ("right wheel", (f"{_W} - {_R}", "0", _TOP)),
            ("right wheel, left", (_R, "0", _TOP)),
            ("right wheel, right", (_W, "0", _TOP)),
            ("movable wheel", ("0", "0", f"{_Y} + {_HANG}")),
            ("movable wheel, left", (f"-{_R}", "0", f"{_Y} + {_HANG}")),
            ("movable wheel, right", (_R, "0", f"{_Y} + {_HANG}")),
            ("left mount", (f"-{_W} + {_R}", "0", f"{_TOP} + 1.5*{_R}")),
            ("right mount", (f"{_W} - {_R}", "0", f"{_TOP} + 1.5*{_R}")),
        ),
        links=(
            ("#0", "left wheel, left", "string"),
            ("left wheel, right", "movable wheel, left", "string"),
            ("movable wheel, right", "right wheel, left", "string"),
            ("right wheel, right", "#1", "string"),
            ("movable wheel", "#2", "rod"),
            ("left wheel", "left mount", "rod"),
            ("right wheel", "right mount", "rod"),
        ),
        wheels=(("left wheel", _R, "top"), ("right wheel", _R, "top"), ("movable wheel", _R, "bottom")),
        curves=(("ceiling", f"-{_W} - 0.3*{_R}", f"{_W} + 0.3*{_R}", ("s", "0", f"{_TOP} + 1.5*{_R}"), "ceiling"),),
        slack="string tension",
        caption=(
            "Two fixed wheels hang from the ceiling; the string runs from the left mass over them and under the "
            f"movable wheel that carries the middle mass, to the right mass; {TRAIL}. The heights are to scale, "
            "and the end masses are drawn d either side of the middle unless the run is so tall that the device "
            "would be a sliver, then farther apart; a string with negative tension is drawn slack."
        ),
    ),
    "disc-pulley": Family(
        # the pulley's axle d above the level where the masses start (their heights' zero), the masses on vertical
        # strings from the two sides of the rim; the wheel turns by z/R, counter-clockwise as m₂ on the right goes
        # up, so that its rim keeps pace with the string
        fixed=(("axle", ("0", "0", "d")),),
        anchors=(
            ("left side", ("-R", "0", "d")),
            ("right side", ("R", "0", "d")),
            ("mount", ("0", "0", "d + 2*R")),
        ),
        links=(("left side", "#0", "string"), ("right side", "#1", "string"), ("axle", "mount", "rod")),
        wheels=(("axle", "R", "top", "z/R"),),
        curves=(("ceiling", "-2*R", "2*R", ("s", "0", "d + 2*R"), "ceiling"),),
        caption=(
            "Side view: the pulley on its fixed axle, turning with the string (its two spokes turn with it), and "
            f"the two masses on vertical strings from the sides of its rim, with {TRAIL}. A run in which a mass "
            "reaches the pulley ends there."
        ),
    ),
    "double-pendulum": Family(
        fixed=(("pivot", ("0", "0", "0")),),
        links=(("pivot", "#0", "rod"), ("#0", "#1", "rod")),
        caption=f"Side view: the pivot, the two rods and the two bobs, with {TRAIL}.",
    ),
    "physical-pendulum": Family(
        # the rod from the pivot to its free end drawn as a bar, its centre of mass a small mark halfway down
        points=(("centre of mass", ("l*sin(theta)/2", "0", "-l*cos(theta)/2")),),
        centres=(0,),
        fixed=(("pivot", ("0", "0", "0")),),
        anchors=(("end", ("l*sin(theta)", "0", "-l*cos(theta)")),),
        links=(("pivot", "end", "bar"),),
        curves=(("path of the centre", "0", "2*pi", ("l*sin(s)/2", "0", "-l*cos(s)/2"), "guide"),),
        caption=(
            f"Side view: the pivot, the rod drawn as a bar, its centre of mass marked halfway down, the circle the "
            f"centre can reach (dashed) and {TRAIL}."
        ),
    ),
    "three-springs": Family(
        # walls 2d out from the masses' rest positions (-d and +d), the three springs between
        anchors=(("left wall", ("-3*d", "0", "0")), ("right wall", ("3*d", "0", "0"))),
        links=(("left wall", "#0", "spring"), ("#0", "#1", "spring"), ("#1", "right wall", "spring")),
        curves=(
            ("floor", "-3*d", "3*d", ("s", "0", "-0.12*d"), "ground"),
            ("left wall", "-0.12*d", "0.6*d", ("-3*d", "0", "s"), "wall-left"),
            ("right wall", "-0.12*d", "0.6*d", ("3*d", "0", "s"), "wall-right"),
        ),
        caption=(f"Side view: the two walls, the three springs (drawn stretching) and the two masses, with {TRAIL}."),
    ),
    "wedge": Family(
        # The wedge's top corner is where D = 0 (higher when a run has D < 0); its slope is long enough for the
        # block's whole run. The wedge is drawn at its middle (the centroid of the triangle), the block on
        # the slope below the top corner, so the two labels sit by their own bodies.
        points=(_wedge_middle(_WEDGE_TOP, _WEDGE_FOOT), ("block", ("X + D*cos(alpha)", "0", "-D*sin(alpha)"))),
        anchors=(
            *_wedge_corners(_WEDGE_TOP, _WEDGE_FOOT),
            # the floor pushes on the whole base; its resultant is drawn from the base's middle
            ("wedge base", (f"X + ({_WEDGE_TOP} + {_WEDGE_FOOT})*cos(alpha)/2", "0", f"-{_WEDGE_FOOT}*sin(alpha)")),
        ),
        applied=(("floor force on the wedge", "wedge base"),),
        solids=(("wedge", ("wedge top", "wedge foot", "wedge corner")),),
        # the block rests on the wedge's slope, which falls to the right at alpha; it lies down the slope from D
        blocks=((1, "-alpha", "ahead"),),
        curves=(_wedge_floor(_WEDGE_TOP, _WEDGE_FOOT),),
        caption=(
            f"Side view: the wedge sliding on the floor and the block on its slope, with {TRAIL} "
            "(the wedge's trail follows its middle)."
        ),
    ),
    "rolling-wedge": Family(
        # The sliding wedge's drawing with the block made a cylinder: the wedge drawn at its middle, the cylinder at
        # its centre, r out from the slope, as a wheel whose spokes turn with it by −s/r (clockwise as it rolls
        # down, to the right).
        points=(
            _wedge_middle(_ROLL_TOP, _ROLL_FOOT),
            ("cylinder", ("X + s*cos(alpha) + r*sin(alpha)", "0", "r*cos(alpha) - s*sin(alpha)")),
        ),
        anchors=_wedge_corners(_ROLL_TOP, _ROLL_FOOT),
        solids=(("wedge", ("wedge top", "wedge foot", "wedge corner")),),
        wheels=(("cylinder", "r", "none", "-s/r"),),
        curves=(_wedge_floor(_ROLL_TOP, _ROLL_FOOT),),
        caption=(
            "Side view: the wedge sliding on the floor and the cylinder rolling down its slope, its two spokes "
            f"turning with it, with {TRAIL} (the wedge's trail follows its middle)."
        ),
    ),
}


@dataclass
class MechanismSpec:
    dim: int
    axis_names: list[str]
    points: list[dict[str, Any]] = field(default_factory=list)
    links: list[dict[str, Any]] = field(default_factory=list)
    curves: list[dict[str, Any]] = field(default_factory=list)
    solids: list[dict[str, Any]] = field(default_factory=list)
    wheels: list[dict[str, Any]] = field(default_factory=list)
    forces: list[dict[str, Any]] = field(default_factory=list)
    slack: str = ""
    caption: str = ""
    view: tuple[float, float] | None = None

    def as_json(self) -> dict[str, Any]:
        view = {"view": {"yaw": self.view[0], "pitch": self.view[1]}} if self.view else {}
        return view | {
            "dim": self.dim,
            "axes": self.axis_names,
            "points": self.points,
            "links": self.links,
            "curves": self.curves,
            "solids": self.solids,
            "wheels": self.wheels,
            "forces": self.forces,
            "slack": self.slack,
            "caption": self.caption,
        }


def _names_in(text: str) -> set[str]:
    try:
        return leaves(of_text(text))
    except TreeError:
        return set()


def _moving_axes(
    particles: Sequence[tuple[str, Sequence[str]]], coordinates: Sequence[str], dim: int
) -> tuple[int, ...]:
    """The Cartesian axes along which some particle moves (at most ``dim`` of them)."""
    moving_names = set(coordinates) | {"t"}
    moving = [i for i in range(3) if any(_names_in(pos[i]) & moving_names for _, pos in particles)]
    if dim == 3:
        return (0, 1, 2)
    if moving == [0, 1]:
        return (0, 1)  # motion in a horizontal plane: a top view
    if moving in ([1], [1, 2]):
        return (1, 2)
    return (0, 2)  # otherwise a side view: horizontal x, vertical z


def _inferred(
    particles: Sequence[tuple[str, Sequence[str]]],
    coordinates: Sequence[str],
    dim: int,
    defaults: Mapping[str, float],
    proven: Sequence[FixedDistance],
    potential: Any = None,
) -> Family:
    """A system without a drawing of its own: its particles, with the rods, springs and pivot their motion implies."""
    axes = _moving_axes(particles, coordinates, dim)
    found = rods(particles, coordinates, defaults, proven)
    links = tuple(("pivot" if a is None else f"#{a}", f"#{b}", "rod?" if checked else "rod") for a, b, checked in found)
    # a particle at distance r from the origin, with r squared in U (a spring's energy): a spring from a pivot
    held = {b for a, b, _ in found if a is None}
    coiled = [(j, q) for j, q in springs(particles, coordinates, defaults, potential) if j not in held]
    links += tuple(("pivot", f"#{j}", "spring") for j, _ in coiled)
    pivot = any(a is None for a, _, _ in found) or bool(coiled)
    what = "the particles as declared"
    if found:
        # the positions prove a distance fixed, not what holds it: a rod, a taut string or a hoop the bead rides
        # on are the same to the equations, and one particle at a fixed distance from a point may sweep a whole
        # sphere, so the drawing shows the distance (a rod) and the caption says so
        what += (
            ", each distance that stays fixed drawn as a rod (whatever holds it there: a rod, a taut string, "
            "or a hoop the bead rides on)" + (" and the fixed pivot" if pivot else "")
        )
    if coiled:
        what += f", the spring{'s' if len(coiled) > 1 else ''} from the fixed pivot (its length is {', '.join(q for _, q in coiled)})"
    view = "in three dimensions; drag the background to turn the view" if dim == 3 else _view_name(axes)
    return Family(
        dim=dim,
        axes=axes,
        fixed=(("pivot", ("0", "0", "0")),) if pivot else (),
        links=links,
        caption=f"{what[0].upper()}{what[1:]} ({view}), with {TRAIL}." + _undrawn(particles, coordinates, found),
    )


def _undrawn(
    particles: Sequence[tuple[str, Sequence[str]]], coordinates: Sequence[str], found: Sequence[tuple[Any, Any, bool]]
) -> str:
    """A body that moves along more axes than it has coordinates is held on a surface (a cone's) or a curve (a
    wire's) that the positions give only through the coordinates: the picture cannot draw it, and says so.
    A body held by a distance drawn as a rod is left out: the rod shows what holds it."""
    held = {i for a, b, _ in found for i in (a, b) if i is not None}
    moving_names = set(coordinates) | {"t"}
    kinds = set()
    for i, (_, pos) in enumerate(particles):
        axes = [x for x in pos if _names_in(x) & moving_names]
        own = set().union(*(_names_in(x) for x in pos)) & set(coordinates)
        if i not in held and 0 < len(own) < len(axes):
            kinds.add("surface" if len(own) >= 2 else "curve")
    if not kinds:
        return ""
    which = "surface or curve" if len(kinds) == 2 else kinds.pop()
    return f" The {which} the coordinates hold a body on is not drawn: it is given only through the coordinates."


def _view_name(axes: tuple[int, ...]) -> str:
    names = "xyz"
    return f"{names[axes[0]]} across, {names[axes[1]]} up"


def mechanism(
    family_name: str,
    particles: Sequence[tuple[str, Sequence[str]]],
    coordinates: Sequence[str],
    three_d: bool,
    forces: Sequence[ConstraintForce] = (),
    defaults: Mapping[str, float] | None = None,
    proven: Sequence[FixedDistance] = (),
    potential: Any = None,
) -> dict[str, Any] | None:
    """The animation spec of a scene drawn as ``family_name`` (its ``Scene.family``; None when its positions
    cannot be drawn).

    ``forces`` are the derivation document's constraint forces (name, particle, direction): each
    becomes an arrow on its particle.  A system without a family of its own is drawn from its
    particles, with rods inferred (app/viz/rods.py) from ``proven`` (the derivation's fixed
    distances) or numerically at the parameters ``defaults``; without particles it has no picture,
    and the spec says so (no points, ``none`` true, the caption in words)."""
    family = FAMILIES.get(family_name)
    if family is None and not particles:
        return MechanismSpec(dim=2, axis_names=[], caption=NO_PICTURE).as_json() | {"none": True}
    if family is None:
        family = _inferred(particles, coordinates, 3 if three_d else 2, defaults or {}, proven, potential)
    # a particle without a label is "mass k" (links refer to points by label)
    own: list[tuple[str, Sequence[str]]] = list(family.points) or [
        (name or f"mass {i + 1}", pos) for i, (name, pos) in enumerate(particles)
    ]
    spec = MechanismSpec(
        dim=family.dim,
        axis_names=[family.axis_names[i] for i in family.axes],
        slack=family.slack,
        caption=family.caption,
        view=family.view,
    )
    try:
        tilt = {k: (angle, base) for k, angle, base in family.blocks}
        for k, (name, pos) in enumerate(own):
            point = {"label": name, "mass": True, "xyz": [of_text(pos[i]) for i in family.axes]}
            if k in tilt:
                point["block"] = of_text(tilt[k][0])
                point["base"] = tilt[k][1]
            if k in family.centres:
                point["centre"] = True
            spec.points.append(point)
        for drawn, group in ((True, family.fixed), (False, family.anchors)):
            for name, pos in group:
                point = {"label": name, "mass": False, "xyz": [of_text(pos[i]) for i in family.axes]}
                spec.points.append(point if drawn else {**point, "hidden": True})
        index = {p["label"]: i for i, p in enumerate(spec.points)}
        index.update({f"#{k}": k for k in range(len(own))})
        for a, b, style in family.links:
            if a in index and b in index:
                # "rod?": a rod found only numerically, which the browser confirms along the run
                link = {"from": index[a], "to": index[b], "style": style.rstrip("?")}
                spec.links.append({**link, "check": True} if style.endswith("?") else link)
        for name, lo, hi, pos, style in family.curves:
            lo, hi = _rail_bounds(lo, hi, coordinates)
            spec.curves.append(
                {
                    "label": name,
                    "from": of_text(lo),
                    "to": of_text(hi),
                    "xyz": [of_text(pos[i]) for i in family.axes],
                    "style": style,
                    "moving": bool(set().union(*(_names_in(pos[i]) for i in family.axes)) & ({"t", *coordinates})),
                }
            )
        for name, corners in family.solids:
            spec.solids.append({"label": name, "corners": [index[c] for c in corners]})
        for centre, radius, wrap, *turn in family.wheels:
            wheel = {"at": index[centre], "radius": of_text(radius), "wrap": wrap}
            if turn:
                wheel["turn"] = of_text(turn[0])
            spec.wheels.append(wheel)
    except TreeError:
        return None
    where = dict(family.applied)
    for f in forces:
        # every body the force acts on (a string pulls each mass it holds, twice as hard where it runs round a
        # movable wheel); a force with none listed acts on its own particle only
        acting = [(a.particle, a.direction_trees, a.ratio_tree) for a in f.acts_on] or [
            (f.particle, f.direction_trees, None)
        ]
        for particle, direction, ratio in acting:
            k = particle - 1
            if not direction or not 0 <= k < len(own):
                continue
            arrow = [direction[i] for i in family.axes]
            if any(a is None for a in arrow):
                continue  # this force is left without an arrow
            force = {"name": f.name, "on": k, "direction": arrow}
            if ratio is not None and ratio != 1:
                force["ratio"] = ratio
            if k == f.particle - 1 and f.name in where and where[f.name] in index:
                force["at"] = index[where[f.name]]
            spec.forces.append(force)
    if not spec.points:
        return None
    return spec.as_json()


def _rail_bounds(lo: str, hi: str, coordinates: Sequence[str]) -> tuple[str, str]:
    # "Min1"/"Max2": the extent of the first and last coordinate (a rail under several masses)
    if coordinates:
        lo = lo.replace("Min1", f"qmin_{coordinates[0]}")
        hi = hi.replace("Max2", f"qmax_{coordinates[-1]}")
    return lo, hi
