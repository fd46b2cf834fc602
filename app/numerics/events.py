"""Terminal events: where a run leaves its set-up (a block reaching the foot of its ramp).

An event is a function g(t, q, q_dot; k) that is positive while the set-up holds;
the run ends at the first instant g falls below zero.  The integrators run to
the end on their own grid of samples; the event is then found on that grid and
pinned down between the two samples around it.  There the state is the cubic
Hermite interpolant of the two samples and their slopes y' = f(t, y):

    y(t_a + s h) = h00(s) y_a + h10(s) h y'_a + h01(s) y_b + h11(s) h y'_b,
    h00 = 2s³ − 3s² + 1,  h10 = s³ − 2s² + s,  h01 = −2s³ + 3s²,  h11 = s³ − s²,

accurate to O(h⁴) like the samples themselves at the page's spacing.  The root
of g in s is bracketed by evaluating g on GRID points of the interval at once
(one vectorised call), narrowing to the cell where it changes sign, ROUNDS
times, and then taken where the straight line through g at the cell's two ends
crosses zero.  A run that starts with g < 0 ends at once.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from app.engine.errors import DerivationError
from app.engine.parser.parse import parse_expression
from app.numerics import jit
from app.numerics.generate import Names, observables_source
from app.numerics.methods import Trajectory
from app.numerics.system import NumericSystem

GRID = 64  # points per narrowing round
ROUNDS = 4  # the last cell is 64^-4 (about 6e-8) of the interval between two samples


@dataclass(frozen=True)
class EventFunction:
    name: str
    message: str
    g: Callable[..., list[np.ndarray]]  # observe(t, Q, V, k): g on arrays of samples


@dataclass(frozen=True)
class Hit:
    """An event that happened: its index among the samples (the first sample past it), time and state.

    Plain data (the event's name and message, not its function), so that an outcome computed in a
    worker process can be sent back."""

    name: str
    message: str
    index: int
    t: float
    y: np.ndarray

    def as_json(self) -> dict[str, Any]:
        return {"name": self.name, "t": self.t, "message": self.message}


def compile_events(system: NumericSystem, events: Sequence[Any]) -> list[EventFunction]:
    """Each declared event (``name``, ``expression``, ``message``) as a vectorised function of the state."""
    d = system.derivation
    out = []
    for event in events:
        try:
            expr = parse_expression(event.expression, d.table.namespace())
        except DerivationError as exc:
            raise DerivationError(f"event {event.name!r}: {exc}") from exc
        source = observables_source(Names.of(d), [expr])
        out.append(EventFunction(event.name, event.message, jit.python_functions({"observe": source})["observe"]))
    return out


def _g(event: EventFunction, t: np.ndarray, y: np.ndarray, k: np.ndarray, n: int) -> np.ndarray:
    with np.errstate(all="ignore"):
        return event.g(t, y[:, :n].T, y[:, n:].T, k)[0]


def _hermite(s: Any, h: float, ya: np.ndarray, fa: np.ndarray, yb: np.ndarray, fb: np.ndarray) -> np.ndarray:
    s2, s3 = s * s, s * s * s
    return (2 * s3 - 3 * s2 + 1) * ya + (s3 - 2 * s2 + s) * h * fa + (-2 * s3 + 3 * s2) * yb + (s3 - s2) * h * fb


def first_hit(
    system: NumericSystem, events: Sequence[EventFunction], trajectory: Trajectory, k: np.ndarray
) -> Hit | None:
    """The earliest event along the run's samples, located between samples; None when the set-up holds throughout."""
    t, y, n = trajectory.t, trajectory.y, system.n
    best: Hit | None = None
    for event in events:
        g = _g(event, t, y, k, n)
        below = np.flatnonzero(g < 0)
        if below.size == 0:
            continue
        i = int(below[0])
        if best is not None and i >= best.index:
            continue
        if i == 0:
            best = Hit(event.name, event.message, 0, float(t[0]), y[0].copy())
            continue
        ta, tb, h = float(t[i - 1]), float(t[i]), float(t[i] - t[i - 1])
        ya, yb = y[i - 1], y[i]
        fa, fb = np.asarray(system.f(ta, ya, k)), np.asarray(system.f(tb, yb, k))
        lo, hi = 0.0, 1.0  # g >= 0 at lo, g < 0 at hi
        g_lo, g_hi = float(g[i - 1]), float(g[i])
        for _ in range(ROUNDS):
            s = np.linspace(lo, hi, GRID + 1)
            states = _hermite(s[:, None], h, ya, fa, yb, fb)
            values = _g(event, ta + s * h, states, k, n)
            below = np.flatnonzero(values < 0)
            if below.size == 0 or below[0] == 0:
                break  # round-off at the cell's ends: keep the cell found so far
            j = int(below[0])  # values[j - 1] >= 0 > values[j]
            lo, hi, g_lo, g_hi = float(s[j - 1]), float(s[j]), float(values[j - 1]), float(values[j])
        # the zero of the line through (lo, g_lo) and (hi, g_hi)
        root = lo + (hi - lo) * g_lo / (g_lo - g_hi) if g_lo > g_hi else hi
        best = Hit(event.name, event.message, i, ta + root * h, _hermite(root, h, ya, fa, yb, fb))
    return best


def before(trajectory: Trajectory, hit: Hit) -> Trajectory:
    """The samples before the event (the part an error estimate can compare with a reference on the same grid)."""
    return replace(trajectory, t=trajectory.t[: hit.index], y=trajectory.y[: hit.index])


def ended(trajectory: Trajectory, hit: Hit) -> Trajectory:
    """The run up to the event: the samples before it, then the state at the event itself."""
    return replace(
        trajectory,
        t=np.append(trajectory.t[: hit.index], hit.t),
        y=np.vstack([trajectory.y[: hit.index], hit.y[None, :]]),
        complete=True,
        stop_reason="",
    )
