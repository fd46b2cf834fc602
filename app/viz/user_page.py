"""The page model of a system a user typed: the scene page's model, built from its derivation document.

Pure Python on the derivation JSON (expression trees, no SymPy): what the
animation draws (the particles, or one bead per coordinate) and which panels
the page shows.
"""

from __future__ import annotations

from typing import Any

from app.viz.exprtree import TreeError, tree
from app.viz.page_model import angles, scene_page


def _display_particles(spec: dict[str, Any], doc: dict[str, Any]) -> list[tuple[str, tuple[str, str, str]]]:
    """What the animation draws: the particles, or else one bead per coordinate (on a circle for an angle)."""
    if spec.get("particles"):
        return [
            (p.get("label") or "", tuple(p["position"]) + ("0",) * (3 - len(p["position"]))) for p in spec["particles"]
        ]
    angular = angles(doc)
    beads = []
    for k, q in enumerate(spec["coordinates"]):
        x0, z0 = 3 * k, 0
        position = (f"{x0} + sin({q})", "0", f"{z0} - cos({q})") if q in angular else (q, "0", f"{-1.5 * k}")
        beads.append((q, position))
    return beads


def _moves_in_3d(particles: list[tuple[str, tuple[str, str, str]]], coordinates: list[str]) -> bool:
    moving = set(coordinates) | {"t"}

    def names(node: Any) -> set[str]:
        if isinstance(node, str):
            return {node}
        if isinstance(node, list):
            return set().union(*(names(c) for c in node[1:])) if len(node) > 1 else set()
        return set()

    def moves(text: str) -> bool:
        try:
            return bool(names(tree(text)) & moving)
        except TreeError:
            return False

    return all(any(moves(pos[i]) for _, pos in particles) for i in range(3))


def model_of(spec: dict[str, Any], doc: dict[str, Any], methods: Any) -> dict[str, Any]:
    """The scene page model for a user system (pure Python: expression trees, no SymPy)."""
    particles = _display_particles(spec, doc)
    three_d = bool(spec.get("particles")) and _moves_in_3d(particles, spec["coordinates"])
    panels = ["animation-3d" if three_d else "animation-2d", "energy"]
    if doc["hamiltonian_equals_energy"] is False:
        panels.append("h-vs-e")
    panels += ["momenta", "phase", "effective-potential", "small-oscillations"]
    info = {
        "id": "playground",
        "title": "Your system",
        "section": "",
        "summary": "",
        "statement": "",
        "figure": "The system as declared, drawn at its initial state.",
        "panels": panels,
        "initial": {q: 1.0 for q in spec["coordinates"]},
        "t_end": 10.0,
    }
    return scene_page(doc, info, particles, methods, spec.get("nonnegative") or ())
