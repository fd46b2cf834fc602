"""The letters of a document: one table, so that one letter means one quantity on a page.

A document's coordinates and parameters keep the names they were declared with.  The quantities the
engine derives (the mass matrix, the stiffness matrix, a frequency of small oscillations) each have
a list of letters a textbook uses for them; a document takes the first that no coordinate or
parameter already has.  So the pulley and the wedge, whose body has mass M, write the mass matrix
𝓜, and the rotating parabola, turning at the rate ω, writes its small-oscillation frequency Ω.

Every step that prints one of these letters asks ``letter`` (LaTeX) or ``text`` (Unicode) for it,
and ``table`` is the "Symbols" table the page shows and the API serves: each letter once, with what
it means.
"""

from __future__ import annotations

from typing import Any

from app.engine.derive import Derivation
from app.engine.names import latex, unicode

# concept -> (what it is, candidate letters as (LaTeX, Unicode), first free one used)
DERIVED: dict[str, tuple[str, tuple[tuple[str, str], ...]]] = {
    "mass_matrix": ("mass matrix (the Hessian of L in the velocities)", (("M", "M"), (r"\mathcal{M}", "𝓜"))),
    "stiffness": (
        "stiffness matrix (the Hessian of the potential at an equilibrium)",
        (("K", "K"), (r"\mathcal{K}", "𝒦")),
    ),
    "frequency": ("angular frequency of small oscillations", ((r"\omega", "ω"), (r"\Omega", "Ω"), (r"\varpi", "ϖ"))),
    # the small displacement of the normal modes: η (Goldstein's), never ε, the action panel's variation size
    "displacement": (
        "small displacement of the coordinates from an equilibrium",
        ((r"\eta", "η"), (r"\xi", "ξ"), (r"\zeta", "ζ")),
    ),
    "amplitude": ("amplitudes of a normal mode (its shape)", (("a", "a"), (r"\mathbf{A}", "𝐀"))),
}

# quantities every document writes with one fixed letter
FIXED: tuple[tuple[str, str, str], ...] = (
    ("T", "T", "kinetic energy"),
    ("U", "U", "potential energy"),
    ("L", "L", "Lagrangian, L = T − U"),
    ("h", "h", "energy function, h = Σ q̇ ∂L/∂q̇ − L"),
    ("H", "H", "Hamiltonian, h written in the coordinates and momenta"),
    ("E", "E", "total energy, T + U"),
    ("t", "t", "time"),
)


def _taken(d: Derivation) -> set[str]:
    """The Unicode letters the declaration already uses (a coordinate's or a parameter's name)."""
    return {unicode(n) for n in (*d.table.names, *(p.name for p in d.system.parameters))}


def _choice(concept: str, d: Derivation) -> tuple[str, str]:
    taken = _taken(d)
    candidates = DERIVED[concept][1]
    return next((c for c in candidates if c[1] not in taken), candidates[-1])


def letter(concept: str, d: Derivation) -> str:
    """The LaTeX letter of a derived quantity in this document."""
    return _choice(concept, d)[0]


def text(concept: str, d: Derivation) -> str:
    """The Unicode letter of a derived quantity in this document (for sentences)."""
    return _choice(concept, d)[1]


def table(d: Derivation) -> list[dict[str, Any]]:
    """Every letter of the document once, with what it stands for: coordinates, parameters (with their
    units), then the derived quantities, in that order."""
    rows: list[dict[str, Any]] = []
    for name in d.table.names:
        rows.append({"latex": latex(name), "unicode": unicode(name), "meaning": "generalized coordinate", "unit": "", "kind": "coordinate"})
    for p in d.system.parameters:
        rows.append(
            {
                "latex": latex(p.name),
                "unicode": unicode(p.name),
                "meaning": p.description or "parameter",
                "unit": p.unit,
                "kind": "parameter",
            }
        )
    taken = _taken(d)
    for tex, uni, meaning in FIXED:
        if uni not in taken:
            rows.append({"latex": tex, "unicode": uni, "meaning": meaning, "unit": "", "kind": "derived"})
    for concept, (meaning, _) in DERIVED.items():
        tex, uni = _choice(concept, d)
        rows.append({"latex": tex, "unicode": uni, "meaning": meaning, "unit": "", "kind": "derived"})
    return rows
