"""The page model of a system a user typed: the scene page's model, built from its derivation document.

Pure Python on the derivation JSON (expression trees, no SymPy): what the animation
draws (the particles as declared; nothing for a system given by L or by T and U) and
which optional panels the page asks for (the registry in ``panels.py`` adds the rest).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from app.viz.page_model import scene_page

# the optional panels (app/viz/panels.py) a user's system gets wherever its derivation supports them
PANELS = ("effective-potential", "small-oscillations", "poincare")


def _display_particles(spec: dict[str, Any]) -> list[tuple[str, tuple[str, str, str]]]:
    """What the animation draws: the particles as declared (none for a system given by L or by T and U)."""
    return [
        (p.get("label") or "", tuple(p["position"]) + ("0",) * (3 - len(p["position"])))
        for p in spec.get("particles") or []
    ]


def model_of(spec: dict[str, Any], doc: dict[str, Any], methods: Sequence[str]) -> dict[str, Any]:
    """The scene page model for a user system (pure Python: expression trees, no SymPy)."""
    info = {
        "id": "playground",
        "title": "Your system",
        "section": "",
        "summary": "",
        "statement": "",
        "figure": "The system as declared, drawn at its initial state.",
        "panels": PANELS,
        "initial": {q: 1.0 for q in spec["coordinates"]},
        "t_end": 10.0,
    }
    return scene_page(doc, info, _display_particles(spec), methods, spec.get("nonnegative") or (), scene=False)
