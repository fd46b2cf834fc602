"""A standalone Python script: derive q̈ from L with SymPy, integrate with scipy, print the end state.

It needs numpy, scipy and sympy only.  Its last line of output is one JSON
object, ``{"t": t_end, "state": {"theta": ..., "theta_dot": ...}}``, the same
keys as the app's simulation ``state``, so the two can be compared (t is earlier
where a terminal event of the scene ends the run, as in the app).
"""

from __future__ import annotations

from app.service.export.code import (
    ACCELERATION_LINES,
    DT_LINES,
    EULER_LAGRANGE_LINES,
    Naming,
    event_lines,
    simulation_lines,
)
from app.service.export.source import Source

RTOL = 1e-10
ATOL = 1e-12


def script(source: Source) -> str:
    d = source.derivation
    naming = Naming.of(d)
    state_names = [*naming.coordinates, *(f"{q}_dot" for q in naming.coordinates)]
    lines = [
        "#!/usr/bin/env python3",
        '"""Equations of motion from a Lagrangian, derived with SymPy and integrated with scipy.',
        "",
        "Exported by Lagrange. Needs numpy, scipy and sympy. Prints the state at t_end (or where the set-up ends) as JSON on its last line.",
        '"""',
        "",
        "import json",
        "",
        "import numpy as np",
        "import sympy as sp",
        "from scipy.integrate import solve_ivp",
        "",
        *naming.symbol_lines(),
        "",
        "",
        *DT_LINES,
        "",
        "",
        "# The Lagrangian and the generalized forces Q (d/dt ∂L/∂q̇ − ∂L/∂q = Q)",
        f"L = {naming.code(d.mechanics.L)}",
        f"Q = {naming.code_list(d.mechanics.Q)}",
        "",
        *EULER_LAGRANGE_LINES,
        "",
        *ACCELERATION_LINES,
        "",
        *simulation_lines(naming, [p.default for p in source.parameters], source.initial, source.t_end),
        *event_lines(naming, d, source.events),
        f'sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol={RTOL!r}, atol={ATOL!r}, events=events)',
        "if not sol.success:",
        '    raise SystemExit(f"the integration stopped: {sol.message}")',
        f"names = {state_names!r}",
        "end = np.asarray(sol.y[:, -1], dtype=float)",
        'print(json.dumps({"t": float(sol.t[-1]), "state": dict(zip(names, end.tolist()))}))',
    ]
    return "\n".join(lines) + "\n"
