"""The letters of a document: one table, so that one letter means one quantity on a page.

A document's coordinates and parameters keep the names they were declared with.  The quantities the
engine derives (the mass matrix, the stiffness matrix, a frequency of small oscillations) each have
a list of letters a textbook uses for them; a document takes the first that no coordinate or
parameter already has (the mass matrix is ℳ on every page, app/engine/names.MASS_MATRIX), so the rotating parabola, turning at the rate ω, writes its small-oscillation frequency Ω.

Every step that prints one of these letters asks ``letter`` (LaTeX) or ``text`` (Unicode) for it,
and ``table`` is the "Symbols" table the page shows and the API serves: each letter once, with what
it means.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from fractions import Fraction
from typing import Any, NamedTuple

import sympy as sp

from app.engine.derivation.derive import Derivation, Transformed
from app.engine.derivation.dimensions import Dims, add_dims, dimension, kind_of_unit, system_dimensions, unit_text
from app.engine.display.names import MASS_MATRIX, SUBSCRIPT, latex, prose, unicode
from app.engine.display.textbook import unicode_text
from app.engine.equations.constraints import ConstraintForce, cartesian_symbols

# concept -> (what it is, candidate letters as (LaTeX, Unicode), first free one used)
DERIVED: dict[str, tuple[str, tuple[tuple[str, str], ...]]] = {
    # one letter on every page, whatever the parameters are called (app/engine/display/names.py)
    "mass_matrix": ("mass matrix (the Hessian of L in the velocities)", (MASS_MATRIX,)),
    "stiffness": (
        "stiffness matrix (the Hessian of the potential at an equilibrium)",
        (("K", "K"), (r"\mathcal{K}", "𝒦")),
    ),
    "frequency": ("angular frequency of small oscillations", ((r"\omega", "ω"), (r"\Omega", "Ω"), (r"\varpi", "ϖ"))),
    # the small displacement of the normal modes: η (Goldstein's), never ε, the action panel's variation size
    "displacement": (
        "small displacement of the coordinates from an equilibrium",
        ((r"\eta", "η"), (r"\xi", "ξ"), (r"\zeta", "ζ"), (r"\chi", "χ")),
    ),
    "amplitude": ("amplitudes of a normal mode (its shape)", (("a", "a"), (r"\mathbf{A}", "𝐀"))),
    "start": ("displacement the beats start from, the other coordinate at rest", (("A", "A"), ("B", "B"))),
}

# a constraint's surface 𝒞 = 0 (a calligraphic C, which no parameter can be), in its steps and the Symbols table
CONSTRAINT = r"\mathcal{C}"


# The letters of the a-th constraint (a = 1, 2, … in the order the Results list the forces): its surface 𝒞ₐ = 0,
# its multiplier λₐ and the size Fₐ = λₐ |∂𝒞ₐ/∂r| of its force. Every step, the Symbols table and the page's
# Results read them here, so that F₂ in a formula is the F₂ the table explains.
def surface(a: int) -> tuple[str, str]:
    """The a-th constraint's letter (LaTeX, Unicode): 𝒞ₐ."""
    return f"{CONSTRAINT}_{{{a}}}", f"𝒞{str(a).translate(SUBSCRIPT)}"


def multiplier(a: int) -> tuple[str, str]:
    """The a-th constraint's Lagrange multiplier (LaTeX, Unicode): λₐ."""
    return rf"\lambda_{{{a}}}", f"λ{str(a).translate(SUBSCRIPT)}"


def force(a: int) -> tuple[str, str]:
    """The size of the a-th force of constraint (LaTeX, Unicode): Fₐ."""
    return f"F_{{{a}}}", f"F{str(a).translate(SUBSCRIPT)}"


# The Euler–Lagrange equations written as ℳ q̈ = f, in a textbook's words (Taylor, Morin), never a numerical
# solver's "forcing": the step's title, and what f is. Every page, note and table row reads them here; the
# document's members keep their names (mass_matrix, forcing).
MATRIX_FORM = "The equations in matrix form"
RIGHT_SIDE = "the terms without accelerations, moved to the right side"

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
    # the small displacement's η must not be a Cartesian η the constraint steps print (the helix's, the pulley's)
    extra = _cartesian_letters(d) if concept == "displacement" else set()
    return free_letter(concept, _taken(d) | extra)


def free_letter(concept: str, names: Iterable[str]) -> tuple[str, str]:
    """The (LaTeX, Unicode) letter of a derived quantity where the declaration has these names: the first of its
    candidates that no name already is (Ω for the frequency where ω is a parameter)."""
    taken = {unicode(n) for n in names}
    candidates = DERIVED[concept][1]
    return next((c for c in candidates if c[1] not in taken), candidates[-1])


def letter(concept: str, d: Derivation) -> str:
    """The LaTeX letter of a derived quantity in this document."""
    return _choice(concept, d)[0]


def text(concept: str, d: Derivation) -> str:
    """The Unicode letter of a derived quantity in this document (for sentences)."""
    return _choice(concept, d)[1]


class Inertia(NamedTuple):
    """The letter (LaTeX, Unicode) of the inertia of a single coordinate, and its name in words."""

    latex: str
    unicode: str
    words: str


# The inertia a reduction leaves with its one coordinate, in the reduced energy ½ m_eff q̇² + U_eff: a mass for a
# length; for an angle a moment of inertia (kg·m²), which Taylor and Morin write I (½ I θ̇²), never m.
MASS_INERTIA = Inertia(r"m_\text{eff}", "m_eff", "effective mass")
ANGLE_INERTIA = Inertia(r"I_\text{eff}", "I_eff", "effective moment of inertia")


def angle_coordinates(d: Derivation) -> list[str]:
    """Coordinates that are angles: each is, alone, the argument of sin, cos or tan in the positions or in L."""
    exprs = [c for r in d.mechanics.positions for c in r] + [d.mechanics.L]
    arguments = {f.args[0] for e in exprs for f in sp.sympify(e).atoms(sp.sin, sp.cos, sp.tan)}
    return [name for name, q in zip(d.table.names, d.table.q, strict=True) if q in arguments or -q in arguments]


def inertia(d: Derivation | None, name: str | None = None) -> Inertia:
    """The inertia's letter and words for the coordinate ``name`` (the reduction's where not given): I_eff for an
    angle, m_eff for a length or where no document says which (a sentence about every system)."""
    if d is None:
        return MASS_INERTIA
    if name is None:
        if d.reduction is None:
            return MASS_INERTIA
        name = d.reduction.coordinate
    return ANGLE_INERTIA if name in angle_coordinates(d) else MASS_INERTIA


# The position vector of a point: r⃗, as Taylor and Morin write it. Where a parameter is called r (the rolling
# cylinder's radius), R⃗, the letter Goldstein gives the centre of mass's position, so that r is never a fixed
# length and a vector on one page; ρ⃗ where R is a parameter too. A coordinate r keeps r⃗: it is the vector's own
# length (the puck's r⃗ = (r cos θ, r sin θ, 0)).
POSITION: tuple[tuple[str, str], ...] = ((r"\vec r", "r⃗"), (r"\vec R", "R⃗"), (r"\vec \rho", "ρ⃗"))


def position(d: Derivation) -> tuple[str, str]:
    """The letter (LaTeX, Unicode) of the position vectors on this page: r⃗, unless a parameter is r."""
    taken = {unicode(p.name) for p in d.system.parameters}
    # a vector's letter is taken where its bare letter names a parameter
    return next((c for c in POSITION if c[1].removesuffix("\u20d7") not in taken), POSITION[-1])


# the exponents of a small motion η ∝ e^{λt}, the roots of its auxiliary equation: never r, which names the
# positions r⃗ on every page, nor s, the unit beside them (s⁻¹); λ as in an eigenvalue problem, σ where λ is taken
# (a constraint's multipliers λ₁, λ₂, …, or a parameter called λ)
EXPONENT: tuple[tuple[str, str], ...] = ((r"\lambda", "λ"), (r"\sigma", "σ"), (r"\varsigma", "ς"))


def exponent(d: Derivation) -> tuple[str, str]:
    """The letter (LaTeX, Unicode) of the exponents of e^{λt} about an equilibrium where velocity terms act."""
    taken = _taken(d) | ({"λ"} if d.system.constraints else set())
    return next((c for c in EXPONENT if c[1] not in taken), EXPONENT[-1])


# the radicand named where a frequency's square root is too long to print inside it (ω² = g/(2m₁l₁l₂) [… ∓ √Δ]):
# Δ, as a textbook names a discriminant; D where a coordinate or parameter is already called Δ
RADICAND: tuple[tuple[str, str], ...] = ((r"\Delta", "Δ"), ("D", "D"))


def radicand(d: Derivation) -> tuple[str, str]:
    """The letter (LaTeX, Unicode) of the long radicand named in the frequencies of the normal modes."""
    taken = _taken(d)
    return next((c for c in RADICAND if c[1] not in taken), RADICAND[-1])


def rest_potential(d: Derivation) -> tuple[str, str]:
    """The name (LaTeX, Unicode) of −L at q̇ = 0, U − T₀, whose stationary points are the equilibria: U_eff, the
    effective potential, as on every page that reduces to it; V only where the effective-potential step writes
    another function (its conserved momenta held), so that U_eff never names two functions on one page."""
    at_rest = d.mechanics.L.xreplace(dict.fromkeys(d.table.qd, 0))
    if d.reduction is None or sp.expand(d.reduction.effective_potential + at_rest) == 0:
        return r"U_\text{eff}", "U_eff"
    return "V", "V"


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


_FORCE: Dims = {"kg": Fraction(1), "m": Fraction(1), "s": Fraction(-2)}


def _force_unit(dims: Dims | None) -> str:
    """A multiplier's unit: N, or N over a power of m (N/m for a string's R² − r²), else as ``_unit`` prints it."""
    if dims is not None and dims.get("kg") == 1 and dims.get("s") == -2 and set(dims) <= {"kg", "m", "s"}:
        metres = dims.get("m", Fraction(0)) - 1
        if metres == 0:
            return "N"
        if metres < 0 and metres.denominator == 1:
            return "N/m" if metres == -1 else f"N/m{str(-metres.numerator).translate(_SUPERSCRIPTS)}"
    return _unit(dims)


_SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


class _PerCoordinate:
    """The unit of an entry that carries its coordinates' units: [entry] = base / ([q_j] [q_k] …), one unit
    when every coordinate has the same, else the rule ``per entry: …``."""

    def __init__(self, d: Derivation, dims: dict[sp.Symbol, Dims]) -> None:
        self.coordinates = [dims.get(q) for q in d.table.q]

    def unit(self, base: Dims, power: int, rule: str) -> str:
        if any(c is None for c in self.coordinates):
            return ""
        first = self.coordinates[0]
        if any(c != first for c in self.coordinates):
            return f"per entry: {rule}"
        shown = add_dims(base, first or {}, Fraction(-power))
        # a torque (J per radian) reads N·m, a force N, a stiffness per metre N/m
        if shown == _ENERGY and power:
            return "N·m"
        return _force_unit(shown) if shown.get("s") == -2 and shown.get("kg") == 1 else _unit(shown, angle=not shown)


def _derived_unit(concept: str, per: _PerCoordinate | None) -> str:
    """The unit of a normal-mode letter: ℳ per entry J·s²/([q_j][q_k]), K J/([q_j][q_k]), η, a and A the coordinate's."""
    if per is None:
        return ""
    if concept == "mass_matrix":
        return per.unit({"kg": Fraction(1), "m": Fraction(2)}, 2, "kg·m² divided by the units of its row's and column's coordinates")
    if concept == "stiffness":
        return per.unit(_ENERGY, 2, "J divided by the units of its row's and column's coordinates")
    return per.unit({}, -1, "that of its coordinate")


def _is_energy(d: Derivation, dims: dict[sp.Symbol, Dims]) -> bool:
    """Whether the energies are in J: every term of a sum has one dimension, so L is an energy as soon as one of
    its terms is (½mẋ² in kg·m²/s²) and none is known to be anything else; with no term told, no unit is claimed."""
    told = [dimension(term, dims) for term in sp.Add.make_args(sp.expand(d.mechanics.L))]
    known = [x for x in told if x is not None]
    return bool(known) and all(x == _ENERGY for x in known)


def _alone_in_trig(d: Derivation, name: str) -> bool:
    """A parameter that is, alone, the argument of a sine, cosine or tangent of L or of a position: an angle."""
    exprs = [d.mechanics.L, *(c for r in d.mechanics.positions for c in r)]
    return any(str(f.args[0]) == name for e in exprs for f in sp.sympify(e).atoms(sp.sin, sp.cos, sp.tan, sp.cot))


def _kind(words: str | None) -> str | None:
    """ "a mass" as a Symbols table's meaning: "mass"."""
    return words.split(" ", 1)[1] if words else None


def _row(tex: str, uni: str, meaning: str, unit: str, kind: str) -> dict[str, Any]:
    return {"latex": tex, "unicode": uni, "meaning": meaning, "unit": unit, "kind": kind}


def table(
    d: Derivation,
    forces: tuple[ConstraintForce, ...] = (),
    transformed: Transformed | None = None,
    meanings: Mapping[str, str] | None = None,
) -> list[dict[str, Any]]:
    """Every letter of the document once, with what it stands for and its unit: coordinates, parameters,
    the coordinates' momenta, the derived quantities, then the letters of the steps a document has only
    sometimes (a reduction's U_eff and m_eff, V, Q, the constraints' 𝒞, λ, F and Cartesian coordinates,
    the new coordinates of a change and the reduced mass)."""
    rows: list[dict[str, Any]] = []
    dims = system_dimensions(d)
    energy = "J" if _is_energy(d, dims) else ""
    for q in d.table.q:
        # an angle is a coordinate inside a sine or cosine: dimensionless, printed in rad
        unit = _unit(dims.get(q), angle=True)
        # what the coordinate is in its set-up's words (a scene's), else only what it is to the method
        said = prose((meanings or {}).get(q.name, "")) or "generalized coordinate"
        rows.append(_row(latex(q.name), unicode(q.name), said, unit, "coordinate"))
    for p in d.system.parameters:
        rows.append(
            {
                "latex": latex(p.name),
                "unicode": unicode(p.name),
                # what the user declared it to be, else what its unit says (a mass, an angle, a magnetic field)
                "meaning": p.description
                or _kind(kind_of_unit(p.unit))
                or ("angle" if _alone_in_trig(d, p.name) else "parameter"),
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
    per = _PerCoordinate(d, dims) if energy else None
    rows.append(
        _row("f", "f", f"{RIGHT_SIDE} of the equations of motion, {text('mass_matrix', d)} q̈ = f",
             per.unit(_ENERGY, 1, "J divided by its coordinate's unit") if per else "", "derived")  # fmt: skip
    )
    for concept, (meaning, _) in DERIVED.items():
        tex, uni = _choice(concept, d)
        rows.append(_row(tex, uni, meaning, "rad/s" if concept == "frequency" else _derived_unit(concept, per), "derived"))
    rows += _sometimes(d, dims, energy, forces, transformed)
    # each letter once: the first meaning a page gives it stands
    first: dict[str, dict[str, Any]] = {}
    for r in rows:
        first.setdefault(r["unicode"], r)
    return list(first.values())


def _sometimes(
    d: Derivation, dims: dict[sp.Symbol, Dims], energy: str, forces: tuple[ConstraintForce, ...], tr: Transformed | None
) -> list[dict[str, Any]]:
    """The letters only some documents print, each where its step is."""
    rows: list[dict[str, Any]] = []
    m = d.mechanics
    if d.reduction is not None:
        q = next(s for s in d.table.q if s.name == d.reduction.coordinate)
        rows.append(
            _row(
                r"U_\text{eff}",
                "U_eff",
                f"effective potential in which {unicode(q.name)} moves as a single coordinate"
                + (" (conserved momenta held fixed)" if d.reduction.momenta else ""),
                energy,
                "derived",
            )
        )
        # ½ m_eff q̇² is an energy: [m_eff] = J s² / [q]² (kg·m² for an angle, its I_eff)
        m_dims = (
            add_dims({"kg": Fraction(1), "m": Fraction(2)}, dims[q], Fraction(-2)) if q in dims and energy else None
        )
        held = inertia(d, q.name)
        # an angle turns with a moment of inertia, a length moves with a mass
        what, does = ("moment of inertia", "turns") if held is ANGLE_INERTIA else ("mass", "moves")
        rows.append(
            _row(
                held.latex,
                held.unicode,
                # with conserved momenta held, m_eff is not ∂²L/∂q̇² (the wedge's m): it is the inertia left in the
                # reduced energy ½ m_eff q̇² + U_eff once the cyclic velocities are eliminated
                f"{held.words} of {unicode(q.name)}: the {what} {unicode(q.name)} {does} with"
                + (" once the conserved momenta are held fixed" if d.reduction.momenta else "")
                + " (the inertia in its reduced energy)",
                _unit(m_dims),
                "derived",
            )
        )
    at_rest = m.L.xreplace(dict.fromkeys(d.table.qd, 0))
    tex, uni = rest_potential(d)
    if m.U is not None and sp.expand(at_rest + m.U) != 0 and (uni != "U_eff" or d.reduction is None):
        # the effective potential U − T₀ (T₀ the part of T without velocities); with a reduction to it, its row above
        rows.append(
            _row(
                tex,
                uni,
                "effective potential, the potential energy less the part of the kinetic energy without velocities "
                "(U − T₀): the equilibria are where it is stationary",
                energy,
                "derived",
            )
        )
    rows += _symmetries(d, dims, energy)
    if any(f != 0 for f in m.Q):
        per = _PerCoordinate(d, dims) if energy else None
        rows.append(_row("Q", "Q", "generalized force that no potential describes",
                         per.unit(_ENERGY, 1, "J divided by its coordinate's unit") if per else "", "derived"))  # fmt: skip
        # with a drag on one coordinate, the small motions about an equilibrium go as e^{σt} (app/engine/report_modes)
        if len(d.table.q) == 1:
            tex, uni = exponent(d)
            rows.append(_row(tex, uni, f"rate in one of the exponentials that make up a small motion {text('displacement', d)} "
                             "about an equilibrium, a root of its auxiliary equation", "1/s" if energy else "", "derived"))  # fmt: skip
    if len(d.table.q) > 1:
        # printed only where an ω² is too long to hold its root whole (the double pendulum's); the page lists a
        # row only where its letter is printed (``printed``)
        tex, uni = radicand(d)
        rows.append(_row(tex, uni, f"quantity under the square root in {text('frequency', d)}², named where "
                         f"{text('frequency', d)}² is too long to print it whole",
                         "that of the square of the other term in its bracket" if energy else "", "derived"))  # fmt: skip
    if forces:
        rows.append(
            _row(CONSTRAINT, "𝒞", "a constraint written as a surface 𝒞 = 0 in Cartesian coordinates", "per constraint (𝒞₁, … below)" if energy else "", "derived")
        )
        rows.append(
            _row(
                r"\lambda", "λ", "Lagrange multiplier of a constraint: its force on body i is λ ∂𝒞/∂r_i",
                "J divided by the unit of its 𝒞 (λ𝒞 is an energy)" if energy else "", "derived",
            )
        )
        rows.append(_row("L'", "L′", "the Lagrangian in Cartesian coordinates with the constraints' multipliers", energy, "derived"))
        # each constraint's 𝒞ₐ and λₐ with its unit in this scene: [λ] = [F]/[∂𝒞/∂r] (λ in N/m for a string's R² − r²)
        metres = {s: {"m": Fraction(1)} for f in forces for s in f.g.free_symbols if s not in dims}
        for a, f in enumerate(forces, start=1):
            (g_tex, g), (lam_tex, lam) = surface(a), multiplier(a)
            g_unit = _unit(dimension(f.g, {**dims, **metres})) if energy else ""
            lam_unit = _force_unit(dimension(f.multiplier, dims)) if energy else ""
            rows.append(_row(g_tex, g, f"the constraint of the {f.constraint.name}, {g} = 0", g_unit, "derived"))
            rows.append(_row(lam_tex, lam, f"the multiplier of {g}: its force on the body is {lam} ∂{g}/∂r", lam_unit, "derived"))
        # each force of constraint its own letter, F₁, F₂, … in the order the Results list them (the page
        # prints F₁ = … there and in the constraint panel)
        for a, f in enumerate(forces, start=1):
            rows.append(_row(*force(a), f.constraint.name, "N" if energy else "", "derived"))
        rows += _cartesian(d, forces)
    if tr is not None:
        for Q, definition in zip(tr.derivation.table.q, tr.definitions, strict=True):
            unit = _unit(dimension(definition, dims))
            rows.append(
                _row(
                    latex(Q.name),
                    unicode(Q.name),
                    f"new coordinate, {unicode(Q.name)} = {unicode_text(definition)}",
                    unit,
                    # derived from the document's own coordinates, which alone are of kind "coordinate"
                    "derived",
                )
            )
        if tr.reduced_mass is not None:
            rows.append(
                _row(
                    r"\mu",
                    "μ",
                    f"reduced mass, μ = {unicode_text(tr.reduced_mass)}",
                    _unit(dimension(tr.reduced_mass, dims)),
                    "derived",
                )
            )
    return rows


def _symmetries(d: Derivation, dims: dict[sp.Symbol, Dims], energy: str) -> list[dict[str, Any]]:
    """The letters of the quantities a rotation (J) or a translation (P) of the coordinates conserves."""
    rows = []
    for c in d.energetics.conserved:
        if c.name.startswith("J"):
            meaning = "generalized angular momentum, conserved because L is unchanged by a rotation"
            unit = _unit(_ACTION) if energy else ""
        elif c.name.startswith("P_"):
            q = next(s for s in d.table.q if s.name == c.name[2:])
            meaning = f"conserved momentum of a translation of {unicode(q.name)}: p_{unicode(q.name)} less the total derivative L changes by"
            unit = _unit(add_dims(_ACTION, dims[q], Fraction(-1))) if q in dims and energy else ""
        else:
            continue
        rows.append(_row(c.latex_name, unicode(c.name), meaning, unit, "derived"))
    return rows


_GREEK_AXES = {"x": "xi", "y": "eta", "z": "zeta"}


def cartesian_names(names: list[str], taken: set[str]) -> dict[str, str]:
    """The name each body's Cartesian component is printed by (x1 → x1, or → xi1): x, y, z, or ξ, η, ζ for all of
    them where the system already prints one of their names (the pulley's coordinates are its end masses' heights
    y₁, y₂), so that ẏ₁ never means two things. ``taken``: the LaTeX the document prints for its own
    names. One home: the constraint steps (report_members) and the Symbols table both read it."""
    greek = any(latex(n) in taken or n in taken for n in names)
    return {n: (_GREEK_AXES[n[0]] + n[1:] if greek else n) for n in names}


def practice_axes(d: Derivation) -> tuple[str, str, str]:
    """The letters (names) a positions step in practice calls the Cartesian axes by: x, y, z, or ξ, η, ζ where a
    coordinate takes one of those names without being each body's displacement along that axis (the massive
    pulley's z, m₂'s height, puts −z in m₁'s z: "ζ of the mass m₁ = −z", never "z of the mass m₁ = −z"; the helix's
    z turns the bead in x and y too). A cart's x that moves every body it carries along x keeps x."""
    points = [*d.mechanics.positions, *(b.centre for b in d.mechanics.bodies if b.translation != 0)]
    for q in d.table.q:
        if q.name not in ("x", "y", "z"):
            continue
        own = "xyz".index(q.name)
        # ∂r/∂q is the unit vector along q's own axis for every point q moves
        for r in points:
            if any(c.has(q) for c in r) and any(sp.diff(c, q) != (a == own) for a, c in enumerate(r)):
                return ("xi", "eta", "zeta")
    return ("x", "y", "z")


def _printed_cartesian(
    d: Derivation, forces: tuple[ConstraintForce, ...], velocities: bool = False
) -> tuple[list[str], dict[str, str]]:
    """The Cartesian components the constraint steps print (x, y1, … by name): those a constraint holds, one named
    like a coordinate (the helix's z) still the body's Cartesian z; with ``velocities``, every body's three, whose
    rates L′'s kinetic energy holds (the pulley's η̇₃). And the name each is printed by (ζ where z is taken)."""
    every = [s.name for triple in cartesian_symbols(len(d.system.particles)) for s in triple]
    held = {s.name for f in forces for s in f.g.free_symbols}
    names = sorted(n for n in every if velocities or n in held) if forces else []
    # decided over every body's three components, as the constraint steps decide it (y₁ taken makes z₁ ζ₁ too)
    printed = cartesian_names(every, {latex(s.name) for s in (*d.table.q, *d.table.params)})
    return names, printed


def _cartesian_letters(d: Derivation) -> set[str]:
    """The letters (Unicode) the constraint steps print for Cartesian coordinates: ξ, η, ζ on the helix."""
    forces = d.constraint_forces
    if not isinstance(forces, tuple) or not forces:  # none, or skipped (too costly)
        return set()
    names, printed = _printed_cartesian(d, forces, velocities=True)
    # η₃ takes η: the letter, whatever body's it is
    return {unicode(re.sub(r"\d+$", "", printed.get(n, n))) for n in names}


def _cartesian(d: Derivation, forces: tuple[ConstraintForce, ...]) -> list[dict[str, Any]]:
    """The Cartesian coordinates the constraints are written in: x across, y, z up, of each body."""
    names, printed = _printed_cartesian(d, forces)
    rows = []
    for name in names:
        axis, number = name[0], name[1:]
        # x, y, z name a single body's; x1, z2 … body 1's, body 2's
        index = int(number) - 1 if number.isdigit() else 0
        body = d.system.particles[index] if index < len(d.system.particles) else None
        whose = f"the {body.label or 'body ' + (number or '1')}" if body is not None else "the body"
        shown = printed.get(name, name)
        rows.append(_row(latex(shown), unicode(shown), f"Cartesian {axis} of {whose}", "m", "derived"))
    return rows


# ---- which rows a page prints: a letter is listed only where the page prints it ----------------------------

# a LaTeX token: a styled letter (\mathcal{C}, \text{eff}) whole, a command, or one character; braces dropped
_TEX_TOKEN = re.compile(
    r"\\(?:text|mathrm|mathcal|mathbf|mathit|operatorname|begin|end)\s*\{[^{}]*\}|\\[A-Za-z]+|\\.|[^\s{}]"
)
# letters that are also English words: in prose they count only beside a sign of mathematics (x₁ = A cos …)
_WORDS = {"a", "A", "I"}
_MATH_SIGN = "=+−·×/²³"
# what may not touch a letter in prose for it to be that letter (θ̇ is not θ, x₁ is not x, p_θ is not θ)
_JOINED = re.compile(r"[\w\u0300-\u036fⁱ⁰-⁹'′]")


def _tex_tokens(tex: str) -> list[str]:
    return [re.sub(r"\s+", "", t) for t in _TEX_TOKEN.findall(tex)]


def _in_tex(symbol: list[str], tokens: list[str]) -> bool:
    """``symbol``'s tokens occur in ``tokens`` as a letter of its own: not a subscript of another letter (p_x),
    not the stem of a subscripted one (x_1 is not x)."""
    n = len(symbol)
    for i in range(len(tokens) - n + 1):
        if tokens[i : i + n] != symbol:
            continue
        before = tokens[i - 1] if i else ""
        after = tokens[i + n] if i + n < len(tokens) else ""
        # a numbered one counts (𝒞₁ is a 𝒞, F₂ an F); another subscript makes another letter
        numbered = after == "_" and i + n + 1 < len(tokens) and tokens[i + n + 1].isdigit()
        if before not in ("_", "^") and (after != "_" or numbered or "_" in symbol):
            return True
    return False


def _in_prose(symbol: str, text: str) -> bool:
    """``symbol`` (Unicode) occurs in running text as a letter of its own; an English word only as mathematics."""
    for m in re.finditer(re.escape(symbol), text):
        before, after = text[max(0, m.start() - 40) : m.start()], text[m.end() : m.end() + 40]
        # a numbered one counts (𝒞₁ is a 𝒞)
        if (before and _JOINED.match(before[-1])) or (after and _JOINED.match(after.lstrip("₀₁₂₃₄₅₆₇₈₉")[:1] or " ")):
            continue
        # a letter inside LaTeX's markup (\alpha, \mathcal{M}) is not that letter
        if before.endswith("\\") or re.search(r"\\[A-Za-z]+\{$", before):
            continue
        if symbol in _WORDS:
            near = before.rstrip()[-1:] + after.lstrip()[:1]
            if not any(c in _MATH_SIGN for c in near):
                continue
        return True
    return False


def printed(rows: list[dict[str, Any]], formulas: list[str], words: list[str]) -> list[dict[str, Any]]:
    """The rows of a Symbols table whose letter the page prints somewhere: in its ``formulas`` (LaTeX) or its
    ``words`` (running text, captions, figures' labels), in their order. A table never explains a letter the
    reader cannot find on the page."""
    tokens = [_tex_tokens(t) for t in formulas]
    return [
        r
        for r in rows
        if any(_in_tex(_tex_tokens(r["latex"]), ts) for ts in tokens) or any(_in_prose(r["unicode"], t) for t in words)
    ]
