"""Display names have one home: LaTeX, Unicode and plain forms agree everywhere."""

import pytest

from app.engine.derivation.derive import derive
from app.engine.display.names import latex, plain, prose, unicode
from app.engine.document.contract import derivation_json
from app.engine.document.model import Document
from app.scenes.types import Parameter, System
from app.viz.page_model import scene_page


def test_forms_of_a_name():
    assert (latex("theta_dot"), unicode("theta_dot"), plain("theta_dot")) == (r"\dot{\theta}", "θ̇", "theta_dot")
    assert (latex("theta1_ddot"), unicode("theta1_ddot")) == (r"\ddot{\theta}_{1}", "θ̈₁")
    assert (latex("x1"), unicode("x1")) == ("x_{1}", "x₁")
    assert (latex("p_phi"), unicode("p_phi")) == (r"p_{\varphi}", "p_φ")  # one glyph: KaTeX \varphi is φ
    assert (latex("Omega"), unicode("Omega")) == (r"\Omega", "Ω")
    assert latex("U_eff") == r"U_{\text{eff}}" and latex("E_r") == "E_{r}"


def test_names_in_prose_are_written_as_a_reader_writes_them():
    text = "Two masses m1 and m2 at x1, x2 with rest length l0; start at theta_0 (section 4.5, Ex. 4.2)."
    assert prose(text) == "Two masses m₁ and m₂ at x₁, x₂ with rest length l₀; start at θ₀ (section 4.5, Ex. 4.2)."


@pytest.mark.slow
def test_omega_is_the_same_letter_in_steps_controls_and_document():
    hoop = System(
        coordinates=("theta",),
        parameters=(Parameter("m", 1.0, "kg", 0.01, 10.0), Parameter("R", 1.0, "m", 0.1, 10.0),
                    Parameter("g", 9.81, "m/s²", 0.1, 30.0), Parameter("Omega", 3.0, "rad/s", 0.0, 20.0)),
        lagrangian="m*R**2*(theta_dot**2 + Omega**2*sin(theta)**2)/2 + m*g*R*cos(theta)",
    )  # fmt: skip
    doc = derivation_json(derive(hoop), beyond=False)
    assert doc["symbols"]["Omega"] == {"latex": r"\Omega", "unicode": "Ω", "plain": "Omega"}
    assert doc["angles"] == ["theta"]
    lagrangian = next(s for s in doc["steps"] if s["title"] == "Lagrangian")["latex"]
    assert r"\Omega^{2}" in lagrangian and "Omega" not in lagrangian.replace(r"\Omega", "")
    info = {"id": "hoop", "title": "Hoop", "panels": ["energy"], "initial": {"theta": 0.5}, "t_end": 5.0}
    model = scene_page(Document.model_validate(doc), info)
    control = next(c for c in model["parameters"] if c["name"] == "Omega")
    assert (control["latex"], control["label"]) == (r"\Omega", "Ω")
    assert next(c for c in model["initial"] if c["name"] == "theta")["unit"] == "rad"


def test_a_name_of_several_letters_is_greek_or_one_upright_name():
    from app.engine.display.names import latex, unicode

    # prof-g 56: th is no Greek letter's name: one upright name, the dot over all of it; theta is θ
    assert latex("th") == r"\mathrm{th}" and latex("th_dot") == r"\dot{\mathrm{th}}"
    assert latex("th2_ddot") == r"\ddot{\mathrm{th}}_{2}" and latex("theta_dot") == r"\dot{\theta}"
    assert unicode("th_dot") == "th˙" and unicode("theta_dot") == "θ̇" and unicode("x1_dot") == "x\u0307\u2081"


@pytest.mark.slow
def test_a_momentums_rate_has_its_dot_on_the_p_not_over_the_subscript():
    """prof-m 10a: Hamilton's equations set \\dot{p_θ}, the dot between p and θ; a textbook prints ṗ_θ."""
    assert (latex("p_theta_dot"), unicode("p_theta_dot")) == (r"\dot{p}_{\theta}", "p\u0307_θ")
    assert (latex("p_theta1_dot"), unicode("p_theta1_dot")) == (r"\dot{p}_{\theta_{1}}", "p\u0307_θ₁")
    assert latex("p_phi_dot") == r"\dot{p}_{\varphi}" and latex("p_x_dot") == r"\dot{p}_{x}"
    doc = derivation_json(derive(_spherical()))
    rows = next(s for s in doc["steps"] if s["key"] == "hamilton-equations")["latex"]
    assert r"\dot{p}_{\theta} &= -\frac{\partial H}{\partial \theta}" in rows
    assert r"\dot{p}_{\varphi} &= -\frac{\partial H}{\partial \varphi} = 0" in rows
    assert r"\dot{p_" not in rows


def _spherical() -> System:
    return System(
        coordinates=("theta", "phi"),
        parameters=(Parameter("m", 1.0, "kg", 0.01, 10.0), Parameter("R", 1.0, "m", 0.1, 10.0),
                    Parameter("g", 9.81, "m/s²", 0.1, 30.0)),
        lagrangian="m*R**2*(theta_dot**2 + phi_dot**2*sin(theta)**2)/2 - m*g*R*cos(theta)",
    )  # fmt: skip
