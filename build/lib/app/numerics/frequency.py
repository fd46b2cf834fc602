"""Measured frequency of an oscillation: the mean period between upward zero crossings.

A crossing between samples i and i+1 (x_i < 0 <= x_{i+1}) is placed by linear
interpolation, t = t_i - x_i (t_{i+1} - t_i) / (x_{i+1} - x_i); the period is the
time from the first crossing to the last over the number of whole cycles between.
"""

from __future__ import annotations

import math

import numpy as np


def measured_omega(t: np.ndarray, x: np.ndarray) -> float | None:
    """Angular frequency 2 pi / period of x(t) about 0, or None with fewer than two upward crossings."""
    t, x = np.asarray(t, dtype=float), np.asarray(x, dtype=float)
    up = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    if up.size < 2:
        return None
    times = t[up] - x[up] * (t[up + 1] - t[up]) / (x[up + 1] - x[up])
    period = (times[-1] - times[0]) / (len(times) - 1)
    return 2 * math.pi / period if period > 0 else None
