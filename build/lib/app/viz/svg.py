"""A tiny SVG writer for the set-up diagrams (strings in, markup out, all escaped)."""

from __future__ import annotations

import math
from html import escape

INK = "#1b1f24"  # contrast 16:1 on white
ACCENT = "#0b5cad"  # coordinates (7:1 on white)
PARAM = "#8a3b00"  # parameters (7.5:1 on white)
GUIDE = "#57606a"  # dashed guides (6:1 on white)


def _num(x: float) -> str:
    return f"{x:.1f}".rstrip("0").rstrip(".")


class Svg:
    """Collects shapes; ``render`` wraps them with an accessible title and description."""

    def __init__(self, width: int = 320, height: int = 240):
        self.width, self.height = width, height
        self.parts: list[str] = []

    def line(self, x1: float, y1: float, x2: float, y2: float, color: str = INK, width: float = 2, dash: bool = False):
        style = ' stroke-dasharray="5 4"' if dash else ""
        self.parts.append(
            f'<line x1="{_num(x1)}" y1="{_num(y1)}" x2="{_num(x2)}" y2="{_num(y2)}" '
            f'stroke="{color}" stroke-width="{_num(width)}"{style}/>'
        )

    def polyline(
        self, points: list[tuple[float, float]], color: str = INK, width: float = 2, fill: str = "none", dash=False
    ):
        pts = " ".join(f"{_num(x)},{_num(y)}" for x, y in points)
        style = ' stroke-dasharray="5 4"' if dash else ""
        self.parts.append(
            f'<polyline points="{pts}" fill="{fill}" stroke="{color}" stroke-width="{_num(width)}" '
            f'stroke-linejoin="round"{style}/>'
        )

    def polygon(self, points: list[tuple[float, float]], fill: str = "#e8eef5", color: str = INK, width: float = 2):
        pts = " ".join(f"{_num(x)},{_num(y)}" for x, y in points)
        self.parts.append(f'<polygon points="{pts}" fill="{fill}" stroke="{color}" stroke-width="{_num(width)}"/>')

    def circle(self, x: float, y: float, r: float, fill: str = INK, color: str = INK, width: float = 1.5, dash=False):
        style = ' stroke-dasharray="5 4"' if dash else ""
        self.parts.append(
            f'<circle cx="{_num(x)}" cy="{_num(y)}" r="{_num(r)}" fill="{fill}" stroke="{color}" '
            f'stroke-width="{_num(width)}"{style}/>'
        )

    def ellipse(self, x: float, y: float, rx: float, ry: float, color: str = GUIDE, dash: bool = True):
        style = ' stroke-dasharray="5 4"' if dash else ""
        self.parts.append(
            f'<ellipse cx="{_num(x)}" cy="{_num(y)}" rx="{_num(rx)}" ry="{_num(ry)}" fill="none" '
            f'stroke="{color}" stroke-width="1.5"{style}/>'
        )

    def rect(self, x: float, y: float, w: float, h: float, fill: str = "#dfe7f1", color: str = INK):
        self.parts.append(
            f'<rect x="{_num(x)}" y="{_num(y)}" width="{_num(w)}" height="{_num(h)}" fill="{fill}" '
            f'stroke="{color}" stroke-width="2"/>'
        )

    def text(self, x: float, y: float, label: str, color: str = INK, size: int = 15, anchor: str = "middle"):
        self.parts.append(
            f'<text x="{_num(x)}" y="{_num(y)}" fill="{color}" font-size="{size}" text-anchor="{anchor}" '
            f'dominant-baseline="middle" font-style="italic" font-family="Georgia, serif">{escape(label)}</text>'
        )

    def arrow(self, x1: float, y1: float, x2: float, y2: float, color: str = INK, width: float = 2, head: float = 8):
        self.line(x1, y1, x2, y2, color, width)
        angle = math.atan2(y2 - y1, x2 - x1)
        left = (x2 - head * math.cos(angle - 0.4), y2 - head * math.sin(angle - 0.4))
        right = (x2 - head * math.cos(angle + 0.4), y2 - head * math.sin(angle + 0.4))
        self.polygon([(x2, y2), left, right], fill=color, color=color, width=1)

    def arc(self, cx: float, cy: float, r: float, start: float, end: float, color: str = ACCENT, arrow: bool = False):
        """An arc of radius r from angle ``start`` to ``end`` (radians, SVG's y-down convention)."""
        n = max(4, int(abs(end - start) * 12))
        pts = [
            (cx + r * math.cos(start + (end - start) * i / n), cy + r * math.sin(start + (end - start) * i / n))
            for i in range(n + 1)
        ]
        self.polyline(pts, color=color, width=1.8)
        if arrow and len(pts) > 2:
            self.arrow(*pts[-2], *pts[-1], color=color, width=1.8, head=7)

    def spring(self, x1: float, y1: float, x2: float, y2: float, coils: int = 7, amplitude: float = 6, color=INK):
        length = math.hypot(x2 - x1, y2 - y1) or 1.0
        ux, uy = (x2 - x1) / length, (y2 - y1) / length
        nx, ny = -uy, ux
        pts = [(x1, y1)]
        lead = 0.12 * length
        pts.append((x1 + ux * lead, y1 + uy * lead))
        for i in range(1, 2 * coils):
            s = lead + (length - 2 * lead) * i / (2 * coils)
            side = amplitude if i % 2 else -amplitude
            pts.append((x1 + ux * s + nx * side, y1 + uy * s + ny * side))
        pts += [(x2 - ux * lead, y2 - uy * lead), (x2, y2)]
        self.polyline(pts, color=color, width=1.8)

    def render(self, title: str, description: str, ident: str) -> str:
        body = "".join(self.parts)
        return (
            f'<svg class="diagram" viewBox="0 0 {self.width} {self.height}" role="img" '
            f'aria-labelledby="{ident}-title {ident}-desc" xmlns="http://www.w3.org/2000/svg">'
            f'<title id="{ident}-title">{escape(title)}</title><desc id="{ident}-desc">{escape(description)}</desc>'
            f"{body}</svg>"
        )
