"""Forms by meaning, as the documents serve them (issue 40): an energy as its bodies' and springs' pieces, U_eff as
its centrifugal and potential pieces, a momentum grouped by velocity; each still equal to the engine's expression."""

from __future__ import annotations

import sympy as sp

from app.service.chapter.derivations import derivation_document
from tests.reference import numerically_equal


def names_of(doc, extra=()):
    names = {"t": sp.Symbol("t", real=True)}
    for q in [*doc["coordinates"], *extra]:
        for s in ("", "_dot"):
            names[q + s] = sp.Symbol(q + s, real=True)
        names[f"p_{q}"] = sp.Symbol(f"p_{q}", real=True)
    names |= {p: sp.Symbol(p, real=True) for p in doc["parameters"]}
    return names


def same(a, b, names):
    return numerically_equal(sp.sympify(a, locals=names), sp.sympify(b, locals=names), sorted(set(names.values()), key=str))


SPRING = r"\frac{1}{2} k \left(x_{2} - x_{1} - l_{0}\right)^{2}"


def test_the_rails_conserved_energy_is_its_bodies_and_springs_pieces():
    doc = derivation_document("rail-two-body")
    names = names_of(doc, ("X", "x"))
    (energy,) = [c for c in doc["conserved"] if c["name"] == "E"]
    assert energy["latex"] == doc["energy"]["latex"]
    assert energy["latex"].endswith(SPRING) and "k x_{1} x_{2}" not in energy["latex"]
    assert same(energy["sympy"], doc["energy"]["sympy"], names)
    # the centre-of-mass block: E in the original coordinates, and U_eff of the relative coordinate
    block = doc["transformed"]
    (moved,) = [c for c in block["conserved"] if c["name"] == "E"]
    assert moved["original"]["latex"] == (
        r"\frac{1}{2} m_{1} \dot{x}_{1}^{2} + \frac{1}{2} m_{2} \dot{x}_{2}^{2} + " + SPRING
    )
    assert same(moved["original"]["sympy"], doc["energy"]["sympy"], names)
    potential = block["effective_potential"]["potential"]
    assert potential["latex"] == (
        r"\frac{p_{X}^{2}}{2 \left(m_{1} + m_{2}\right)} + \frac{1}{2} k \left(x - l_{0}\right)^{2}"
    )
    (p_X,) = [c for c in block["conserved"] if c["name"] == "p_X"]
    assert p_X["latex"] == r"\left(m_{1} + m_{2}\right) \dot{X}"
    assert p_X["original"]["latex"] == r"m_{1} \dot{x}_{1} + m_{2} \dot{x}_{2}"
    assert block["momenta"]["X"]["latex"] == r"\left(m_{1} + m_{2}\right) \dot{X}"


def test_the_tabletop_effective_potential_is_centrifugal_plus_spring():
    doc = derivation_document("tabletop-spring")
    served = doc["effective_potential"]["potential"]
    assert served["latex"] == r"\frac{p_{\theta}^{2}}{2 m r^{2}} + \frac{1}{2} k r^{2}"
    (s,) = [s for s in doc["steps"] if s["key"] == "effective-potential"]
    assert r"U_\text{eff}(r) &= \frac{p_{\theta}^{2}}{2 m r^{2}} + \frac{1}{2} k r^{2}" in s["latex"]
    names = names_of(doc)
    m, k, r, p = (names[n] for n in ("m", "k", "r", "p_theta"))
    assert same(served["sympy"], str((m * k * r**4 + p**2) / (2 * m * r**2)), names)


def test_the_wedges_momentum_is_grouped_by_velocity():
    doc = derivation_document("movable-incline")
    grouped = r"\left(M + m\right) \dot{X} + m \dot{D} \cos {\alpha}"
    assert doc["momenta"]["X"]["latex"] == grouped
    (p_X,) = [c for c in doc["conserved"] if c["name"] == "p_X"]
    assert p_X["latex"] == grouped
    steps = {s["key"]: s["latex"] for s in doc["steps"]}
    assert grouped in steps["momenta"] and grouped in steps["cyclic"]
    names = names_of(doc)
    M, m, a, Xd, Dd = (names[n] for n in ("M", "m", "alpha", "X_dot", "D_dot"))
    assert same(p_X["sympy"], str(M * Xd + m * Xd + m * Dd * sp.cos(a)), names)
    assert doc["effective_potential"]["potential"]["latex"].startswith(r"\frac{p_{X}^{2}}{2 \left(M + m\right)}")


def test_matrices_are_printed_in_textbook_order():
    doc = derivation_document("double-pendulum")
    (modes,) = [s for s in doc["steps"] if s["key"] == "normal-modes:1"]
    assert r"\left[\begin{matrix}\left(m_{1} + m_{2}\right) l_{1}^{2} & m_{2} l_{1} l_{2}" in modes["latex"]
    assert "l_{1}^{2} \\left(m_{1}" not in modes["latex"] and "l_{1} l_{2} m_{2}" not in modes["latex"]
    # one coordinate: ω² itself, no 1×1 matrices
    (one,) = [s for s in derivation_document("simple-pendulum")["steps"] if s["key"] == "normal-modes:1"]
    # and the equilibrium in the same row (prof-g 5: "about θ = 0: ω² = g/R", no lone "θ = 0" above it)
    assert r"\text{about } \theta=0:\quad \omega^2 = \frac{g}{R}" in one["latex"] and "matrix" not in one["latex"]
