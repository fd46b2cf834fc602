"""The derivation's first step: the action S = ∫ L dt, stationary on the true path (Hamilton's principle).

``report.build_steps`` puts it first; it links the derivation to the page's panel "The action"
(static/js/action.js), where the student varies the path and watches S.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from app.engine.derivation.derive import LARGE_FROM, Derivation

KEY = "action"
TITLE = "The action S = ∫ L dt is stationary on the true path"
# with forces Q that no potential describes S alone is not stationary: the title says what the step shows instead
FORCED_TITLE = "Hamilton's principle with a non-conservative force: δS is minus the force's work"


def kinetic_focus_possible(d: Derivation) -> bool:
    """Whether a true path of this system can reach a kinetic focus (a conjugate point).

    The variations η about a true path obey the Jacobi equation d/dt(P η̇ + C η) = C^T η̇ + R η with
    P = ∂²L/∂q̇², C = ∂²L/∂q̇∂q and R = ∂²L/∂q².  Where L is at most linear in the coordinates (R = 0), has no
    product of a coordinate and a velocity (C = 0) and its mass matrix P is constant, it reads d/dt(P η̇) = 0:
    the fields that start at η(0) = 0 are η = a t, which never vanish again, so no focus exists at any time
    (a uniform field, constant forces).  Otherwise a focus may exist; the action panel finds where."""
    q, qd, t = list(d.table.q), list(d.table.qd), d.table.t
    L = d.mechanics.L
    # a large system is not searched term by term (its L can be long): a focus is taken to be possible, which
    # the action panel's numerical search then settles
    if len(q) >= LARGE_FROM:
        return True
    if any(s in d.equations.mass_matrix.free_symbols for s in (*q, t)):
        return True
    for a in q:
        first = sp.diff(L, a)
        for b in (*q, *qd):
            second = sp.diff(first, b)
            if second != 0 and sp.expand(second) != 0:
                return True
    return False


def action_step(d: Derivation) -> dict[str, str]:
    forced = any(Q != 0 for Q in d.mechanics.Q)
    # the condition on the variations is one group (in braces): a narrow page breaks before its "with", never
    # inside it, so no "0" is left alone on a line
    ends = r"\text{ with } {\delta q(t_0) = \delta q(t_1) = 0}"
    rows = [
        r"S[q] = \int_{t_0}^{t_1} L(q, \dot q, t)\,dt",
        rf"\delta S = 0 \quad \text{{for every }} \delta q {ends}"
        if not forced
        # with forces Q the variation of S is minus their work; written δS = −∫ Q·δq dt, both rows start with
        # their left side and their = signs line up
        else rf"\delta S = -\int_{{t_0}}^{{t_1}} Q\cdot\delta q\,dt \quad \text{{for every }} \delta q {ends}",
    ]
    latex = r"\begin{aligned}" + r" \\ ".join(row.replace(" = ", " &= ", 1) for row in rows) + r"\end{aligned}"
    focus = (
        "The true path is a minimum of S only up to the first kinetic focus; for longer times it is a saddle."
        + (
            # that focus is of every variation together; a family that varies fewer coordinates has its own
            " That focus is the first for all the coordinates varied together; varying one coordinate alone, the "
            "others kept on the true path, its focus comes then or later, or never."
            if len(d.table.q) > 1
            else ""
        )
        if kinetic_focus_possible(d)
        else "Here L is at most linear in the coordinates and its mass matrix is constant, so no true path reaches "
        "a kinetic focus: it is a minimum of S for every duration."
    )
    text = (
        "Hamilton's principle: among all paths with the same ends, the true motion makes the action S stationary; a "
        "small change δq that vanishes at both ends changes S only at second order. The Euler–Lagrange equations "
        f"below are this condition written at every instant. {focus} The panel “The action” lets you vary the path "
        "and watch S."
    )
    if forced:
        text += " Here forces Q that no potential describes act, so they join the condition as the work ∫ Q·δq dt."
    integral: Any = sp.Integral(d.mechanics.L, d.table.t)
    return {"key": KEY, "title": FORCED_TITLE if forced else TITLE, "latex": latex, "sympy": sp.sstr(integral), "explanation": text}
