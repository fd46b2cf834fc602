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

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from app.viz.exprtree import TreeError, tree


@dataclass(frozen=True)
class Family:
    dim: int = 2
    axes: tuple[int, ...] = (0, 2)  # which Cartesian components the view shows
    fixed: tuple[tuple[str, tuple[str, str, str]], ...] = ()  # (label, position) drawn but not particles
    links: tuple[tuple[str, str, str], ...] = ()  # (from label, to label, style: rod | spring)
    curves: tuple[tuple[str, str, str, tuple[str, str, str]], ...] = ()  # (label, s from, s to, position of s)
    points: tuple[tuple[str, tuple[str, str, str]], ...] = ()  # replaces the particles when given
    axis_names: tuple[str, ...] = ("x", "y", "z")


def _span(q: str, pad: str = "0.25") -> tuple[str, str]:
    return (f"qmin_{q} - {pad}*(qmax_{q} - qmin_{q}) - 0.2", f"qmax_{q} + {pad}*(qmax_{q} - qmin_{q}) + 0.2")


PENDULUM = Family(
    fixed=(("pivot", ("0", "0", "R")),),
    links=(("pivot", "#0", "rod"),),
    curves=(("path", "0", "2*pi", ("R*sin(s)", "0", "R - R*cos(s)")),),
)
FAMILIES: dict[str, Family] = {
    "simple-pendulum": PENDULUM,
    "damped-pendulum": PENDULUM,
    "spherical-pendulum": Family(
        dim=3,
        axes=(0, 1, 2),
        fixed=(("pivot", ("0", "0", "0")),),
        links=(("pivot", "#0", "rod"),),
        curves=(
            ("equator", "0", "2*pi", ("R*cos(s)", "R*sin(s)", "0")),
            ("meridian", "0", "2*pi", ("R*sin(s)", "0", "R*cos(s)")),
            ("meridian", "0", "2*pi", ("0", "R*sin(s)", "R*cos(s)")),
        ),
    ),
    "helix-bead": Family(
        dim=3,
        axes=(0, 1, 2),
        curves=(
            ("helix", *_span("z"), ("R*cos(alpha*s)", "R*sin(alpha*s)", "s")),
            ("axis", *_span("z"), ("0", "0", "s")),
        ),
    ),
    "rotating-parabola": Family(
        axes=(0, 1),
        axis_names=("ρ", "z"),
        points=(("bead", ("rho", "alpha*rho**2", "0")),),
        curves=(
            (
                "wire",
                "-1.2*Abs(qmax_rho) - 1.2*Abs(qmin_rho) - 0.2",
                "1.2*Abs(qmax_rho) + 1.2*Abs(qmin_rho) + 0.2",
                ("s", "alpha*s**2", "0"),
            ),
            ("axis of rotation", "0", "alpha*(1.2*Abs(qmax_rho) + 1.2*Abs(qmin_rho) + 0.2)**2", ("0", "s", "0")),
        ),
    ),
    "incline-block": Family(
        curves=(("incline", *_span("X"), ("s*cos(alpha)", "0", "s*sin(alpha)")),),
    ),
    "tabletop-spring": Family(
        axes=(0, 1),
        fixed=(("centre", ("0", "0", "0")),),
        links=(("centre", "#0", "spring"),),
    ),
    "rail-two-body": Family(
        links=(("#0", "#1", "spring"),),
        curves=(("rail", "Min1 - 0.5", "Max2 + 0.5", ("s", "0", "0")),),
    ),
    "pulley": Family(
        # masses hang at x = -1, 1 (the ends) and 0 (the middle); the pulleys sit above the higher end mass
        fixed=(
            ("left pulley", ("-1", "0", "(qmax_y1 + qmax_y2)/2 + Abs(qmax_y1 - qmax_y2)/2 + 1")),
            ("right pulley", ("1", "0", "(qmax_y1 + qmax_y2)/2 + Abs(qmax_y1 - qmax_y2)/2 + 1")),
        ),
        links=(
            ("#0", "left pulley", "string"),
            ("left pulley", "#2", "string"),
            ("#2", "right pulley", "string"),
            ("right pulley", "#1", "string"),
        ),
    ),
    "double-pendulum": Family(
        fixed=(("pivot", ("0", "0", "0")),),
        links=(("pivot", "#0", "rod"), ("#0", "#1", "rod")),
    ),
    "coupled-oscillators": Family(
        # walls 2 m out from the masses' rest positions (-1 m and +1 m), the three springs between
        fixed=(("left wall", ("-3", "0", "0")), ("right wall", ("3", "0", "0"))),
        links=(("left wall", "#0", "spring"), ("#0", "#1", "spring"), ("#1", "right wall", "spring")),
        curves=(("floor", "-3", "3", ("s", "0", "0")),),
    ),
    "movable-incline": Family(
        # the wedge's apex is the wedge particle; its slope is long enough for the block's whole run
        fixed=(
            ("wedge foot", ("X + (1.15*Abs(qmax_D) + 0.5)*cos(alpha)", "0", "-(1.15*Abs(qmax_D) + 0.5)*sin(alpha)")),
            ("wedge corner", ("X", "0", "-(1.15*Abs(qmax_D) + 0.5)*sin(alpha)")),
        ),
        links=(("#0", "wedge foot", "rod"), ("wedge foot", "wedge corner", "rod"), ("wedge corner", "#0", "rod")),
        curves=(
            (
                "floor",
                "qmin_X - 0.5",
                "qmax_X + (1.15*Abs(qmax_D) + 0.5)*cos(alpha) + 0.5",
                ("s", "0", "-(1.15*Abs(qmax_D) + 0.5)*sin(alpha)"),
            ),
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

    def as_json(self) -> dict[str, Any]:
        return {
            "dim": self.dim,
            "axes": self.axis_names,
            "points": self.points,
            "links": self.links,
            "curves": self.curves,
        }


def _moving_axes(
    particles: Sequence[tuple[str, Sequence[str]]], coordinates: Sequence[str], dim: int
) -> tuple[int, ...]:
    """The Cartesian axes along which some particle moves (at most ``dim`` of them)."""

    def moves(text: str) -> bool:
        try:
            t = tree(text)
        except TreeError:
            return False
        names = set()

        def walk(node: Any) -> None:
            if isinstance(node, str):
                names.add(node)
            elif isinstance(node, list):
                for child in node[1:]:
                    walk(child)

        walk(t)
        return bool(names & (set(coordinates) | {"t"}))

    moving = [i for i in range(3) if any(moves(pos[i]) for _, pos in particles)]
    if dim == 3:
        return (0, 1, 2)
    if moving == [0, 1]:
        return (0, 1)  # motion in a horizontal plane: a top view
    if moving in ([1], [1, 2]):
        return (1, 2)
    return (0, 2)  # otherwise a side view: horizontal x, vertical z


def mechanism(
    scene_id: str,
    particles: Sequence[tuple[str, Sequence[str]]],
    coordinates: Sequence[str],
    three_d: bool,
) -> dict[str, Any] | None:
    """The animation spec of a scene (None when its positions cannot be drawn)."""
    family = FAMILIES.get(scene_id)
    if family is None:
        dim = 3 if three_d else 2
        family = Family(dim=dim, axes=_moving_axes(particles, coordinates, dim))
    # a particle without a label is "mass k" (links refer to points by label)
    own = list(family.points) or [(name or f"mass {i + 1}", pos) for i, (name, pos) in enumerate(particles)]
    spec = MechanismSpec(dim=family.dim, axis_names=[family.axis_names[i] for i in family.axes])
    try:
        for name, pos in own:
            spec.points.append({"label": name, "mass": True, "xyz": [tree(pos[i]) for i in family.axes]})
        for name, pos in family.fixed:
            spec.points.append({"label": name, "mass": False, "xyz": [tree(pos[i]) for i in family.axes]})
        index = {p["label"]: i for i, p in enumerate(spec.points)}
        index.update({f"#{k}": k for k in range(len(own))})
        for a, b, style in family.links:
            if a in index and b in index:
                spec.links.append({"from": index[a], "to": index[b], "style": style})
        for name, lo, hi, pos in family.curves:
            lo, hi = _rail_bounds(lo, hi, coordinates)
            spec.curves.append(
                {"label": name, "from": tree(lo), "to": tree(hi), "xyz": [tree(pos[i]) for i in family.axes]}
            )
    except TreeError:
        return None
    if not spec.points:
        return None
    return spec.as_json()


def _rail_bounds(lo: str, hi: str, coordinates: Sequence[str]) -> tuple[str, str]:
    # "Min1"/"Max2": the extent of the first and last coordinate (a rail under several masses)
    if coordinates:
        lo = lo.replace("Min1", f"qmin_{coordinates[0]}")
        hi = hi.replace("Max2", f"qmax_{coordinates[-1]}")
    return lo, hi
