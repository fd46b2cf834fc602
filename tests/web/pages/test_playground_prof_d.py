"""The playground as a professor read it (issue 40, part D): systems typed in, read back from the API and the page."""

import html as html_lib
import re
from urllib.parse import urlencode

import pytest

from app.web.pages.playground_form import form_of, query_of

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

MAGNETIC = {
    "coordinates": ["x", "y"],
    "parameters": [
        {"name": "m", "value": 1.0, "unit": "kg", "min": 0.1},
        {"name": "e", "value": 1.0, "unit": "C"},
        {"name": "B", "value": 2.0, "unit": "T"},
    ],
    "lagrangian": "m/2*(x_dot**2 + y_dot**2) + e*B/2*(x*y_dot - y*x_dot)",
}
# a system without the rotational symmetry: the springs differ along x and y
ANISOTROPIC = {
    "coordinates": ["x", "y"],
    "parameters": [
        {"name": n, "value": v, "unit": u} for n, v, u in (("m", 1.0, "kg"), ("k", 1.0, "N/m"), ("c", 2.0, "N/m"))
    ],
    "lagrangian": "m/2*(x_dot**2 + y_dot**2) - k/2*x**2 - c/2*y**2",
}


def page(client, spec) -> str:
    return client.get("/playground?" + urlencode({**query_of(form_of(spec)), "stage": "whole"}, doseq=True)).text


def test_the_magnetic_field_lists_its_angular_momentum_and_guiding_centre(client):
    doc = client.post("/api/derive", json=MAGNETIC).json()
    conserved = {c["name"]: c for c in doc["conserved"]}
    assert {"J_z", "P_x", "P_y", "h"} <= set(conserved)
    assert "Noether" in conserved["J_z"]["reason"]
    assert conserved["P_x"]["latex"] == r"m \dot{x} - B e y"
    # the page prints it under "Conserved quantities"
    text = page(client, MAGNETIC)
    listed = text[text.index("Conserved quantities") :]
    assert "J_{z}" in listed and "by Noether" in html_lib.unescape(listed)


def test_a_system_without_the_symmetry_lists_no_angular_momentum(client):
    doc = client.post("/api/derive", json=ANISOTROPIC).json()
    assert [c["name"] for c in doc["conserved"]] == ["h"]


def test_units_follow_from_the_declared_units_whatever_the_form(client):
    doc = client.post("/api/derive", json=MAGNETIC).json()
    units = {r["unicode"]: r["unit"] for r in doc["notation"]}
    assert units["p_x"] == units["p_y"] == "kg·m/s"
    assert all(units[e] == "J" for e in ("T", "U", "L", "h", "H", "E"))
    assert units["J_z"] == "kg·m²/s" and units["P_x"] == "kg·m/s"
    meaning = {r["unicode"]: r["meaning"] for r in doc["notation"]}
    # parameters described by what their units declare them to be
    assert (meaning["m"], meaning["e"], meaning["B"]) == ("mass", "charge", "magnetic field")


def test_an_angle_parameter_is_described_as_an_angle(client):
    cone = {
        "coordinates": ["r", "phi"],
        "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "g", "value": 9.81, "unit": "m/s^2"},
                       {"name": "alpha", "value": 0.5}],
        "kinetic": "m/2*(r_dot**2/sin(alpha)**2 + r**2*phi_dot**2)",
        "potential": "m*g*r/tan(alpha)",
    }  # fmt: skip
    meaning = {r["unicode"]: r["meaning"] for r in client.post("/api/derive", json=cone).json()["notation"]}
    assert (meaning["m"], meaning["g"], meaning["α"]) == ("mass", "acceleration", "angle")


@pytest.mark.parametrize(
    ("name", "what", "instead"), [("q", "the generalized coordinates", "e"), ("L", "the Lagrangian", "l")]
)
def test_a_parameter_named_with_a_page_letter_is_refused_with_another_name(client, name, what, instead):
    spec = {
        **MAGNETIC,
        "parameters": [*MAGNETIC["parameters"][:1], {"name": name, "value": 1.0}, MAGNETIC["parameters"][2]],
    }
    spec["lagrangian"] = MAGNETIC["lagrangian"].replace("e*B", f"{name}*B")
    response = client.post("/api/derive", json=spec)
    assert response.status_code == 422
    detail = response.json()["detail"]
    assert f"clashes with the page's own letter {name}, {what}" in detail and f"such as {instead}" in detail
    # the playground says so at the parameter's name, and derives nothing
    text = html_lib.unescape(page(client, spec))
    assert f"clashes with the page's own letter {name}" in text and "Conserved quantities" not in text


def test_a_coordinate_may_be_called_q(client):
    spec = {
        "coordinates": ["q"],
        "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}],
        "lagrangian": "m*q_dot**2/2",
    }
    assert client.post("/api/derive", json=spec).status_code == 200
    assert re.search("clashes", page(client, spec)) is None


@pytest.mark.parametrize(
    ("lagrangian", "said"),
    [
        ("m/2*x_dot**2 + c*x", "In the Lagrangian: unknown name"),
        # no velocity: ∂, not d, and the en dash of Euler–Lagrange
        ("m*x*y", "In the Lagrangian: the mass matrix ∂²L/∂q̇² is zero: L has no term quadratic in the velocities, "
                  "so the Euler–Lagrange equations"),
    ],
)  # fmt: skip
def test_a_refusal_names_its_field_in_words(client, lagrangian, said):
    text = html_lib.unescape(page(client, {**MAGNETIC, "lagrangian": lagrangian}))
    box = text[text.index('id="form-error"') :]
    assert said in box[: box.index("</div>")] and "lagrangian:" not in box[: box.index("</div>")]


DRIVEN = {
    "coordinates": ["theta"],
    "parameters": [{"name": n, "value": v, "unit": u} for n, v, u in
                   (("m", 1.0, "kg"), ("l", 1.0, "m"), ("a", 0.1, "m"), ("w", 20.0, "1/s"), ("g", 9.81, "m/s^2"))],
    "particles": [{"mass": "m", "position": ["l*sin(theta)", "0", "a*cos(w*t) - l*cos(theta)"]}],
    "potential": "m*g*(a*cos(w*t) - l*cos(theta))",
}  # fmt: skip


def test_a_potential_with_explicit_time_is_not_said_to_depend_on_positions_only(client):
    doc = client.post("/api/derive", json=DRIVEN).json()
    step = next(s for s in doc["steps"] if s["key"] == "potential")
    assert "positions only" not in step["explanation"] and "explicitly, on the time t" in step["explanation"]
    # a pendulum at rest below its fixed pivot keeps the sentence
    still = {**DRIVEN, "parameters": DRIVEN["parameters"][:2] + DRIVEN["parameters"][4:],
             "particles": [{"mass": "m", "position": ["l*sin(theta)", "0", "-l*cos(theta)"]}], "potential": "-m*g*l*cos(theta)"}  # fmt: skip
    step = next(s for s in client.post("/api/derive", json=still).json()["steps"] if s["key"] == "potential")
    assert step["explanation"] == "The potential energy depends on positions only."


def test_nothing_conserved_says_which_cause_applies(client):
    text = html_lib.unescape(page(client, DRIVEN))
    assert "Nothing is conserved here: L depends explicitly on time (∂L/∂t ≠ 0), so h changes" in text
    assert "a non-conservative force acts or" not in text
    damped = {"coordinates": ["x"], "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "b", "value": 0.1, "unit": "kg/s"}],
              "kinetic": "m*x_dot**2/2", "potential": "0", "forces": {"x": "-b*x_dot"}}  # fmt: skip
    text = html_lib.unescape(page(client, damped))
    assert (
        "Nothing is conserved here: a generalized force that no potential describes acts on x and does work, so h"
        in text
    )


CONE = {
    "coordinates": ["r", "phi"],
    "nonnegative": ["r"],
    "parameters": [{"name": "m", "value": 0.1, "unit": "kg"}, {"name": "g", "value": 9.81, "unit": "m/s^2"},
                   {"name": "alpha", "value": 0.5, "unit": "rad"}],
    "kinetic": "m/2*(r_dot**2/sin(alpha)**2 + r**2*phi_dot**2)",
    "potential": "m*g*r*cot(alpha)",
}  # fmt: skip


def test_the_cone_prints_its_steady_motion_as_a_textbook_does(client):
    doc = client.post("/api/derive", json=CONE).json()
    (e,) = doc["effective_potential"]["equilibria"]
    # r₀³ = p_φ² tan α/(m² g), not ∛(1/cot α)|p_φ|^(2/3)/(m^(2/3)∛g)
    assert e["power"] == 3 and e["position_power"]["latex"] == r"\frac{p_{\varphi}^{2} \tan {\alpha}}{m^{2} g}"
    assert (
        doc["effective_potential"]["omega_squared_steady"]["latex"] == r"\frac{3 g \sin {\alpha} \cos {\alpha}}{r_{0}}"
    )
    (step,) = [s for s in doc["steps"] if s["key"] == "reduced-equilibria"]
    assert (
        r"r_0^{3} &= \frac{p_{\varphi}^{2} \tan {\alpha}}{m^{2} g}" in step["latex"]
        and "frac{2}{3}" not in step["latex"]
    )
    text = page(client, CONE)
    summary = text[text.index("<dt>Effective potential</dt>") :]
    assert "r_0^{3} = " in html_lib.unescape(summary) and "frac{2}{3}" not in summary[: summary.index("</dd>")]


@pytest.mark.slow
def test_a_fall_into_the_centre_is_said_in_words(client):
    # radial infall of the Kepler problem: the run ends where r reaches 0, said without a solver's words
    spec = {"coordinates": ["r", "phi"], "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "k", "value": 1.0}],
            "lagrangian": "m/2*(r_dot**2 + r**2*phi_dot**2) + k/r"}  # fmt: skip
    body = {**spec, "initial": {"r": 1.0, "phi": 1.0, "r_dot": 0.0, "phi_dot": 0.0}, "t_end": 10.0}
    text = client.post("/api/simulate", json=body).text
    assert "underflow" not in text and "det M" not in text and "2.7e" not in text
    assert "The run stops at t = " in text and "divide by" in text
