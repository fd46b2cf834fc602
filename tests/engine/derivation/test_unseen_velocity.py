"""Lagrangians not quadratic in the velocities (issue 42): W(q, q̇, t) q̈ = f with W = ∂²L/∂q̇∂q̇ᵀ.

Relativistic systems, L = −mc²√(1 − v²/c²) − U, derived by the engine and checked against
``sympy.physics.mechanics.LagrangesMethod`` (which takes any L) at physical points (|v| < c); their
documents printed as a textbook prints them; a Lagrangian singular at rest refused with its reason.
"""

from __future__ import annotations

import random
import unicodedata
from functools import cache

import numpy as np
import pytest
import sympy as sp

from app.engine.derivation.derive import Derivation, derive
from app.engine.document.contract import derivation_json
from app.engine.errors import DerivationError
from app.numerics.simulate import simulate
from app.numerics.system import numeric_system
from app.scenes.types import Parameter, System
from tests.reference import lagranges_method, reference_accelerations

pytestmark = pytest.mark.slow  # each system derived whole and integrated

MASS, LIGHT = Parameter("m", 1.0, "kg", 1e-3, 1e3), Parameter("c", 3.0, "m/s", 0.01, 1e3)
GAMMA_2D = "1/sqrt(1 - (x_dot**2 + y_dot**2)/c**2)"
SYSTEMS = {
    "free-particle-2d": System(
        coordinates=("x", "y"), parameters=(MASS, LIGHT), lagrangian="-m*c**2*sqrt(1 - (x_dot**2 + y_dot**2)/c**2)"
    ),
    "oscillator": System(
        coordinates=("x",),
        parameters=(MASS, LIGHT, Parameter("k", 4.0, "N/m", 1e-3, 1e3)),
        lagrangian="-m*c**2*sqrt(1 - x_dot**2/c**2) - k*x**2/2",
    ),
    "uniform-force": System(
        coordinates=("x",),
        parameters=(MASS, LIGHT, Parameter("F", 2.0, "N", 0.0, 1e3)),
        lagrangian="-m*c**2*sqrt(1 - x_dot**2/c**2) + F*x",
    ),
    "kepler": System(
        coordinates=("r", "phi"),
        parameters=(MASS, LIGHT, Parameter("k", 1.0, "N*m^2", 1e-3, 1e3)),
        lagrangian="-m*c**2*sqrt(1 - (r_dot**2 + r**2*phi_dot**2)/c**2) + k/r",
        nonnegative=("r",),
    ),
}


@cache
def ours(name: str) -> Derivation:
    return derive(SYSTEMS[name])


def physical_points(d: Derivation, count: int = 4) -> list[dict[sp.Symbol, float]]:
    """Random states with every speed below c (the coordinates' rates 0.1–0.6, c = 3, r ≥ 0.5)."""
    rng = random.Random(42)
    table = d.table
    points = []
    for _ in range(count):
        point = {s: rng.uniform(0.5, 1.5) for s in table.q}
        point |= {s: rng.uniform(0.1, 0.6) for s in table.qd}
        point |= {p: next(x.default for x in d.system.parameters if x.name == p.name) for p in table.params}
        point[table.t] = 0.0
        points.append(point)
    return points


def value(expr: sp.Expr, point: dict[sp.Symbol, float]) -> float:
    return float(sp.N(sp.sympify(expr).xreplace(point), 30))


def plain(point: dict[sp.Symbol, float]) -> dict[sp.Symbol, float]:
    """The same point keyed by plain real symbols of the same names (the reference's own)."""
    return {sp.Symbol(s.name, real=True): v for s, v in point.items()}


@pytest.mark.parametrize("name", sorted(SYSTEMS))
def test_accelerations_and_w_agree_with_lagranges_method(name):
    d = ours(name)
    assert d.equations.velocity_dependent
    reference, back = reference_accelerations(d.system)
    lm, qs, _ = lagranges_method(d.system)
    W = lm.mass_matrix.subs(back)
    for point in physical_points(d):
        for ours_a, ref_a in zip(d.equations.accelerations, reference, strict=True):
            assert value(ours_a, point) == pytest.approx(value(ref_a, plain(point)), rel=1e-12, abs=1e-12)
        # W = ∂²L/∂q̇∂q̇ᵀ, LagrangesMethod's mass matrix
        for ours_w, ref_w in zip(d.equations.mass_matrix, W, strict=True):
            assert value(ours_w, point) == pytest.approx(value(ref_w, plain(point)), rel=1e-12, abs=1e-12)


def test_the_energy_function_is_gamma_m_c_squared_plus_u():
    d = ours("oscillator")
    m, c, k, x, v = (d.table.namespace()[n] for n in ("m", "c", "k", "x", "x_dot"))
    # h = Σ q̇ ∂L/∂q̇ − L = γmc² + ½kx², by hand
    by_hand = m * c**2 / sp.sqrt(1 - v**2 / c**2) + k * x**2 / 2
    assert sp.simplify(d.energetics.hamiltonian - by_hand) == 0
    assert any(c.name == "h" for c in d.energetics.conserved)


def test_printed_as_a_textbook_prints_it():
    doc = derivation_json(ours("oscillator"))
    steps = {s["key"]: s for s in doc["steps"]}
    # p = mẋ/√(1 − ẋ²/c²) (γmẋ) and h = mc²/√(1 − ẋ²/c²) + ½kx²: the root as a root, the dot as a dot
    assert steps["momenta"]["latex"] == r"p_{x} = \frac{m \dot{x}}{\sqrt{1 - \dot{x}^{2} / c^{2}}}"
    # ẍ = −(k/m) x (1 − ẋ²/c²)^{3/2}, that is −kx/(mγ³)
    assert steps["accelerations"]["latex"] == (
        r"\ddot{x} = - \frac{k}{m} x \left(1 - \dot{x}^{2} / c^{2}\right)^{\frac{3}{2}}"
    )
    assert steps["hamiltonian"]["latex"].endswith(
        r"= \frac{m c^{2}}{\sqrt{1 - \dot{x}^{2} / c^{2}}} + \frac{1}{2} k x^{2}"
    )
    for step in doc["steps"]:
        text = step.get("latex") or ""
        assert not any(word in text for word in ("x_dot", "sqrt(", "**", "Derivative")), step["key"]


def test_members_built_on_a_constant_mass_matrix_say_why_they_are_left_out():
    d = ours("kepler")
    doc = derivation_json(d)
    skipped = {s["member"]: s["reason"] for s in doc["skipped"]}
    assert "depends on the velocities" in skipped["hamilton"]
    assert "depends on the velocities" in skipped["effective_potential"]
    assert doc["effective_potential"] is None
    # φ is still cyclic and its momentum conserved, with h
    assert {"p_phi", "h"} <= {c.name for c in d.energetics.conserved}


def test_equilibrium_linearised_with_w_at_rest():
    modes = ours("oscillator").normal_modes()
    (eq,) = modes.equilibria
    # W(0, 0) = m, so ω² = k/m
    assert eq.position == {"x": 0.0} and eq.kind == "stable"
    assert eq.modes[0].omega_squared == pytest.approx(4.0)


def test_hyperbolic_motion_under_a_uniform_force():
    """From rest, x(t) = (mc²/F)(√(1 + (Ft/mc)²) − 1) exactly (Rindler); the app's run follows it and keeps h."""
    d = ours("uniform-force")
    system = numeric_system(d)
    m, c, F = 1.0, 3.0, 2.0
    out = simulate(system, np.array([m, c, F]), np.array([0.0, 0.0]), 10.0, 101, rtol=1e-11, atol=1e-12)
    t, y = out.trajectory.t, out.trajectory.y
    exact = m * c**2 / F * (np.sqrt(1 + (F * t / (m * c)) ** 2) - 1)
    assert np.max(np.abs(y[:, 0] - exact)) < 1e-7 * exact[-1]
    # the speed approaches c and never passes it
    assert 0.98 * c < y[-1, 1] < c
    # h = γmc² − Fx is conserved
    h = m * c**2 / np.sqrt(1 - (y[:, 1] / c) ** 2) - F * y[:, 0]
    assert np.max(np.abs(h - h[0])) < 1e-8 * m * c**2


@pytest.mark.parametrize(
    ("lagrangian", "shown"),
    [
        ("x_dot**4 - x**2", "ẋ = 0"),
        ("x_dot**3 + y_dot**2", "ẋ = ẏ = 0"),
    ],
)
def test_singular_at_rest_is_refused_with_its_reason(lagrangian, shown):
    coordinates = ("x",) if "y" not in lagrangian else ("x", "y")
    with pytest.raises(DerivationError) as refused:
        derive(System(coordinates=coordinates, lagrangian=lagrangian))
    # compared as composed characters (ẋ is one character or x and a combining dot)
    message = unicodedata.normalize("NFC", str(refused.value))
    assert "singular at rest" in message and shown in message and "invertible at q̇ = 0" in message
