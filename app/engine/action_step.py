"""The derivation's first step: the action S = ∫ L dt, stationary on the true path (Hamilton's principle).

``report.build_steps`` puts it first; it links the derivation to the page's panel "The action"
(static/js/action.js), where the student varies the path and watches S.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from app.engine.derive import Derivation

KEY = "action"
TITLE = "The action S = ∫ L dt is stationary on the true path"


def action_step(d: Derivation) -> dict[str, str]:
    forced = any(Q != 0 for Q in d.mechanics.Q)
    rows = [
        r"S[q] = \int_{t_0}^{t_1} L(q, \dot q, t)\,dt",
        r"\delta S = 0 \quad \text{for every } \delta q \text{ with } \delta q(t_0) = \delta q(t_1) = 0"
        if not forced
        # with forces Q the variation of S is minus their work; written δS = −∫ Q·δq dt, both rows start with
        # their left side and their = signs line up (prof-c S12)
        else r"\delta S = -\int_{t_0}^{t_1} Q\cdot\delta q\,dt \quad \text{for every } \delta q "
        r"\text{ with } \delta q(t_0) = \delta q(t_1) = 0",
    ]
    latex = r"\begin{aligned}" + r" \\ ".join(row.replace(" = ", " &= ", 1) for row in rows) + r"\end{aligned}"
    text = (
        "Hamilton's principle: among all paths with the same ends, the true motion makes the action S stationary; a "
        "small change δq that vanishes at both ends changes S only at second order. The Euler–Lagrange equations "
        "below are this condition written at every instant. The true path is a minimum of S only up to the first "
        "kinetic focus; for longer times it is a saddle. The panel “The action” lets you vary the path and watch S."
    )
    if forced:
        text += " Here forces Q that no potential describes act, so they join the condition as the work ∫ Q·δq dt."
    integral: Any = sp.Integral(d.mechanics.L, d.table.t)
    return {"key": KEY, "title": TITLE, "latex": latex, "sympy": sp.sstr(integral), "explanation": text}
