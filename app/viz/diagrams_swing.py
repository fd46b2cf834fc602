"""Set-up diagrams of the swinging and spinning scenes: pendulums, helix, parabola.

Each function draws the scene at its default parameters and initial
condition, labels the coordinates (blue) and the parameters (brown), and
returns the ``Svg``.  ``p`` maps parameter names to values, ``q`` the initial
state, ``marks`` the optional marks the scene asks for (the pendulum's ``drag``,
the damping force's arrow; a family without options ignores them).  Geometry is only drawing: nothing here is mechanics.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from app.viz.svg import ACCENT, GUIDE, INK, PARAM, Svg


def _gravity(svg: Svg, x: float, y: float) -> None:
    svg.arrow(x, y, x, y + 36, color=PARAM)
    svg.text(x + 12, y + 20, "g", PARAM)


def _drawing_angle(value: float, lo: float = 0.45, hi: float = 1.0) -> float:
    """The initial angle, kept in a range where the drawing stays legible."""
    sign = -1.0 if value < 0 else 1.0
    return sign * min(max(abs(value), lo), hi)


def pendulum(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    theta = _drawing_angle(q.get("theta", 0.8))
    px, py, length = 150.0, 28.0, 150.0
    bx, by = px + length * math.sin(theta), py + length * math.cos(theta)
    svg.line(px - 40, py, px + 40, py, width=3)
    for i in range(5):
        svg.line(px - 36 + 18 * i, py, px - 44 + 18 * i, py - 8, width=1.2)
    svg.line(px, py, px, py + length + 12, GUIDE, 1.5, dash=True)
    svg.line(px, py, bx, by, width=2)
    svg.arc(px, py, 52, math.pi / 2, math.pi / 2 - theta, arrow=True)
    mid = math.pi / 2 - theta / 2
    svg.text(px + 66 * math.cos(mid), py + 66 * math.sin(mid), "θ", ACCENT, 17)
    svg.text((px + bx) / 2 - 12 * math.cos(theta), (py + by) / 2 + 12 * math.sin(theta), "R", PARAM)
    svg.circle(bx, by, 12, fill="#c9d8ea")
    svg.text(bx + 24, by + 4, "m", PARAM)
    _gravity(svg, 40, 150)
    # the origin the statement measures positions from: the lowest point of the swing, x across and z up
    ox, oy = px, py + length
    svg.circle(ox, oy, 2.5, fill=INK)
    svg.arrow(ox, oy, ox + 34, oy, width=1.5)
    svg.text(ox + 44, oy + 5, "x", INK, 14)
    svg.arrow(ox, oy, ox, oy - 30, width=1.5)
    svg.text(ox - 10, oy - 30, "z", INK, 14)
    if "drag" in marks:
        # the bob drawn swinging outward (θ̇ > 0): its velocity v along +θ̂ = (cos θ, −sin θ) on the page (y down)
        vx, vy = math.cos(theta), -math.sin(theta)
        svg.arrow(bx + 16 * vx, by + 16 * vy, bx + 44 * vx, by + 44 * vy)
        svg.text(bx + 44 * vx + 10, by + 44 * vy + 2, "v", INK, 15)
        # the drag acts along the path against v, pointing back toward the bottom
        tx, ty = -vx, -vy
        svg.arrow(bx + 16 * tx, by + 16 * ty, bx + 52 * tx, by + 52 * ty, color=PARAM)
        # labelled with its magnitude, the arrow giving the direction: a torque −b θ̇ about the pivot is, on the
        # bob at distance R, a force b |θ̇| / R along the path
        svg.text(bx + 40 * tx + 6, by + 40 * ty + 18, "(b/R) |θ̇|", PARAM, 14, anchor="start")
    return svg


def _view(x: float, y: float, z: float, scale: float, ox: float, oy: float) -> tuple[float, float]:
    # orthographic view from azimuth GAMMA, elevation EPS: x to the front right, y to the back right, z up
    depth = -x * math.sin(GAMMA) + y * math.cos(GAMMA)
    across = x * math.cos(GAMMA) + y * math.sin(GAMMA)
    return ox + scale * across, oy - scale * (z * math.cos(EPS) + depth * math.sin(EPS))


GAMMA, EPS = 0.75, 0.35


def spherical(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    theta = q.get("theta", 2.2)
    phi = _drawing_angle(q.get("phi", 0.0), 0.9, 1.3)
    ox, oy, s = 150.0, 118.0, 92.0
    svg.circle(ox, oy, s, fill="none", color=GUIDE, width=1.2, dash=True)
    svg.ellipse(ox, oy, s, s * math.sin(EPS))
    top = _view(0, 0, 1.18, s, ox, oy)
    svg.arrow(ox, oy, *top, color=GUIDE, width=1.5)
    svg.text(top[0] + 10, top[1] + 2, "z", GUIDE, 14)
    ball = (math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta))
    bx, by = _view(*ball, s, ox, oy)
    fx, fy = _view(ball[0], ball[1], 0.0, s, ox, oy)
    svg.line(bx, by, fx, fy, GUIDE, 1.2, dash=True)
    svg.line(ox, oy, fx, fy, GUIDE, 1.2, dash=True)
    # the x axis φ is measured from, drawn and named like z
    ax = _view(1.3, 0.0, 0.0, s, ox, oy)
    svg.arrow(ox, oy, *ax, color=GUIDE, width=1.5)
    svg.text(ax[0] + 9, ax[1] + 2, "x", GUIDE, 14)
    svg.line(ox, oy, bx, by, width=2)
    svg.circle(ox, oy, 3.5)
    # theta: from the upward axis to the string; phi: along the equator from the x axis
    arc = [_view(0.3 * math.sin(a) * math.cos(phi), 0.3 * math.sin(a) * math.sin(phi), 0.3 * math.cos(a), s, ox, oy)
           for a in [theta * i / 24 for i in range(25)]]  # fmt: skip
    svg.polyline(arc, ACCENT, 1.8)
    mid_theta = _view(
        0.42 * math.sin(0.5) * math.cos(phi), 0.42 * math.sin(0.5) * math.sin(phi), 0.42 * math.cos(0.5), s, ox, oy
    )
    svg.text(mid_theta[0] + 4, mid_theta[1], "θ", ACCENT, 17)
    eq = [_view(0.55 * math.cos(a), 0.55 * math.sin(a), 0.0, s, ox, oy) for a in [phi * i / 16 for i in range(17)]]
    svg.polyline(eq, ACCENT, 1.8)
    label = _view(0.7 * math.cos(phi / 2), 0.7 * math.sin(phi / 2), 0.0, s, ox, oy)
    svg.text(label[0], label[1] + 10, "φ", ACCENT, 17)
    length = math.hypot(bx - ox, by - oy) or 1.0
    nx, ny = (by - oy) / length, -(bx - ox) / length
    svg.text((ox + bx) / 2 - 14 * nx, (oy + by) / 2 - 14 * ny, "R", PARAM)
    svg.circle(bx, by, 10, fill="#c9d8ea")
    svg.text(bx + 20, by, "m", PARAM)
    _gravity(svg, 286, 40)
    return svg


def helix(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    turns, ox, bottom, top, radius, tilt = 2.5, 150.0, 212.0, 24.0, 62.0, 12.0
    pts = []
    for i in range(241):
        a = 2 * math.pi * turns * i / 240
        pts.append((ox + radius * math.cos(a), bottom - (bottom - top) * i / 240 + tilt * math.sin(a), math.sin(a) < 0))
    svg.line(ox, bottom + 10, ox, top - 6, GUIDE, 1.5, dash=True)
    # the half-turns behind the axis are drawn faint, those in front solid
    run: list[tuple[float, float]] = []
    for k, (x, y, behind) in enumerate(pts):
        run.append((x, y))
        if k == len(pts) - 1 or pts[k + 1][2] != behind:
            svg.polyline(run, "#a0a8b0" if behind else INK, 1.4 if behind else 2.2)
            run = [(x, y)]
    k = 105  # just over one turn up: the bead in front, at φ = 2π + 3π/8 (its direction 3π/8 from x)
    bx, by = pts[k][0], pts[k][1]
    svg.circle(bx, by, 8, fill="#c9d8ea")
    svg.text(bx + 18, by - 10, "m", PARAM)
    svg.arrow(40, bottom, 40, by, color=ACCENT)
    svg.line(34, bottom, 46, bottom, ACCENT, 1.5)
    svg.text(28, (bottom + by) / 2, "z", ACCENT, 17)
    svg.line(40, by, bx - 10, by, GUIDE, 1, dash=True)
    svg.arrow(ox, bottom + 22, ox + radius, bottom + 22, color=PARAM, width=1.5)
    svg.text(ox + radius / 2, bottom + 12, "R", PARAM)
    svg.text(ox + radius + 34, 60, "φ = α z", ACCENT, 15)
    # seen from above (an inset): φ is the bead's angle about the axis from the x axis, where the wire
    # starts at z = 0
    phi = 2 * math.pi * turns * k / 240
    cx, cy, rr = 56.0, 52.0, 30.0
    svg.text(cx, cy - rr - 10, "from above", GUIDE, 11)
    svg.circle(cx, cy, rr, fill="none", color=GUIDE, width=1, dash=True)
    svg.arrow(cx, cy, cx + rr + 12, cy, color=GUIDE, width=1.2, head=6)
    svg.text(cx + rr + 18, cy, "x", GUIDE, 13)
    # the view from above has y pointing up the page
    svg.line(cx, cy, cx + rr * math.cos(phi), cy - rr * math.sin(phi), GUIDE, 1)
    svg.circle(cx + rr * math.cos(phi), cy - rr * math.sin(phi), 4, fill="#c9d8ea")
    turn = phi % (2 * math.pi)
    arc = [(cx + 16 * math.cos(a), cy - 16 * math.sin(a)) for a in [turn * i / 12 for i in range(13)]]
    svg.polyline(arc, ACCENT, 1.6)
    svg.text(cx + 25 * math.cos(turn / 2) + 2, cy - 25 * math.sin(turn / 2), "φ", ACCENT, 14)
    _gravity(svg, 286, 120)
    return svg


def rotating_parabola(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    ox, oy, sx = 150.0, 200.0, 110.0
    half = 1.3
    pts = [(ox + sx * u, oy - sx * 0.9 * u * u) for u in [-half + 2 * half * i / 60 for i in range(61)]]
    svg.polyline(pts, INK, 2.2)
    svg.line(ox, oy + 14, ox, 26, GUIDE, 1.5, dash=True)
    svg.ellipse(ox, 40, 34, 8, ACCENT, dash=False)
    svg.arrow(ox + 8, 48, ox + 22, 47, color=ACCENT, width=1.5)
    svg.text(ox + 52, 36, "ω", PARAM, 17)
    rho = 0.8
    bx, by = ox + sx * rho, oy - sx * 0.9 * rho * rho
    svg.circle(bx, by, 9, fill="#c9d8ea")
    svg.text(bx + 20, by - 4, "m", PARAM)
    svg.arrow(ox, oy + 22, bx, oy + 22, color=ACCENT, width=1.8)
    svg.text((ox + bx) / 2, oy + 34, "ρ", ACCENT, 17)
    svg.line(bx, by + 10, bx, oy + 16, GUIDE, 1, dash=True)
    svg.text(205, 196, "z = α ρ²", PARAM, 15, anchor="start")
    _gravity(svg, 284, 110)
    return svg


def double_pendulum(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    t1 = _drawing_angle(q.get("theta1", 0.6), 0.35, 0.7)
    t2 = _drawing_angle(q.get("theta2", 0.9), 0.5, 1.0)
    px, py, l1, l2 = 130.0, 24.0, 92.0, 84.0
    ax, ay = px + l1 * math.sin(t1), py + l1 * math.cos(t1)
    bx, by = ax + l2 * math.sin(t2), ay + l2 * math.cos(t2)
    svg.line(px - 40, py, px + 40, py, width=3)
    for i in range(5):
        svg.line(px - 36 + 18 * i, py, px - 44 + 18 * i, py - 8, width=1.2)
    # the angles, each from the downward vertical through its own pivot
    svg.line(px, py, px, py + l1 + 10, GUIDE, 1.5, dash=True)
    svg.line(ax, ay, ax, ay + l2 + 10, GUIDE, 1.5, dash=True)
    svg.line(px, py, ax, ay, width=2)
    svg.line(ax, ay, bx, by, width=2)
    svg.arc(px, py, 44, math.pi / 2, math.pi / 2 - t1, arrow=True)
    svg.text(px + 58 * math.sin(t1 / 2) + 4, py + 58 * math.cos(t1 / 2), "θ₁", ACCENT, 16)
    svg.arc(ax, ay, 40, math.pi / 2, math.pi / 2 - t2, arrow=True)
    svg.text(ax + 54 * math.sin(t2 / 2) + 6, ay + 54 * math.cos(t2 / 2), "θ₂", ACCENT, 16)
    # lengths on the outer side of each rod, away from the angle marks
    svg.text((px + ax) / 2 + 16 * math.cos(t1), (py + ay) / 2 - 16 * math.sin(t1), "l₁", PARAM)
    svg.text((ax + bx) / 2 + 16 * math.cos(t2), (ay + by) / 2 - 16 * math.sin(t2), "l₂", PARAM)
    svg.circle(ax, ay, 10, fill="#c9d8ea")
    svg.text(ax + 22, ay - 8, "m₁", PARAM)
    svg.circle(bx, by, 10, fill="#c9d8ea")
    svg.text(bx + 22, by + 4, "m₂", PARAM)
    _gravity(svg, 40, 150)
    return svg


def physical_pendulum(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    """A uniform rod hung from a pivot at one end: the rod drawn as a bar, its centre of mass marked halfway."""
    svg = Svg()
    theta = _drawing_angle(q.get("theta", 0.8))
    px, py, length, half_width = 150.0, 28.0, 170.0, 6.0
    ux, uy = math.sin(theta), math.cos(theta)  # along the rod, downward from the pivot
    nx, ny = uy, -ux  # across the rod
    ex, ey = px + length * ux, py + length * uy
    cx, cy = px + length * ux / 2, py + length * uy / 2
    svg.line(px - 40, py, px + 40, py, width=3)
    for i in range(5):
        svg.line(px - 36 + 18 * i, py, px - 44 + 18 * i, py - 8, width=1.2)
    svg.line(px, py, px, py + length + 8, GUIDE, 1.5, dash=True)
    svg.polygon(
        [
            (px + half_width * nx, py + half_width * ny),
            (ex + half_width * nx, ey + half_width * ny),
            (ex - half_width * nx, ey - half_width * ny),
            (px - half_width * nx, py - half_width * ny),
        ],
        fill="#c9d8ea",
    )
    svg.circle(px, py, 4)
    # the centre of mass, halfway down the rod
    svg.circle(cx, cy, 4, fill=ACCENT, color=ACCENT)
    svg.text(cx + 22 * nx + 8, cy + 22 * ny + 4, "cm", ACCENT, 13, anchor="start")
    svg.arc(px, py, 52, math.pi / 2, math.pi / 2 - theta, arrow=True)
    mid = math.pi / 2 - theta / 2
    svg.text(px + 66 * math.cos(mid), py + 66 * math.sin(mid), "θ", ACCENT, 17)
    # the length on the outer side of the rod, away from the angle mark
    svg.text((px + ex) / 2 - 20 * nx, (py + ey) / 2 - 20 * ny + 4, "l", PARAM)
    svg.text(ex - 22 * nx, ey - 22 * ny + 8, "M", PARAM)
    _gravity(svg, 40, 150)
    return svg
