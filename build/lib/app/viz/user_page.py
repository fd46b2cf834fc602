"""The page model of a system a user typed: the scene page's model, built from its derivation document.

Pure Python on the derivation JSON (expression trees, no SymPy): what the animation
draws (the particles as declared; nothing for a system given by L or by T and U) and
which optional panels the page asks for (the registry in ``panels.py`` adds the rest).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import asdict
from typing import Any

from app.engine.distances import distance_events
from app.engine.names import unicode
from app.engine.user_system import UserSystem
from app.viz.page_model import scene_page

# the optional panels (app/viz/panels.py) a user's system gets wherever its derivation supports them
PANELS = ("effective-potential", "small-oscillations", "poincare")


def model_of(user: UserSystem, doc: dict[str, Any], methods: Sequence[str]) -> dict[str, Any]:
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
    # nothing: the first coordinate starts moving at 1 per second, and the page says why
    note = ""
    if any(e.get("everywhere") for e in doc.get("normal_modes") or []):
        first = user.coordinates[0]
        initial[f"{first}_dot"] = 1.0
        note = (
            f"Every configuration is an equilibrium, so a start at rest would show nothing: the run starts with "
            f"{unicode(first + '_dot')}(0) = 1 per second."
        )
    # what the animation draws: the particles as declared (none for a system given by L or by T and U)
    particles = [(p.label, p.position) for p in user.system().particles]
    model = scene_page(doc, info, particles, methods, user.nonnegative, scene=False)
    if note:
        model["initial_note"] = note  # shown under "Initial conditions"
    return model
