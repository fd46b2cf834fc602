"""Poincaré sections: where orbits cross a plane q_i = c in one direction, on one energy surface.

For two conservative degrees of freedom the motion stays on a 3-D energy
surface h = E; recording (q_j, p_j) each time q_i passes c upward reduces it to
a map of the plane.  An integrable motion leaves each orbit's points on a curve
(an invariant torus cut by the plane); a chaotic one scatters them over an area.

Crossings are events ``g(y) = q_i - c = 0``: the compiled DOP853 run is
sampled at half its mean step (its dense output), a sign change of g between
two samples brackets a crossing, and a short scipy DOP853 run with event
detection over that bracket locates it to the run's tolerance.  For an angle
g is ``sin(q_i - c)`` with crossings kept where ``cos(q_i - c) > 0``, so every
turn through c counts and none through c + pi.

Starting states on one surface: q_i = c, the other coordinates on a grid,
every velocity 0 except q_dot_i, which the energy fixes.  h is quadratic in
q_dot_i (h = T2 - T0 + U), so h(s) = A s^2 + B s + C is read off three values
and A s^2 + B s + C = E solved for the root whose sign is the direction.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from app.limits import POINCARE_PIECE as PIECE_SECONDS
from app.limits import POINCARE_T_END
from app.numerics import limits
from app.numerics.errors import SimulationError, TooMuchWork
from app.numerics.methods import METHODS, Problem
from app.numerics.methods.scipy_ivp import scipy_integrate
from app.numerics.observables import Observables
from app.numerics.system import NumericSystem


@dataclass
class Orbit:
    start: np.ndarray  # (2n,) state at t = 0
    t: np.ndarray  # crossing times
    states: np.ndarray  # (N, 2n) states at the crossings
    momenta: np.ndarray  # (N, n) generalized momenta there
    energy_drift: float  # max |h - h(0)| / max(1, |h(0)|) over the crossings
    complete: bool  # reached t_end (else the time budget ended it)


@dataclass
class Section:
    index: int  # the coordinate the plane cuts
    value: float  # the plane q_index = value
    direction: int  # +1 crossing upward, -1 downward
    energy: float
    orbits: list[Orbit]


MAX_SAMPLES = 400_000  # samples per piece


def hamiltonian(observables: Observables, y: np.ndarray, k: np.ndarray) -> np.ndarray:
    """h at each row of y (shape (N, 2n))."""
    y = np.atleast_2d(y)
    return observables.evaluate(np.zeros(len(y)), y, k)["hamiltonian"]


def _samples(
    system: NumericSystem,
    k: np.ndarray,
    y0: np.ndarray,
    t0: float,
    t1: float,
    rtol: float,
    atol: float,
    deadline: float,
) -> tuple[np.ndarray, np.ndarray, bool]:
    """The compiled DOP853 run from t0 to t1, sampled at half its mean step (so no crossing hides between samples)."""
    method = METHODS["DOP853-compiled"]
    bound = np.full(y0.size, limits.STATE_BOUND)
    atol_vector = np.full(y0.size, atol)
    pilot = method.integrate(
        Problem(system, k, y0, np.array([t0, t1]), rtol, atol_vector, bound, deadline, limits.COMPILED_STEPS)
    )
    count = int(min(max(2 * pilot.steps + 1, 3), MAX_SAMPLES))
    run = method.integrate(
        Problem(system, k, y0, np.linspace(t0, t1, count), rtol, atol_vector, bound, deadline, limits.COMPILED_STEPS)
    )
    return run.t, run.y, run.complete


def crossings(
    system: NumericSystem,
    observables: Observables,
    k: np.ndarray,
    y0: np.ndarray,
    t_end: float,
    index: int,
    value: float = 0.0,
    direction: int = 1,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    deadline: float | None = None,
) -> Orbit:
    """The crossings of q_index = value (in ``direction``) along one orbit up to t_end."""
    angle = bool(system.periodic and system.periodic[index])
    METHODS["DOP853-compiled"].prepare(system)  # compiling (first use) happens before the clock starts
    deadline = time.perf_counter() + limits.WALL_SECONDS if deadline is None else deadline

    def g(y: np.ndarray) -> np.ndarray:
        # q - c, or sin(q - c) for an angle (every turn through c)
        return np.sin(y[..., index] - value) if angle else y[..., index] - value

    def event(t: float, y: np.ndarray) -> float:
        return float(g(y))

    event.direction = direction  # type: ignore[attr-defined]
    # the run goes in pieces, so a time budget that ends it keeps the crossings found so far
    pieces = max(1, math.ceil(t_end / PIECE_SECONDS))
    edges = np.linspace(0.0, t_end, pieces + 1)
    found_t: list[float] = []
    found_y: list[np.ndarray] = []
    y = y0.astype(float)
    complete = True
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        try:
            t, Y, whole = _samples(system, k, y, a, b, rtol, atol, deadline)
        except TooMuchWork:
            complete = False
            break
        G = g(Y)
        # a sign change in the chosen direction between two samples brackets one crossing
        bracket = np.nonzero((direction * G[:-1] < 0) & (direction * G[1:] >= 0))[0]
        if angle:
            bracket = bracket[np.cos(Y[bracket, index] - value) > 0]
        for i in bracket:
            # located to the run's tolerance by a short adaptive run with event detection
            sol = scipy_integrate().solve_ivp(
                lambda s, z: system.f(s, z, k),
                (t[i], t[i + 1]),
                Y[i],
                method="DOP853",
                events=event,
                rtol=rtol,
                atol=atol,
            )
            if sol.t_events[0].size:
                found_t.append(float(sol.t_events[0][0]))
                found_y.append(np.asarray(sol.y_events[0][0], dtype=float))
        if not whole or time.perf_counter() > deadline:
            complete = False
            break
        y = Y[-1]
    times = np.array(found_t)
    states = np.array(found_y).reshape(-1, y0.size)
    n = system.n
    momenta = np.array([system.momenta(t, z, k) for t, z in zip(times, states, strict=True)]).reshape(-1, n)
    h0 = hamiltonian(observables, y0, k)[0]
    drift = float(np.max(np.abs(hamiltonian(observables, states, k) - h0))) if len(states) else 0.0
    return Orbit(y0.copy(), times, states, momenta, drift / max(1.0, abs(h0)), complete)


def energy_starts(
    system: NumericSystem,
    observables: Observables,
    k: np.ndarray,
    energy: float,
    index: int,
    value: float,
    direction: int,
    count: int,
    span: tuple[float, float] | None = None,
) -> list[np.ndarray]:
    """Up to ``count`` states with h = energy on the plane q_index = value, moving across it in ``direction``."""
    n = system.n
    others = [j for j in range(n) if j != index]
    if not others:
        raise SimulationError("a Poincaré section needs at least two coordinates", "coordinate")
    j = others[0]
    angle = bool(system.periodic and system.periodic[j])
    lo, hi = span if span is not None else ((-math.pi, math.pi) if angle else (-10.0, 10.0))
    grid = np.linspace(lo, hi, 801)[1:-1]
    base = np.zeros((len(grid), 2 * n))
    base[:, index] = value
    base[:, j] = grid
    # h(s) = A s^2 + B s + C at s = -1, 0, 1 (s the velocity of q_index)
    h = []
    for s in (-1.0, 0.0, 1.0):
        y = base.copy()
        y[:, n + index] = s
        h.append(hamiltonian(observables, y, k))
    hm, h0, hp = h
    A, B, C = (hp + hm) / 2 - h0, (hp - hm) / 2, h0
    with np.errstate(all="ignore"):
        disc = B**2 - 4 * A * (C - energy)
        s = (-B + direction * np.sqrt(disc)) / (2 * A)
    ok = np.isfinite(s) & (disc > 0) & (A > 0) & (direction * s > 0)
    if not ok.any():
        raise SimulationError(
            f"no state on the plane with h = {energy:g} moves across it: the energy is below the potential there",
            "energy",
        )
    accessible = grid[ok]
    # evenly spread over the accessible part of the plane, ends excluded
    picks = np.linspace(accessible.min(), accessible.max(), count + 2)[1:-1]
    starts = []
    for x in picks:
        i = int(np.argmin(np.abs(grid - x)))
        if not ok[i]:
            continue
        y = base[i].copy()
        y[n + index] = s[i]
        starts.append(y)
    return starts


def section(
    system: NumericSystem,
    observables: Observables,
    k: np.ndarray,
    energy: float,
    index: int,
    value: float = 0.0,
    direction: int = 1,
    count: int = 6,
    t_end: float = POINCARE_T_END,
    wall_seconds: float = limits.WALL_SECONDS,
    starts: list[np.ndarray] | None = None,
    span: tuple[float, float] | None = None,
) -> Section:
    """Crossings of several orbits on the surface h = energy, sharing one wall-clock budget."""
    if not system.autonomous or system.energy_name is None:
        raise SimulationError(
            "a Poincaré section needs a conserved energy: the system must be autonomous and free of "
            "non-conservative forces",
            "system",
        )
    if starts is None:
        starts = energy_starts(system, observables, k, energy, index, value, direction, count, span)
    METHODS["DOP853-compiled"].prepare(system)  # compiling (first use) happens before the clock starts
    deadline = time.perf_counter() + wall_seconds
    orbits = []
    for i, y0 in enumerate(starts):
        # each orbit gets an equal share of what is left
        share = (deadline - time.perf_counter()) / (len(starts) - i)
        if share <= 0:
            break
        orbits.append(
            crossings(system, observables, k, y0, t_end, index, value, direction, deadline=time.perf_counter() + share)
        )
    return Section(index, value, direction, energy, orbits)
