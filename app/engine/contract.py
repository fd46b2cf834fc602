"""The derivation JSON served by the API (the contract later issues rely on)."""

from __future__ import annotations

from typing import Any

from app.engine.derive import Derivation
from app.engine.report import Printer, build_steps
from app.engine.report import display as _show
from app.scenes.types import Parameter


def parameters_json(parameters: tuple[Parameter, ...]) -> dict[str, dict[str, Any]]:
    """Parameter name -> default, unit, allowed range and description."""
    return {
        p.name: {"default": p.default, "unit": p.unit, "min": p.min, "max": p.max, "description": p.description}
        for p in parameters
    }


def derivation_json(d: Derivation) -> dict[str, Any]:
    """Everything derived, with each expression as a sympy string and LaTeX."""
    table, eqs, en, red = d.table, d.equations, d.energetics, d.reduction
    pr = Printer(table.latex_names())
    result: dict[str, Any] = {
        "coordinates": list(table.names),
        "parameters": parameters_json(d.system.parameters),
        "kinetic": pr.pair(d.mechanics.T) if d.mechanics.T is not None else None,
        "potential": pr.pair(d.mechanics.U) if d.mechanics.U is not None else None,
        "lagrangian": pr.pair(d.mechanics.L),
        "hamiltonian": pr.pair(_show(en.hamiltonian)),
        "energy": pr.pair(_show(en.energy)),
        "equations_of_motion": [
            {"coordinate": name, **pr.pair(_show(r)), "latex": f"{pr.tex(_show(r))} = 0"}
            for name, r in zip(table.names, eqs.residuals, strict=True)
        ],
        "accelerations": {name: pr.pair(_show(a)) for name, a in zip(table.names, eqs.accelerations, strict=True)},
        "mass_matrix": [[pr.pair(x) for x in row] for row in eqs.mass_matrix.tolist()],
        "forcing": [pr.pair(_show(x)) for x in eqs.forcing],
        "momenta": {name: pr.pair(_show(p)) for name, p in zip(table.names, eqs.momenta, strict=True)},
        "generalized_forces": {name: pr.pair(f) for name, f in zip(table.names, d.mechanics.Q, strict=True) if f != 0},
        "cyclic": list(en.cyclic),
        "conserved": [
            {"name": c.name, "latex_name": c.latex_name, **pr.pair(_show(c.expr)), "reason": c.reason}
            for c in en.conserved
        ],
        "explicit_time_derivative": pr.pair(en.dL_dt),
        "hamiltonian_equals_energy": en.h_equals_e,
        "hamiltonian_energy_reason": en.reason,
        "energy_minus_hamiltonian": pr.pair(en.energy_minus_h),
        "effective_potential": None,
        "steps": build_steps(d),
    }
    if red is not None:
        result["effective_potential"] = {
            "coordinate": red.coordinate,
            "momenta": [s.name for s in red.momenta],
            "potential": pr.pair(red.effective_potential),
            "mass": pr.pair(red.effective_mass),
            "condition": pr.pair(red.equilibrium_condition),
            "omega_squared": pr.pair(red.omega_squared_at),
            "equilibria": [
                {"position": pr.pair(e.position), "omega_squared": pr.pair(e.omega_squared), "stable": e.stable}
                for e in red.equilibria
            ],
        }
    return result
