"""Set-up diagrams of the sliding and coupled scenes: inclines, table, rail, pulleys.

Same conventions as ``diagrams_swing``: defaults in, labelled ``Svg`` out,
coordinates blue, parameters brown; drawing only, no mechanics.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from app.viz.svg import ACCENT, GUIDE, INK, PARAM, Svg


def _angle_mark(svg: Svg, x: float, y: float, alpha: float, label: str = "α", leftward: bool = False) -> None:
    """The angle between the floor and a slope rising to the right (or, leftward, to the left) of (x, y)."""
    start = math.pi if leftward else 0.0
    end = start + alpha if leftward else -alpha
    svg.arc(x, y, 34, start, end, color=PARAM)
    mid = (start + end) / 2
    svg.text(x + 48 * math.cos(mid), y + 48 * math.sin(mid) + 2, label, PARAM, 16)


def _block_on_slope(svg: Svg, x: float, y: float, alpha: float, size: float = 26) -> tuple[float, float]:
    """A square block resting on a slope of angle alpha, its bottom-centre at (x, y); returns its centre."""
    ux, uy = math.cos(alpha), -math.sin(alpha)  # along the slope, upwards
    nx, ny = -math.sin(alpha), -math.cos(alpha)  # normal, out of the slope
    h = size / 2
    corners = [(x - ux * h, y - uy * h), (x + ux * h, y + uy * h)]
    corners += [(cx + nx * size, cy + ny * size) for cx, cy in reversed(corners)]
    svg.polygon(corners, fill="#c9d8ea")
    return x + nx * h, y + ny * h


def incline(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    alpha = p.get("alpha", math.pi / 6)
    x0, y0, base = 30.0, 210.0, 250.0
    top = (x0 + base, y0 - base * math.tan(alpha))
    svg.polygon([(x0, y0), (x0 + base, y0), top], fill="#eef1f4")
    _angle_mark(svg, x0, y0, alpha)
    s = 0.55 * base / math.cos(alpha)
    bx, by = x0 + s * math.cos(alpha), y0 - s * math.sin(alpha)
    cx, cy = _block_on_slope(svg, bx, by, alpha)
    svg.text(cx - 2, cy + 1, "m", PARAM, 14)
    off = 40
    ax, ay = x0 - off * math.sin(alpha), y0 - off * math.cos(alpha)
    svg.arrow(ax, ay, ax + s * math.cos(alpha), ay - s * math.sin(alpha), color=ACCENT)
    svg.text(ax + 0.5 * s * math.cos(alpha) - 12, ay - 0.5 * s * math.sin(alpha) - 12, "X", ACCENT, 17)
    svg.arrow(60, 40, 60, 76, color=PARAM)
    svg.text(72, 60, "g", PARAM)
    return svg


def _wedge_on_floor(svg: Svg, alpha: float) -> tuple[float, float, float]:
    """The hatched floor and a wedge of angle alpha on it, its slope falling to the right from the top corner; its
    mass M and the angle marked. Returns the top corner (x, y) and the wedge's height."""
    floor = 206.0
    svg.line(10, floor, 310, floor, INK, 2)
    for i in range(16):
        svg.line(14 + 19 * i, floor + 1, 6 + 19 * i, floor + 9, INK, 1)
    x0, base = 86.0, 200.0
    height = min(base * math.tan(alpha), 150.0)
    base = height / math.tan(alpha)
    svg.polygon([(x0, floor), (x0 + base, floor), (x0, floor - height)], fill="#eef1f4")
    svg.text(x0 + base * 0.32, floor - height * 0.22, "M", PARAM, 16)
    _angle_mark(svg, x0 + base, floor, alpha, "α", leftward=True)
    # the wedge's displacement X along the floor, from where it started
    svg.line(20, floor - 6, 20, floor - 60, GUIDE, 1.2, dash=True)
    svg.arrow(20, floor - 40, x0, floor - 40, color=ACCENT)
    svg.text(48, floor - 52, "X", ACCENT, 17)
    svg.arrow(290, 40, 290, 76, color=PARAM)
    svg.text(302, 60, "g", PARAM)
    return x0, floor - height, height


def movable_incline(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    alpha = p.get("alpha", math.pi / 6)
    *apex, height = _wedge_on_floor(svg, alpha)
    d = 0.45 * height / math.sin(alpha)
    bx, by = apex[0] + d * math.cos(alpha), apex[1] + d * math.sin(alpha)
    cx, cy = _block_on_slope(svg, bx, by, -alpha)
    svg.text(cx, cy, "m", PARAM, 14)
    svg.arrow(
        apex[0] + 18 * math.sin(alpha),
        apex[1] - 18 * math.cos(alpha) - 14,
        bx + 18 * math.sin(alpha),
        by - 18 * math.cos(alpha) - 14,
        color=ACCENT,
    )
    svg.text((apex[0] + bx) / 2 + 22, (apex[1] + by) / 2 - 30, "D", ACCENT, 17)
    return svg


def rolling_wedge(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    """The sliding wedge with a cylinder rolling on its slope: the cylinder drawn as a disc touching the slope,
    its radius r to the point of contact, a spoke that turns with it and the way it turns as it rolls down."""
    svg = Svg()
    alpha = p.get("alpha", math.pi / 6)
    *apex, height = _wedge_on_floor(svg, alpha)
    ux, uy = math.cos(alpha), math.sin(alpha)  # down the slope (the drawing's y points down)
    nx, ny = math.sin(alpha), -math.cos(alpha)  # out of the slope, away from the wedge
    radius = 22.0
    # the point of contact, 0.45 of the slope down from the top corner, and the centre r out from it
    d = 0.45 * height / math.sin(alpha)
    bx, by = apex[0] + d * ux, apex[1] + d * uy
    cx, cy = bx + radius * nx, by + radius * ny
    svg.circle(cx, cy, radius, fill="#c9d8ea")
    # the radius r to the point of contact, and a spoke across that turns with the cylinder
    svg.line(cx, cy, bx, by, PARAM, 1.5)
    svg.text(cx + 0.5 * radius * nx - 8 * ux, cy - 0.5 * radius * ny - 12 * uy + 26, "r", PARAM, 14)
    svg.line(cx - radius * ux, cy - radius * uy, cx + radius * ux, cy + radius * uy, INK, 1.5)
    svg.circle(cx, cy, 2.5)
    svg.text(cx - 1.7 * radius * ux, cy - 1.7 * radius * uy - 6, "m", PARAM, 14)
    # it turns clockwise as it rolls down the slope, by the angle s/r
    start = math.atan2(ny, nx)
    svg.arc(cx, cy, radius + 9, start - 0.9, start + 0.5, arrow=True)
    # s: the centre's distance down the slope, drawn parallel to the slope beyond the cylinder
    off = 2 * radius + 16
    svg.arrow(apex[0] + off * nx, apex[1] + off * ny, cx + (radius + 16) * nx, cy + (radius + 16) * ny, color=ACCENT)
    svg.text((apex[0] + cx) / 2 + (off + 12) * nx, (apex[1] + cy) / 2 + (off + 12) * ny, "s", ACCENT, 17)
    return svg


def tabletop(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    theta = q.get("theta", 0.7) or 0.7
    ox, oy, r = 110.0, 150.0, 130.0
    svg.rect(12, 16, 296, 210, fill="#f3f5f7", color=GUIDE)
    svg.line(ox, oy, ox + 180, oy, GUIDE, 1.2, dash=True)
    px, py = ox + r * math.cos(theta), oy - r * math.sin(theta)
    svg.spring(ox, oy, px, py, coils=8)
    svg.circle(ox, oy, 4)
    svg.arc(ox, oy, 40, 0.0, -theta, arrow=True)
    svg.text(ox + 56 * math.cos(theta / 2), oy - 56 * math.sin(theta / 2), "θ", ACCENT, 17)
    svg.text((ox + px) / 2 - 16, (oy + py) / 2 - 10, "r", ACCENT, 17)
    svg.text((ox + px) / 2 + 18, (oy + py) / 2 + 16, "k", PARAM, 16)
    svg.circle(px, py, 11, fill="#c9d8ea")
    svg.text(px + 22, py, "m", PARAM)
    svg.text(250, 206, "top view", GUIDE, 13)
    return svg


def rail_two_body(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    rail = 150.0
    svg.line(10, rail, 310, rail, INK, 3)
    origin = 30.0
    svg.line(origin, rail - 60, origin, rail + 40, GUIDE, 1.2, dash=True)
    x1, x2, w = 100.0, 230.0, 40.0
    svg.rect(x1 - w / 2, rail - 34, w, 32)
    svg.rect(x2 - w / 2, rail - 34, w, 32)
    svg.text(x1, rail - 18, "m₁", PARAM, 15)
    svg.text(x2, rail - 18, "m₂", PARAM, 15)
    svg.spring(x1 + w / 2, rail - 18, x2 - w / 2, rail - 18, coils=7)
    svg.text((x1 + x2) / 2, rail - 44, "k", PARAM, 16)
    svg.arrow(origin, rail + 18, x1, rail + 18, color=ACCENT)
    svg.text((origin + x1) / 2, rail + 30, "x₁", ACCENT, 16)
    svg.arrow(origin, rail + 46, x2, rail + 46, color=ACCENT)
    svg.text((origin + x2) / 2 + 30, rail + 58, "x₂", ACCENT, 16)
    svg.line(x1, rail - 70, x1 + 90, rail - 70, PARAM, 1.5)
    svg.line(x1, rail - 76, x1, rail - 64, PARAM, 1.5)
    svg.line(x1 + 90, rail - 76, x1 + 90, rail - 64, PARAM, 1.5)
    svg.text(x1 + 45, rail - 84, "rest length l₀", PARAM, 13)
    return svg


def pulley(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    ceiling = 22.0
    # every strand vertical, as the constraint assumes (a V of slanted strands has loop length
    # 2√(a² + h²), not linear in Y): the end masses hang d either side of the middle, the movable pulley's two
    # strands rise straight to the fixed pulleys, so each fixed pulley spans from an end mass's strand to one of
    # the movable pulley's, radius (d − r)/2
    mid, half, r = 160.0, 70.0, 18.0
    left, right = mid - half, mid + half
    big = (half - r) / 2
    top = ceiling + 8 + big  # the fixed pulleys' centres, hung just below the ceiling
    svg.line(30, ceiling, 290, ceiling, INK, 3)
    for cx in (left + big, right - big):
        svg.line(cx, ceiling, cx, top, INK, 1.5)
        svg.circle(cx, top, big, fill="#eef1f4")
    # the end masses above the dashed line where U = 0 (y₁, y₂ > 0) and M below it: the string makes
    # Y = −(y₁ + y₂)/2 − c, negative while the end masses are above the line (all three were drawn above it)
    base = 150.0
    y1, y2, centre = 118.0, 100.0, 221.0
    ym = centre - 22 - r  # the movable pulley's centre, M's box hung below it
    # the end masses' strings hang d either side of the middle one's, d marked above the ceiling
    for end in (left, right):
        svg.line(end, 3, end, 17, GUIDE, 1)
        gap = 9 if end < mid else -9
        svg.arrow((end + mid) / 2 - gap, 10, end, 10, color=PARAM, width=1.2, head=6)
        svg.arrow((end + mid) / 2 + gap, 10, mid, 10, color=PARAM, width=1.2, head=6)
        svg.text((end + mid) / 2, 10, "d", PARAM, 15)
    svg.line(mid, 3, mid, 17, GUIDE, 1)
    for x, bottom in ((left, y1 - 16), (mid - r, ym), (mid + r, ym), (right, y2 - 16)):
        svg.line(x, top, x, bottom)
    svg.circle(mid, ym, r, fill="#eef1f4")
    svg.rect(left - 16, y1 - 16, 32, 32)
    svg.text(left, y1, "m₁", PARAM, 14)
    svg.rect(right - 16, y2 - 16, 32, 32)
    svg.text(right, y2, "m₂", PARAM, 14)
    svg.line(mid, ym + r, mid, ym + r + 8)
    svg.rect(mid - 17, ym + r + 8, 34, 28)
    svg.text(mid, centre, "M", PARAM, 14)
    svg.line(20, base, 300, base, GUIDE, 1.2, dash=True)
    svg.text(262, base + 14, "U = 0", GUIDE, 12)
    svg.arrow(left - 30, base, left - 30, y1, color=ACCENT)
    svg.text(left - 44, (base + y1) / 2, "y₁", ACCENT, 16)
    svg.arrow(right + 30, base, right + 30, y2, color=ACCENT)
    svg.text(right + 40, (base + y2) / 2, "y₂", ACCENT, 16)
    # the third height, Y, of M's centre, measured upward like the others: negative, so the arrow from the line
    # down to M is −Y, a positive depth, and is labelled so ("Y" on a downward arrow invites U = −MgY)
    svg.arrow(mid + 34, base, mid + 34, centre, color=ACCENT)
    svg.line(mid + 17, centre, mid + 40, centre, GUIDE, 1, dash=True)
    svg.text(mid + 50, (base + centre) / 2, "−Y", ACCENT, 16)
    # c: how far below the line M would hang with y₁ = y₂ = 0; drawn to the figure's own scale, so that
    # Y = −(y₁ + y₂)/2 − c holds for the heights drawn (the level stops short of the strings)
    level = base + (centre - base) - ((base - y1) + (base - y2)) / 2
    svg.line(16, level, mid - r - 16, level, GUIDE, 1, dash=True)
    svg.arrow(24, base, 24, level, color=PARAM, width=1.4, head=6)
    svg.text(12, (base + level) / 2, "c", PARAM, 15)
    svg.arrow(30, 40, 30, 76, color=PARAM)
    svg.text(42, 58, "g", PARAM)
    return svg


def disc_pulley(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    """An Atwood machine on a massive pulley: a disc of mass M and radius R on a fixed axle, m₁ and m₂ on vertical
    strands from the two sides of its rim, m₂ drawn a height z above the level where both started (m₁ as far
    below it), and a spoke turned by z/R from the upward vertical."""
    svg = Svg()
    ceiling, cx, cy, r = 14.0, 160.0, 62.0, 32.0
    svg.line(132, ceiling, 188, ceiling, INK, 3)
    for i in range(4):
        svg.line(138 + 16 * i, ceiling, 130 + 16 * i, ceiling - 8, INK, 1.2)
    svg.line(cx, ceiling, cx, cy, INK, 2)
    svg.circle(cx, cy, r, fill="#c9d8ea")
    # the string over the top half of the rim, where it grips the pulley
    svg.arc(cx, cy, r, math.pi, 2 * math.pi, color=INK)
    # the turning: a dashed radius where the spoke started (straight up) and the spoke turned from it by z/R,
    # counter-clockwise as the left side goes down with m₁ (SVG angles: y down, so up is −π/2)
    turn = 0.9
    svg.line(cx, cy, cx, cy - r, GUIDE, 1.2, dash=True)
    svg.line(cx, cy, cx + r * math.cos(-math.pi / 2 - turn), cy + r * math.sin(-math.pi / 2 - turn), INK, 2)
    svg.arc(cx, cy, r * 0.62, -math.pi / 2, -math.pi / 2 - turn, arrow=True)
    svg.text(cx - r - 4, cy - r - 2, "z/R", ACCENT, 14, anchor="end")
    svg.circle(cx, cy, 3.5)
    # the radius, from the hub to the rim on the right, below the spoke
    svg.arrow(cx, cy, cx + r * math.cos(0.5), cy + r * math.sin(0.5), color=PARAM, width=1.4, head=6)
    svg.text(cx + 14, cy + 18, "R", PARAM, 14)
    svg.text(cx + r + 16, cy - r + 4, "M", PARAM, 15)
    # the masses started level, a depth d below the axle (the dashed line, where U = 0); m₂ has gone up by z
    # and m₁ down by as much
    base, shift, half = 160.0, 34.0, 15.0
    left, right = cx - r, cx + r
    y1, y2 = base + shift, base - shift  # the masses' centres
    svg.line(left, cy, left, y1 - half)
    svg.line(right, cy, right, y2 - half)
    svg.rect(left - half, y1 - half, 2 * half, 2 * half)
    svg.text(left, y1, "m₁", PARAM, 14)
    svg.rect(right - half, y2 - half, 2 * half, 2 * half)
    svg.text(right, y2, "m₂", PARAM, 14)
    svg.line(40, base, 290, base, GUIDE, 1.2, dash=True)
    svg.text(60, base + 12, "U = 0", GUIDE, 12)
    svg.arrow(left - 30, base, left - 30, y1, color=ACCENT)
    svg.text(left - 42, (base + y1) / 2, "z", ACCENT, 16)
    svg.arrow(right + 30, base, right + 30, y2, color=ACCENT)
    svg.text(right + 42, (base + y2) / 2, "z", ACCENT, 16)
    # d: from the axle's level down to the starting level, on the far right
    svg.line(cx + 6, cy, 292, cy, GUIDE, 1, dash=True)
    svg.arrow(280, cy, 280, base, color=PARAM, width=1.4, head=6)
    svg.text(292, (cy + base) / 2, "d", PARAM, 15)
    svg.arrow(40, 40, 40, 76, color=PARAM)
    svg.text(52, 58, "g", PARAM)
    return svg


def coupled_oscillators(p: dict[str, float], q: dict[str, float], marks: Sequence[str] = ()) -> Svg:
    svg = Svg()
    floor, w = 150.0, 36.0
    svg.line(10, floor, 310, floor, INK, 3)
    for wall in (14.0, 306.0):
        svg.line(wall, floor - 70, wall, floor, INK, 3)
    x1, x2 = 108.0, 212.0  # rest positions of the two masses
    for x, name in ((x1, "m"), (x2, "m")):
        svg.rect(x - w / 2, floor - 34, w, 32)
        svg.text(x, floor - 14, name, PARAM, 15)
    svg.spring(14, floor - 18, x1 - w / 2, floor - 18, coils=6)
    svg.spring(x1 + w / 2, floor - 18, x2 - w / 2, floor - 18, coils=6)
    svg.spring(x2 + w / 2, floor - 18, 306, floor - 18, coils=6)
    svg.text((14 + x1 - w / 2) / 2, floor - 40, "k", PARAM, 16)
    svg.text((x1 + x2) / 2, floor - 40, "κ", PARAM, 16)
    svg.text((x2 + w / 2 + 306) / 2, floor - 40, "k", PARAM, 16)
    # the rest positions, d either side of the middle (the walls 3d out)
    middle = (x1 + x2) / 2
    svg.line(middle, floor - 2, middle, floor - 78, GUIDE, 1.2, dash=True)
    svg.arrow(middle, floor - 66, x2, floor - 66, color=PARAM, width=1.4, head=6)
    svg.line(x2, floor - 36, x2, floor - 72, GUIDE, 1.2, dash=True)
    svg.text((middle + x2) / 2, floor - 72, "d", PARAM, 15)
    # displacements measured from the rest positions
    for x, name in ((x1, "x₁"), (x2, "x₂")):
        svg.line(x, floor + 6, x, floor + 40, GUIDE, 1.2, dash=True)
        svg.arrow(x, floor + 30, x + 34, floor + 30, color=ACCENT)
        svg.text(x + 18, floor + 52, name, ACCENT, 16)
    return svg
