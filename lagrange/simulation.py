"""A simulation in a notebook: the derived equations integrated by the book's methods, with the error estimate."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from app.numerics import limits
from app.numerics.methods import AUTO
from app.numerics.simulate import Outcome
from app.numerics.simulate import simulate as integrate
from app.numerics.system import numeric_system
from app.service.simulations.simulate_request import initial_state, parameter_vector
from lagrange.derivation import Derivation


@dataclass(frozen=True)
class Simulation:
    """Samples of a run: ``t``, each coordinate and rate by name (``run["theta"]``, ``run["theta_dot"]``),
    the method that ran, its estimated error (the largest |q − q_reference| over the samples, or None
    when none was estimated) and the warnings a page would show."""

    t: np.ndarray
    y: np.ndarray  # (len(t), 2n): the coordinates, then their rates
    names: tuple[str, ...]
    method: str
    error: float | None
    warnings: tuple[str, ...]

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self.names:
            raise KeyError(f"{name!r}: this run has {', '.join(self.names)}")
        return self.y[:, self.names.index(name)]

    def __repr__(self) -> str:
        error = "not estimated" if self.error is None else f"{self.error:.2g}"
        return f"<Simulation: {self.t.size} samples to t = {self.t[-1]:g} s by {self.method}, error {error}>"


def simulate(
    derivation: Derivation,
    t_end: float = 10.0,
    *,
    initial: Mapping[str, float] | None = None,
    parameters: Mapping[str, float] | None = None,
    method: str = AUTO,
    rtol: float = limits.RTOL_DEFAULT,
    samples: int = limits.SAMPLES_DEFAULT,
) -> Simulation:
    """Integrate the derived equations from ``initial`` (coordinates and ``<q>_dot`` rates; a scene's own start
    for what is left out, else 0) with ``parameters`` (their defaults for what is left out)."""
    d = derivation.derived
    scene = derivation.system._scene
    k = parameter_vector(d, parameters or {})
    y0 = initial_state(d, initial or {}, scene.initial if scene else {})
    outcome: Outcome = integrate(numeric_system(d), k, y0, t_end, samples, method, rtol)
    names = tuple(d.table.names)
    trajectory = outcome.trajectory
    return Simulation(
        t=trajectory.t,
        y=trajectory.y,
        names=names + tuple(f"{q}_dot" for q in names),
        method=outcome.method,
        error=outcome.estimate.value if outcome.estimate else None,
        warnings=tuple(outcome.warnings),
    )
