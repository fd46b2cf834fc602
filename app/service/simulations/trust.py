"""Whether a run can be trusted: its error estimate against the motion it describes.

The run's error estimate (per coordinate where the estimator gives one) is compared with how far
each coordinate moves over the run: its range, or, for a coordinate that hardly moves, a
thousandth of its size.  The worst ratio over the coordinates decides; a run is trusted when
it is below LIMIT (an error of 5 % of the motion is visible in a plot).  The verdict goes out
with every simulation (``trust`` in the result) so that API callers get the same warning as
the page, in the same plain words.

    {"trusted": bool | None, "ratio": float | None, "coordinate": str | None, "message": str | None}

``trusted`` is None when the run has no error estimate (nothing to judge by).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from app.engine.display.names import unicode

LIMIT = 0.05  # estimated error / range of motion above which the motion shown is not reliable


def judge(
    estimate: float | None, by_coordinate: Mapping[str, float], coordinates: Sequence[str], y: np.ndarray
) -> dict[str, Any]:
    """The verdict on a run whose coordinates are the first columns of ``y`` (samples by rows)."""
    worst, where = 0.0, None
    seen = False
    for i, q in enumerate(coordinates):
        err = by_coordinate.get(q, estimate)
        if err is None or not math.isfinite(err):
            continue
        values = y[:, i][np.isfinite(y[:, i])]
        if not values.size:
            continue
        seen = True
        lo, hi = float(values.min()), float(values.max())
        # the range of motion, or for a coordinate at rest a thousandth of its size (never 0)
        scale = max(hi - lo, 1e-3 * max(abs(lo), abs(hi)), 1e-12)
        if err / scale > worst:
            worst, where = err / scale, q
    if not seen:
        return {"trusted": None, "ratio": None, "coordinate": None, "message": None}
    if worst < LIMIT:
        return {"trusted": True, "ratio": worst, "coordinate": where, "message": None}
    percent = f"{100 * worst:.2g}"
    message = (
        f"Not reliable: the estimated error is {percent} % of how far {unicode(where or '')} moves in this run, "
        "so the motion shown may be wrong. Choose a smaller tolerance (rtol) or a shorter run."
    )
    return {"trusted": False, "ratio": worst, "coordinate": where, "message": message}
