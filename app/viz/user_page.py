"""The page model of a system a user typed: the scene page's model, built from its derivation document.

Pure Python on the derivation JSON (expression trees, no SymPy): what the animation
draws (the particles as declared; nothing for a system given by L or by T and U) and
which optional panels the page asks for (the registry in ``panels.py`` adds the rest).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import asdict
from typing import Any

from app.engine.display.names import unicode
from app.engine.document.model import Document
from app.engine.equations.distances import distance_events
from app.engine.parser.user_system import UserSystem
from app.viz.exprtree import document_tree, evaluate
from app.viz.page_model import scene_page
from app.viz.units import coordinate_units, with_unit

# the optional panels (app/viz/panels.py) a user's system gets wherever its derivation supports them
PANELS = ("effective-potential", "small-oscillations", "poincare")
NEAR = 1.1  # a cyclic coordinate's run starts this many times the steady motion's radius out (a visible oscillation)


def model_of(user: UserSystem, doc: Document, methods: Sequence[str]) -> dict[str, Any]:
    """The scene page model for a user system (pure Python: expression trees, no SymPy)."""
    initial: dict[str, float] = {q: 1.0 for q in user.coordinates}
    info: dict[str, Any] = {
        "id": "playground",
        "title": "Your system",
        "section": "",
        "summary": "",
        "statement": "",
        "figure": "The system as declared, drawn at its initial state.",
        "panels": PANELS,
        "initial": initial,
        "t_end": 10.0,
        # a distance (declared never negative) ends the run where it reaches 0, in the preview as on the server
        "events": [asdict(e) for e in distance_events(user.nonnegative)],
    }
    # where every configuration is an equilibrium (a charge in a uniform magnetic field), a start at rest shows
    # nothing: the first coordinate starts moving at a rate of 1 in its own unit (m/s, rad/s), and the page says why
    note = ""
    rates = coordinate_units(doc, scene=False)["rate_units"]
    if any(e.everywhere for e in doc.normal_modes):
        first = user.coordinates[0]
        initial[f"{first}_dot"] = 1.0
        note = (
            f"Every configuration is an equilibrium, so a start at rest would show nothing: the run starts with "
            f"{unicode(first + '_dot')}(0) = {with_unit('1', rates[first])}."
        )
    # a coordinate that only turns (a cyclic φ) at rest lets a cone's bead or a planet fall into the centre; a
    # start on the steady motion itself makes every plot a point. So the run keeps the conserved momentum of the
    # steady motion through r = 1 (U_eff′ = 0 there) and starts NEAR times farther out: r oscillates about 1
    elif (steady := steady_start(doc, initial, {p.name: p.default for p in user.parameters}, NEAR)) is not None:
        rate, value, r = steady
        steady_at = initial[r]
        initial[r] = NEAR * steady_at
        initial[rate] = value
        note = (
            f"The run starts near the steady motion through {unicode(r)} = {steady_at:g}: with that motion's "
            f"{unicode(rate[:-4])}-momentum, from {unicode(r)} = {initial[r]:g}, so {unicode(rate)}(0) = {with_unit(format(value, '.4g'), rates[rate[:-4]])} "
            f"and {unicode(r)} oscillates about {steady_at:g} (at rest, {unicode(rate[:-4])} would not turn and "
            f"{unicode(r)} would fall). Change {unicode(rate)}(0) to see {unicode(r)} swing wider or leave."
        )
    # what the animation draws: the particles as declared (none for a system given by L or by T and U)
    particles = [(p.label, p.position) for p in user.system().particles]
    model = scene_page(doc, info, particles, methods, user.nonnegative, scene=False)
    if note:
        model["initial_note"] = note  # shown under "Initial conditions"
    return model


def _root(f: Any, lo: float, hi: float) -> float | None:
    """A root of f in [lo, hi] by bisection, or None when f does not change sign there."""
    try:
        a, b = f(lo), f(hi)
    except (ArithmeticError, ValueError):
        return None
    if not (math.isfinite(a) and math.isfinite(b)) or a * b > 0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        c = f(mid)
        if a * c <= 0:
            hi = mid
        else:
            lo, a = mid, c
    return 0.5 * (lo + hi)


def steady_start(
    doc: Document, initial: dict[str, float], params: dict[str, float], near: float = 1.0
) -> tuple[str, float, str] | None:
    """(the cyclic coordinate's rate, its value, the reduced coordinate r) with the momentum of the steady motion
    through r(0), starting from near·r(0) (near = 1: on the steady motion), or None.

    With one conserved momentum p_c the reduction's U_eff′(r; p_c) = 0 is solved for p_c at r(0) (p_c > 0), and
    p_c = ∂L/∂q̇_c, affine in q̇_c, is solved for q̇_c at near·r(0).  Pure Python on the document's expression
    trees."""
    red = doc.effective_potential
    if red is None or len(red.momenta) != 1 or not red.momenta[0].startswith("p_"):
        return None
    held = red.momenta[0]
    cyclic = held[2:]
    condition = document_tree(red.condition)
    momentum = document_tree(doc.momenta.get(cyclic))
    if condition is None or momentum is None:
        return None
    state = {**params, **initial, "t": 0.0}
    state.update({f"{q}_dot": initial.get(f"{q}_dot", 0.0) for q in doc.coordinates})

    def at(p: float) -> float:
        return evaluate(condition, {**state, held: p})

    # the momentum scale: search p in (0, 10⁶] on a log grid for a change of sign, then bisect
    grid = [10.0**k for k in range(-6, 7)]
    for lo, hi in zip(grid, grid[1:], strict=False):
        p = _root(at, lo, hi)
        if p is not None:
            break
    else:
        return None
    rate = f"{cyclic}_dot"
    r = red.coordinate
    state[r] = near * state[r]
    # p_c(q̇_c) = p0 + p1 q̇_c, at the starting radius
    p0 = evaluate(momentum, {**state, rate: 0.0})
    p1 = evaluate(momentum, {**state, rate: 1.0}) - p0
    if not (math.isfinite(p0) and math.isfinite(p1)) or p1 == 0:
        return None
    value = (p - p0) / p1
    return (rate, value, r) if math.isfinite(value) else None
