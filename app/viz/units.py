"""Units of the coordinates, their rates and their momenta, for the labels a page prints.

An angle (the derivation document's ``angles``) is in rad, its rate in rad/s and its momentum
in kg·m²/s.  Another coordinate's unit follows from dimensions: T = ½ M_qq q̇² + … is an
energy, kg·m²/s², so [q]² = kg·m² / [M_qq], with [M_qq] worked out from the units the
parameters declare (a diagonal entry of the mass matrix, as an expression tree).  That gives
m for a coordinate whose M_qq is a mass, and nothing is printed when a unit cannot be worked
out (no unit declared, a unit not understood, or a result that is not a length): a missing unit
is honest, a wrong one is not.  A chapter scene's other coordinates are lengths (its
parameters carry units).

    coordinate_units(doc, scene) -> {"units": {q: u}, "rate_units": {q: u}, "momentum_units": {q: u}}
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from fractions import Fraction
from typing import Any

from app.engine.derivation.dimensions import Dims, parse_unit
from app.engine.derivation.dimensions import add_dims as _add
from app.engine.document.model import Document
from app.viz.exprtree import document_tree

__all__ = ["Dims", "coordinate_units", "dims_of", "parse_unit"]


def dims_of(tree: Any, known: Mapping[str, Dims | None]) -> Dims | None:
    """The dimensions of an expression tree given its names' (None when any needed one is unknown)."""
    if isinstance(tree, (int, float)):
        return {}
    if isinstance(tree, str):
        return known.get(tree)
    op, *args = tree
    if op == "*":
        out: Dims = {}
        for a in args:
            d = dims_of(a, known)
            if d is None:
                return None
            out = _add(out, d)
        return out
    if op == "/":
        top, bottom = dims_of(args[0], known), dims_of(args[1], known)
        return None if top is None or bottom is None else _add(top, bottom, Fraction(-1))
    if op == "neg":
        return dims_of(args[0], known)
    if op == "+":
        found = [dims_of(a, known) for a in args]
        # a sum of terms of one dimension has it; terms that disagree (or are unknown) say nothing
        return found[0] if found and all(d is not None and d == found[0] for d in found) else None
    if op == "pow":
        base = dims_of(args[0], known)
        if base is None or not isinstance(args[1], (int, float)):
            return None
        return {k: v * Fraction(args[1]).limit_denominator(1000) for k, v in base.items()}
    # functions (sin, exp, ...) of a dimensionless argument are dimensionless; Abs keeps its argument's
    return dims_of(args[0], known) if op == "Abs" else {}


# names a student gives an angle (theta, phi1, ...): such a coordinate is in rad whatever its equations say
ANGLE_NAMES = re.compile(r"(theta|phi|psi|alpha|beta|gamma|chi|varphi|vartheta)_?\d*")


def coordinate_units(doc: Document, scene: bool) -> dict[str, dict[str, str]]:
    coordinates = list(doc.coordinates)
    angles = set(doc.angles) | {q for q in coordinates if ANGLE_NAMES.fullmatch(q)}
    known: dict[str, Dims | None] = {n: parse_unit(p.unit) for n, p in doc.parameters.items()}
    known.update({a: {} for a in angles})  # an angle is dimensionless
    energy = {"kg": Fraction(1), "m": Fraction(2)}  # kg·m² (T times s²)
    units: dict[str, str] = {q: "rad" if q in angles else ("m" if scene else "") for q in coordinates}
    matrix = doc.mass_matrix
    # each pass may resolve a coordinate another one's M_qq needs (r before theta in m r² theta_dot²)
    for _ in range(len(coordinates)):
        for i, q in enumerate(coordinates):
            if units[q] or i >= len(matrix) or i >= len(matrix[i]):
                continue
            entry = document_tree(matrix[i][i])
            d = dims_of(entry, known) if entry is not None else None
            if d is None and entry is not None:
                # an M_qq that depends on the velocities (−mc²√(1 − ẋ²/c²)): try q in m, q̇ in m/s and the other
                # rates in their units, and keep m only when M_qq then has the units m would need (kg)
                trial = dict(known) | {f"{p}_dot": _rate_dims(known.get(p)) for p in coordinates}
                trial[q], trial[f"{q}_dot"] = {"m": Fraction(1)}, {"m": Fraction(1), "s": Fraction(-1)}
                d = dims_of(entry, trial)
            if d is not None and _add(energy, d, Fraction(-1)) == {"m": Fraction(2)}:
                units[q] = "m"
                known[q] = {"m": Fraction(1)}
    rate = {q: rate_unit(u) for q, u in units.items()}
    momentum = {q: {"rad": "kg·m²/s", "m": "kg·m/s"}.get(u, "") for q, u in units.items()}
    return {"units": units, "rate_units": rate, "momentum_units": momentum}


def _rate_dims(d: Dims | None) -> Dims | None:
    """A coordinate's rate: its dimension per second (None when the coordinate's own is not known)."""
    return None if d is None else _add(d, {"s": Fraction(-1)})


def rate_unit(unit: str) -> str:
    """The unit of a coordinate's rate: m/s, rad/s; 1/s where the coordinate's own unit is not known."""
    return f"{unit}/s" if unit else "1/s"


def with_unit(value: str, unit: str) -> str:
    """A number with its unit as prose prints it: "1 m/s", "1 rad/s"; a rate of a coordinate without a known unit
    ("1/s") reads "1 s⁻¹", never "1 1/s" or "1 per second"."""
    if not unit:
        return value
    return f"{value} s⁻¹" if unit == "1/s" else f"{value} {unit}"
