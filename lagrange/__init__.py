"""Lagrangian mechanics in Python: declare a system, derive its equations step by step, simulate them.

The same engine as the web book (app/engine) and the same integrators (app/numerics), without a server::

    import lagrange

    pendulum = lagrange.System(
        coordinates=["theta"],
        parameters={"m": 1.0, "g": 9.81, "l": 1.0},
        kinetic="m*l**2*theta_dot**2/2",
        potential="-m*g*l*cos(theta)",
    )
    d = lagrange.derive(pendulum)        # in Jupyter: the equations of motion, typeset
    d.equations                          # the same as SymPy equations
    d.steps                              # every step: title, LaTeX, reason
    run = lagrange.simulate(d, t_end=10, initial={"theta": 1.0})
    run.t, run["theta"], run.error       # samples, a coordinate, the estimated error

``lagrange.scene("double-pendulum")`` is one of the book's scenes; ``System.from_json`` takes the
playground's JSON (its "Download the system" file, or the body of ``POST /api/derive``).
The console command ``lagrange serve`` starts the web book (docs/notebook.md).
"""

from __future__ import annotations

from app.errors import Refused as Refused
from lagrange.derivation import Derivation, Step, derive
from lagrange.simulation import Simulation, simulate
from lagrange.system import System, scene, scenes

__all__ = ["Derivation", "Refused", "Simulation", "Step", "System", "derive", "scene", "scenes", "simulate"]
