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

from fractions import Fraction
from typing import Any

from app.engine.derive import Derivation
from app.engine.dimensions import Dims, add_dims, dimension, system_dimensions, unit_text
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


# the SI name of an energy's dimension (kg·m²/s²), and of a frequency's
_ENERGY: Dims = {"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-2)}
_ACTION: Dims = {"kg": Fraction(1), "m": Fraction(2), "s": Fraction(-1)}


def _unit(dims: Dims | None, angle: bool = False) -> str:
    """A unit as the Symbols table prints it: J for an energy, rad for an angle, "" when unknown."""
    if dims is None:
        return ""
    if dims == _ENERGY:
        return "J"
    if not dims:
        return "rad" if angle else ""
    return unit_text(dims)


def _row(tex: str, uni: str, meaning: str, unit: str, kind: str) -> dict[str, Any]:
    return {"latex": tex, "unicode": uni, "meaning": meaning, "unit": unit, "kind": kind}


def table(d: Derivation) -> list[dict[str, Any]]:
    """Every letter of the document once, with what it stands for and its unit: coordinates, parameters,
    the coordinates' momenta, then the derived quantities, in that order."""
    rows: list[dict[str, Any]] = []
    dims = system_dimensions(d)
    # the energies are in J when every term of L is (the declared units tell it); otherwise no unit is claimed
    energy = "J" if dimension(d.mechanics.L, dims) == _ENERGY else ""
    for q in d.table.q:
        # an angle is a coordinate inside a sine or cosine: dimensionless, printed in rad
        rows.append(_row(latex(q.name), unicode(q.name), "generalized coordinate", _unit(dims.get(q), angle=True), "coordinate"))
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
    for q in d.table.q:
        # p_q = ∂L/∂q̇ has the dimension of an action over q's: kg·m/s for a length, kg·m²/s for an angle
        p_dims = add_dims(_ACTION, dims[q], Fraction(-1)) if q in dims and energy else None
        rows.append(
            _row(
                latex(f"p_{q.name}"),
                unicode(f"p_{q.name}"),
                f"generalized momentum conjugate to {unicode(q.name)}, ∂L/∂{unicode(q.name + '_dot')}",
                _unit(p_dims),
                "derived",
            )
        )
    taken = _taken(d)
    for tex, uni, meaning in FIXED:
        if uni not in taken:
            rows.append(_row(tex, uni, meaning, "s" if uni == "t" else energy, "derived"))
    rows.append(_row("f", "f", f"right-hand side of the equations of motion, {text('mass_matrix', d)} q̈ = f", "", "derived"))
    for concept, (meaning, _) in DERIVED.items():
        tex, uni = _choice(concept, d)
        rows.append(_row(tex, uni, meaning, "rad/s" if concept == "frequency" else "", "derived"))
    return rows
