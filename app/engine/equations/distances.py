"""Coordinates declared never negative (distances such as r): where a run of them ends.

A coordinate declared a distance stays ≥ 0.  When the motion carries it to 0 (a bead sliding into the
apex of its cone, a particle through the origin of polar coordinates), the coordinates break down there,
and the equations past that instant describe a point with r < 0, which the declaration rules out.  So
the run ends at the first instant the coordinate falls below 0: a terminal event ``r`` (positive while
the set-up holds), the same kind as a chapter scene's block reaching the foot of its ramp.  The server's
run and the browser's preview both stop there, and the page says why with the time.
"""

from __future__ import annotations

from collections.abc import Sequence

from app.engine.display.names import unicode
from app.scenes import Event


def distance_events(nonnegative: Sequence[str]) -> list[Event]:
    """One terminal event per coordinate declared never negative, in the declared order."""
    return [
        Event(
            f"{q} reaches 0",
            q,
            f"{unicode(q)} reached 0, the end of its declared range ({unicode(q)} ≥ 0, a distance): the "
            "coordinates break down there, so the run ends.",
        )
        for q in nonnegative
    ]
