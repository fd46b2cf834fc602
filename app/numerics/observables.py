"""Energy, Hamiltonian, conserved quantities and constraint forces along a trajectory.

Every quantity is the engine's own expression (E = T + U, h = sum p q_dot - L,
each conserved quantity, det M, and the derivation's constraint forces, as
SymPy expressions), printed as one vectorised function over all samples.  The drift of each quantity the engine
calls conserved is measured, and warnings are raised where the numbers say
something the reader should know: a conserved quantity that drifted, a path
that passes close to a singular point of the coordinates (det M -> 0), a
string or surface force that would have to pull the wrong way.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from app.engine.equations.constraints import ConstraintForce
from app.numerics import jit
from app.numerics.generate import Names, observables_source
from app.numerics.system import NumericSystem

DRIFT_WARNING = 1e-6  # relative drift of a conserved quantity worth a warning (at least 100 rtol)
SINGULAR_RATIO = 1e-6  # det M falling below this fraction of its value at the start


@dataclass
class Observables:
    system: NumericSystem
    labels: list[str]  # "energy", "hamiltonian", "det", "T", "U", "conserved:<name>", "force:<i>"
    forces: tuple[ConstraintForce, ...]  # force:<i> is the i-th
    function: Any = None

    def evaluate(self, t: np.ndarray, y: np.ndarray, k: np.ndarray) -> dict[str, np.ndarray]:
        n = self.system.n
        with np.errstate(all="ignore"):
            values = self.function(t, y[:, :n].T, y[:, n:].T, k)
        return dict(zip(self.labels, values, strict=True))


def build(system: NumericSystem, constraint_forces: Sequence[ConstraintForce] = ()) -> Observables:
    d = system.derivation
    en = d.energetics
    exprs: list[sp.Expr] = [en.energy, en.hamiltonian]
    labels = ["energy", "hamiltonian"]
    if system.n <= 4:
        # det M by Berkowitz (division-free, no simplification)
        exprs.append(d.equations.mass_matrix.det(method="berkowitz"))
        labels.append("det")
    for c in en.conserved:
        # the quantity, and the sum of its terms' sizes: the scale its drift is measured against
        exprs += [c.expr, sum((sp.Abs(term) for term in sp.Add.make_args(c.expr)), sp.Integer(0))]
        labels += [f"conserved:{c.name}", f"scale:{c.name}"]
    for i, f in enumerate(constraint_forces):
        # the force along grad g on its particle, a function of q, q_dot, t and the parameters
        exprs.append(f.force)
        labels.append(f"force:{i}")
    source = observables_source(Names.of(d), exprs)
    function = jit.python_functions({"observe": source})["observe"]
    return Observables(system, labels, tuple(constraint_forces), function)


def _drift(values: np.ndarray) -> float:
    finite = values[np.isfinite(values)]
    return float(np.max(np.abs(finite - values[0]))) if finite.size and np.isfinite(values[0]) else float("nan")


def summarize(obs: Observables, t: np.ndarray, values: dict[str, np.ndarray], rtol: float) -> dict[str, Any]:
    """Drifts and warnings; the per-sample series stay in ``values``."""
    warnings: list[str] = []
    drifts: dict[str, dict[str, float]] = {}
    d = obs.system.derivation
    for c in d.energetics.conserved:
        series = values[f"conserved:{c.name}"]
        absolute = _drift(series)
        # relative to the largest sum of the sizes of its terms (p_X = (M + m) X_dot + m cos(a) D_dot is 0
        # when the two terms cancel, but each term shows the size round-off acts on)
        scale = float(np.nanmax(values[f"scale:{c.name}"])) if series.size else 0.0
        relative = absolute / scale if scale > 0 else (0.0 if absolute == 0 else float("inf"))
        drifts[c.name] = {"absolute": absolute, "relative": relative}
        if relative > max(DRIFT_WARNING, 100 * rtol) and np.isfinite(relative):
            warnings.append(
                f"{c.name} is conserved (the engine: {c.reason.rstrip('.')}) but drifted by {absolute:.3g} "
                f"({relative:.2g} of its size) along this run"
            )
    det = np.abs(values.get("det", np.zeros(0)))
    if det.size and det[0] > 0:
        ratio = float(np.nanmin(det) / det[0])
        if ratio < SINGULAR_RATIO:
            at = float(t[int(np.nanargmin(det))])
            warnings.append(
                f"near t = {at:.4g} s the path passes close to a singular point of the coordinates, where they "
                "fail (as at r = 0 of polar coordinates or at the apex of a cone) and the equations divide by "
                "nearly zero; the numbers near that instant are less accurate: see how far the conserved "
                "quantities drifted"
            )
    for i, force in enumerate(obs.forces):
        series = values[f"force:{i}"]
        if force.constraint.slack_when_negative and series.size and np.nanmin(series) < 0:
            at = float(t[int(np.argmax(series < 0))])
            warnings.append(
                f"{force.constraint.name} becomes negative at t = {at:.4g} s: a string or surface cannot pull that way, "
                "so the real motion would leave the constraint there (the simulation keeps it)"
            )
    return {
        "max_energy_drift": _drift(values["energy"]),
        "max_hamiltonian_drift": _drift(values["hamiltonian"]),
        "conserved_drift": drifts,
        "warnings": warnings,
    }
