"""The set-up diagram of a scene, as inline SVG with a title and a description.

``diagram(...)`` picks the drawing of the family a scene names (``Scene.family``;
one function per family in ``diagrams_swing`` and ``diagrams_blocks``, told the
scene's optional ``marks``); a system without a family (a user's own system)
gets a generic drawing: its particles placed at the initial state, projected
onto the plane where they move.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from app.engine.document.trees import TreeError, of_text
from app.viz import diagrams_blocks as blocks
from app.viz import diagrams_swing as swing
from app.viz.exprtree import evaluate
from app.viz.names import label
from app.viz.svg import ACCENT, GUIDE, PARAM, Svg

# a family's drawing: parameters, initial state and the scene's optional marks -> the figure
Family = Callable[[dict[str, float], dict[str, float], Sequence[str]], Svg]

# by family (the name a scene gives as ``Scene.family``), never by scene
FAMILIES: dict[str, Family] = {
    "pendulum": swing.pendulum,
    "spherical-pendulum": swing.spherical,
    "helix": swing.helix,
    "rotating-wire": swing.rotating_parabola,
    "incline": blocks.incline,
    "wedge": blocks.movable_incline,
    "rolling-wedge": blocks.rolling_wedge,
    "tabletop-spring": blocks.tabletop,
    "two-body-rail": blocks.rail_two_body,
    "pulleys": blocks.pulley,
    "double-pendulum": swing.double_pendulum,
    "physical-pendulum": swing.physical_pendulum,
    "disc-pulley": blocks.disc_pulley,
    "three-springs": blocks.coupled_oscillators,
}

Particle = tuple[str, Sequence[str]]  # (label, (x, y, z) expression strings)


def particle_points(particles: Sequence[Particle], env: dict[str, float]) -> list[tuple[str, tuple[float, ...]]]:
    """Each particle's Cartesian position at ``env`` (skipping what cannot be evaluated)."""
    points = []
    for name, position in particles:
        try:
            points.append((name, tuple(evaluate(of_text(c), env) for c in position)))
        except (TreeError, KeyError, ValueError, ZeroDivisionError, OverflowError):
            continue
    return points


def generic(particles: Sequence[Particle], coordinates: Sequence[str], p: dict[str, float], q: dict[str, float]) -> Svg:
    svg = Svg()
    env = {**p, **q, "t": 0.0}
    points = particle_points(particles, env)
    if points:
        spread = [max(pt[i] for _, pt in points) - min(pt[i] for _, pt in points) for i in range(3)]
        ax = sorted(range(3), key=lambda i: -spread[i])[:2]
        ax.sort()
        xs = [pt[ax[0]] for _, pt in points] + [0.0]
        ys = [pt[ax[1]] for _, pt in points] + [0.0]
        size = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
        scale = 150.0 / size

        def place(x: float, y: float) -> tuple[float, float]:
            return 160 + scale * (x - (max(xs) + min(xs)) / 2), 110 - scale * (y - (max(ys) + min(ys)) / 2)

        ox, oy = place(0.0, 0.0)
        svg.line(ox - 8, oy, ox + 8, oy, GUIDE, 1.2)
        svg.line(ox, oy - 8, ox, oy + 8, GUIDE, 1.2)
        for i, (name, pt) in enumerate(points):
            x, y = place(pt[ax[0]], pt[ax[1]])
            svg.circle(x, y, 9, fill="#c9d8ea")
            svg.text(x + 20, y - 8, name or f"particle {i + 1}", PARAM, 14, anchor="start")
    text = "coordinates: " + ", ".join(label(c) for c in coordinates)
    svg.text(12, 222, text, ACCENT, 14, anchor="start")
    return svg


def diagram(
    family: str,
    title: str,
    description: str,
    parameters: dict[str, float],
    initial: dict[str, float],
    coordinates: Sequence[str] = (),
    particles: Sequence[Particle] = (),
    ident: str = "setup",
    marks: Sequence[str] = (),
) -> str:
    """Inline SVG markup of the set-up (accessible: role img, title and description); ``family`` and ``marks``
    are the scene's (a name no family has, or none, gets the generic drawing)."""
    draw = FAMILIES.get(family)
    values = {k: v for k, v in parameters.items() if isinstance(v, (int, float)) and math.isfinite(v)}
    svg = draw(values, initial, marks) if draw else generic(particles, coordinates, values, initial)
    return svg.render(title, description or title, ident)
