"""How the Equilibria step states what it found, as the derivation document serves it (issue 40):
none, isolated points in closed form, families, everywhere; each listed once; one letter per quantity."""

from __future__ import annotations

import pytest

from app.service.chapter.derivations import derivation_document


def step(doc, key):
    return next(s for s in doc["steps"] if s["key"] == key)


def keys(doc, prefix):
    return [s["key"] for s in doc["steps"] if s["key"].startswith(prefix)]


@pytest.mark.parametrize("scene_id", ["helix-bead", "incline-block", "movable-incline"])
def test_no_equilibrium_is_never_written_as_a_condition_that_holds(scene_id):
    doc = derivation_document(scene_id)
    eq = step(doc, "equilibria")
    # the force along the slope is a constant: "≠ 0", never "= 0", and the step says there is none
    assert r"\neq 0" in eq["latex"]
    for row in eq["latex"].removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}").split(r" \\ "):
        # a row is "∂U/∂q = 0" (U free of q), "∂U/∂q = … ≠ 0", or the sentence; never "= … = 0"
        right = row.partition("&= ")[2]
        assert right in ("0", "") or right.endswith(r"\neq 0"), row
    assert r"\text{no equilibrium}" in eq["latex"]
    assert doc["normal_modes"] == [] and not keys(doc, "normal-modes")
    reduced = [s for s in doc["steps"] if s["key"] == "reduced-equilibria"]
    for s in reduced:
        # no frequency about an equilibrium that does not exist
        assert r"\omega^2" not in s["latex"] and r"\neq 0" in s["latex"]


def test_the_rail_states_its_family_of_equilibria():
    doc = derivation_document("rail-two-body")
    eq = step(doc, "equilibria")
    assert r"\text{every state with } x_{2} - x_{1} &= l_{0}" in eq["latex"]
    assert "- l_{0},\\; x_{2} = 0" not in eq["latex"]
    modes = step(doc, "normal-modes:1")
    assert modes["title"] == "Normal modes about the equilibria x₂ − x₁ = l₀"


def test_isolated_points_are_in_closed_form():
    for sid in ("simple-pendulum", "double-pendulum", "damped-pendulum"):
        doc = derivation_document(sid)
        titles = [s["title"] for s in doc["steps"] if s["key"].startswith("normal-modes")]
        assert any("π" in t for t in titles), titles
        assert not any("3.14159" in t for t in titles)
    sph = derivation_document("spherical-pendulum")
    eq = step(sph, "equilibria")
    assert r"\theta &= \pi" in eq["latex"] and "3.14159" not in eq["latex"]


def test_the_spherical_pendulum_lists_its_cone_once_with_its_mass_exact():
    doc = derivation_document("spherical-pendulum")
    steady = [e for e in doc["normal_modes"] if e["momenta"]]
    assert len(steady) == 1 and steady[0]["equilibrium"]["theta"] > 0
    s = step(doc, "steady-motion:1")
    # one coordinate: ω² alone, four figures with its unit, no 1×1 matrices in brackets
    assert "1.0" not in s["latex"] and r"\begin{matrix}" not in s["latex"]
    assert "35.7045920522236" not in s["latex"] and r"\omega^2 &= 35.7\,\mathrm{s}^{-2}" in s["latex"]


def test_one_letter_one_quantity_on_the_rotating_parabola():
    doc = derivation_document("rotating-parabola")
    # ω is the rotation rate; the frequency of small oscillations is Ω
    # one coordinate, no momentum held: the reduction's equilibria are the Equilibria step's, said once
    assert not [s for s in doc["steps"] if s["key"] == "reduced-equilibria"]
    s = step(doc, "normal-modes:1")
    assert r"\Omega" in s["latex"], s["latex"]
    assert r"\omega_{1}^2" not in s["latex"] and r"\omega^2 =" not in s["latex"]
    assert "Ω² = 2 g α − ω²" in step(doc, "equilibria")["explanation"]
    letters = [row["unicode"] for row in doc["notation"]]
    assert len(letters) == len(set(letters))
    meaning = {row["unicode"]: row["meaning"] for row in doc["notation"]}
    assert "frequency" in meaning["Ω"] and meaning["ω"] == next(
        p["description"] for n, p in doc["parameters"].items() if n == "omega"
    )


@pytest.mark.parametrize("scene_id", ["pulley", "movable-incline"])
def test_the_mass_matrix_is_not_m_where_a_body_has_mass_m(scene_id):
    doc = derivation_document(scene_id)
    assert "M" in doc["parameters"]
    mm = step(doc, "mass-matrix")
    assert mm["latex"].startswith(r"\begin{aligned}\mathcal{M} &=") and "ℳ" in mm["explanation"]
    assert "M is not diagonal" not in mm["explanation"]
    table = {row["unicode"]: row for row in doc["notation"]}
    assert table["M"]["kind"] == "parameter" and table["ℳ"]["meaning"].startswith("mass matrix")
    assert len(table) == len(doc["notation"])


def test_every_scene_serves_a_table_with_each_letter_once():
    from app.scenes import SCENES

    for sid in SCENES:
        doc = derivation_document(sid)
        letters = [row["unicode"] for row in doc["notation"]]
        assert len(letters) == len(set(letters)), (sid, letters)
        assert {r["unicode"] for r in doc["notation"] if r["kind"] == "coordinate"} == {
            doc["symbols"][q]["unicode"] for q in doc["coordinates"]
        }


@pytest.mark.slow
def test_a_bead_on_a_turning_hoop_sits_at_acos_without_trigonometry_of_atan():
    import sympy as sp

    from app.engine.derivation.derive import derive
    from app.engine.document.report_modes import normal_mode_steps
    from app.engine.equilibria.modes import normal_modes
    from app.scenes.types import Parameter, Particle, System

    system = System(
        coordinates=("theta",),
        parameters=(Parameter("m", 1.0), Parameter("g", 9.81), Parameter("R", 1.0), Parameter("w", 5.0)),
        particles=(Particle("m", ("R*sin(theta)*cos(w*t)", "R*sin(theta)*sin(w*t)", "-R*cos(theta)")),),
        potential="-m*g*R*cos(theta)",
    )
    d = derive(system)
    nm = normal_modes(d.system, d.mechanics, d.equations, d.reduction)
    assert not nm.failed
    m, g, R, w = (sp.Symbol(n, real=True) for n in ("m", "g", "R", "w"))
    tilted = [e for e in nm.equilibria if abs(e.position["theta"]) not in (0.0, pytest.approx(3.141592653589793))]
    assert len(tilted) == 2
    for e in tilted:
        # cos θ₀ = g/(Rω²) (here ω is w): the closed form is ±acos(g/(R w²)), and M is m R²
        assert sp.simplify(sp.cos(e.exact["theta"]) - g / (R * w**2)) == 0
        assert not e.exact["theta"].has(sp.atan)
        assert sp.simplify(e.mass[0, 0] - m * R**2) == 0
    text = " ".join(s["latex"] for s in normal_mode_steps(d, nm))
    assert "atan" not in text and r"\pi" in text and "3.14159" not in text
