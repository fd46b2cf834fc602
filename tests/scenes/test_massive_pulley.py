"""The Atwood machine with a massive pulley (issue 42): two masses on a string over a uniform disc on a fixed
axle, derived as a rigid body and printed as a textbook prints it (Morin § 8.2, Taylor § 10.1):
T = ½(m₁ + m₂ + M/2) ż², z̈ = (m₁ − m₂) g/(m₁ + m₂ + M/2).

The derivation is checked against sympy.physics.mechanics built here from the physics, not from the scene's
declaration: a RigidBody with its own inertia dyadic about the axle, turned by z/R as the string does not slip.
"""

import pytest
import sympy as sp
import sympy.physics.mechanics as me

from app.scenes import SCENES
from app.service.chapter.derivations import derivation, derivation_document, scene_document
from app.viz.page_model import _answers
from tests.scenes.common import S

m1, m2, M, R, g = (S(n) for n in ("m1", "m2", "M", "R", "g"))
z, z_dot = S("z"), S("z_dot")


def _reference() -> tuple[sp.Expr, sp.Expr]:
    """T and z̈ from LagrangesMethod: the pulley a RigidBody turning about the fixed axle N.y, the masses Particles."""
    q = me.dynamicsymbols("q")
    t = me.dynamicsymbols._t
    N = me.ReferenceFrame("N")
    axle = me.Point("axle")
    axle.set_vel(N, 0)
    # the rim, and the string with it, moves by q when the disc turns by q/R: no slipping
    disc = N.orientnew("disc", "Axis", [q / R, N.y])
    # a uniform disc in the x–z plane: M R²/2 about its axis (y), M R²/4 about each diameter
    pulley = me.RigidBody("pulley", axle, disc, M, (me.inertia(disc, M * R**2 / 4, M * R**2 / 2, M * R**2 / 4), axle))
    left = axle.locatenew("left", -R * N.x - q * N.z)
    right = axle.locatenew("right", R * N.x + q * N.z)
    for point in (left, right):
        point.set_vel(N, point.pos_from(axle).dt(N))
    masses = me.Particle("m1", left, m1), me.Particle("m2", right, m2)
    # heights from the start: m₁ at −q, m₂ at +q; the axle's height is fixed
    U = -m1 * g * q + m2 * g * q
    T = me.kinetic_energy(N, pulley, *masses)
    lm = me.LagrangesMethod(T - U, [q])
    lm.form_lagranges_equations()
    (acceleration,) = lm.mass_matrix.LUsolve(lm.forcing)
    plain = {q.diff(t): z_dot, q: z}
    return T.subs(plain), acceleration.subs(plain)


@pytest.mark.slow
def test_the_engine_agrees_with_sympy_physics_mechanics():
    d = derivation("massive-pulley")
    T, acceleration = _reference()
    assert sp.simplify(d.mechanics.T - T) == 0
    (engine,) = d.equations.accelerations
    assert sp.simplify(engine - acceleration) == 0
    # the textbook result, and the massless pulley's (m₁ − m₂) g/(m₁ + m₂) as M → 0
    assert sp.simplify(engine - (m1 - m2) * g / (m1 + m2 + M / 2)) == 0
    assert sp.simplify(engine.subs(M, 0) - (m1 - m2) * g / (m1 + m2)) == 0


def test_t_is_the_masses_and_the_pulleys_turning_printed_as_a_textbook_does():
    steps = {s["key"]: s for s in derivation_document("massive-pulley")["steps"]}
    assert r"I_{\mathrm{cm}} &= \frac{M R^{2}}{2}" in steps["bodies"]["latex"]
    kinetic = steps["kinetic"]["latex"]
    # the pulley only turns: ½ (½ M R²)(ż/R)² = ¼ M ż², with no "0 +" for its centre on the axle
    assert (
        r"T_{\mathrm{pulley}} &= \tfrac{1}{2} M v_{\mathrm{cm}}^2 + \tfrac{1}{2} I_{\mathrm{cm}} "
        r"\left(\frac{\dot{z}}{R}\right)^{2} = \frac{1}{4} M \dot{z}^{2}"
    ) in kinetic
    assert kinetic.endswith(r"T &= \frac{1}{2} \left(m_{1} + m_{2} + \frac{M}{2}\right) \dot{z}^{2}\end{aligned}")


def test_the_equation_keeps_its_inertia_and_the_acceleration_reads_as_one_fraction():
    doc = derivation_document("massive-pulley")
    # 𝓜 z̈ = f as the Euler–Lagrange equation gives it (prof-q 8), not z̈ − (m₁ − m₂) g/(m₁ + m₂ + M/2) = 0
    (equation,) = doc["equations_of_motion"]
    assert equation["latex"] == r"\left(m_{1} + m_{2} + \frac{M}{2}\right) \ddot{z} = \left(m_{1} - m_{2}\right) g"
    assert equation["divided_by"] is None
    steps = {s["key"]: s["latex"] for s in doc["steps"]}
    assert steps["euler-lagrange"] == equation["latex"]
    assert doc["accelerations"]["z"]["latex"] == r"\frac{\left(m_{1} - m_{2}\right) g}{m_{1} + m_{2} + M / 2}"


def test_the_inertia_reads_m1_plus_m2_plus_half_m_everywhere():
    # the mass matrix, m_eff and the energy integral print the inertia as T does, masses first: m₁ + m₂ + M/2
    steps = {s["key"]: s["latex"] for s in derivation_document("massive-pulley")["steps"]}
    assert r"\mathcal{M} &= m_{1} + m_{2} + \frac{M}{2}" in steps["mass-matrix"]
    assert r"m_\text{eff} &= m_{1} + m_{2} + \frac{M}{2}" in steps["effective-potential"]
    assert steps["energy-integral"].startswith(r"E = \frac{1}{2} \left(m_{1} + m_{2} + \frac{M}{2}\right) \dot{z}^{2}")


def test_results_state_the_acceleration_beside_the_massless_pulleys():
    # prof-q 10: the comparison the statement asks for (M → 0) stated where Results say what the problem asks
    doc = scene_document("massive-pulley")
    (answer,) = _answers(doc)
    assert answer["title"] == "The acceleration and its limit as M → 0"
    # the numbers beside the closed forms are the defaults' values, to four figures
    p = {q.name: q.default for q in SCENES["massive-pulley"].system.parameters}
    massive = (p["m1"] - p["m2"]) * p["g"] / (p["m1"] + p["m2"] + p["M"] / 2)
    massless = (p["m1"] - p["m2"]) * p["g"] / (p["m1"] + p["m2"])
    assert answer["latex"] == (
        r"\begin{aligned}\ddot{z} &= \frac{\left(m_{1} - m_{2}\right) g}{m_{1} + m_{2} + M / 2} "
        rf"\approx {massive:.4g}\,\mathrm{{m}}\,\mathrm{{s}}^{{-2}}\quad \text{{at the defaults}} \\ "
        r"\lim_{M \to 0} \ddot{z} &= \frac{\left(m_{1} - m_{2}\right) g}{m_{1} + m_{2}} "
        rf"\approx {massless:.4g}\,\mathrm{{m}}\,\mathrm{{s}}^{{-2}}\end{{aligned}}"
    )
    assert "massless pulley" in answer["explanation"]
