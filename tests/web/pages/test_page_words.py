"""Words and letters a student reads, pinned by what the API serves (issue 40, item 7)."""

from __future__ import annotations

import html
import json
import math
import re

import pytest
import sympy as sp

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

SCENES_WITH_A_REDUCTION = ["tabletop-spring", "spherical-pendulum", "rotating-parabola", "helix-bead"]


def steps(client, scene: str) -> dict[str, dict]:
    return {s["key"]: s for s in client.get(f"/api/scenes/{scene}/derivation").json()["steps"]}


@pytest.mark.parametrize("scene", SCENES_WITH_A_REDUCTION)
def test_the_energy_integral_uses_the_pages_own_letter(client, scene):
    shown = steps(client, scene)
    energy, time = shown["energy-integral"]["latex"], shown["time-integral"]["latex"]
    assert "E_r" not in energy + time and "E_{r}" not in energy + time
    # the rotating parabola's conserved quantity is h (h ≠ E in the rotating set-up); the others', E
    letter = "h" if scene == "rotating-parabola" else "E"
    assert energy.startswith(f"{letter} = ") and f"\\left({letter} - U_\\text{{eff}}" in time


def test_the_tabletop_energy_integral_is_kinetic_then_u_eff_as_printed_a_step_before(client):
    shown = steps(client, "tabletop-spring")
    u_eff = (
        shown["effective-potential"]["latex"][0] if isinstance(shown["effective-potential"]["latex"], list) else None
    )
    energy = shown["energy-integral"]["latex"]
    assert energy == r"E = \frac{1}{2} m \dot{r}^{2} + \frac{p_{\theta}^{2}}{2 m r^{2}} + \frac{1}{2} k r^{2}"
    assert u_eff is None or u_eff.endswith(r"\frac{p_{\theta}^{2}}{2 m r^{2}} + \frac{1}{2} k r^{2}")


def test_the_helix_winding_is_described_in_its_unit(client):
    alpha = client.get("/api/scenes/helix-bead/derivation").json()["parameters"]["alpha"]
    assert alpha["unit"] == "rad/m" and "radians" in alpha["description"] and "turns of" not in alpha["description"]
    assert "radians of turn per metre" in client.get("/scenes/helix-bead").text


# ---- issue 40, part B: scenes 7–12 and the Symbols tables -------------------------------------------------


def test_the_rail_errata_write_partials_and_the_total_mass(client):
    errata = client.get("/api/scenes/rail-two-body/derivation").json()["errata"]
    partials, momentum = errata[0]["correct_latex"], errata[1]["correct_latex"]
    assert partials.startswith(r"\frac{\partial L}{\partial x_{1}} = - \frac{\partial L}{\partial x_{2}}")
    assert r"\frac{dL}" not in partials
    assert momentum.startswith(r"P = \left(m_{1} + m_{2}\right) \dot{X}") and "M" not in momentum


def test_the_rail_names_its_bodies_masses(client):
    page = client.get("/scenes/rail-two-body").text
    for other in ("two cars", "blocks", "body 1", "first body"):
        assert other not in page


def test_a_mode_shape_is_exact_where_it_is_and_omega_squared_has_four_figures_and_a_unit(client):
    rail = steps(client, "rail-two-body")["normal-modes:1"]["latex"]
    assert r"\approx 15\,\mathrm{s}^{-2}" in rail and r"a_{2} = \begin{pmatrix}1\\- \frac{m_{1}}{m_{2}}\end{pmatrix}" in rail
    pendulum = steps(client, "double-pendulum")["normal-modes:1"]["latex"]
    assert r"\approx 5.747\,\mathrm{s}^{-2}" in pendulum and "5.74656" not in pendulum and "0.707107" not in pendulum
    coupled = steps(client, "coupled-oscillators")["normal-modes:1"]["latex"]
    assert r"a_{2} = \begin{pmatrix}1\\-1\end{pmatrix}" in coupled


@pytest.mark.parametrize("scene", ["coupled-oscillators", "double-pendulum", "rail-two-body"])
def test_the_normal_modes_write_eta_for_the_displacement_epsilon_being_the_action_panels(client, scene):
    for key, step in steps(client, scene).items():
        if key.startswith("normal-modes"):
            assert "ε" not in step["explanation"]
    explained = steps(client, "double-pendulum")["normal-modes:1"]["explanation"]
    assert "ℳ η̈ + K η = 0" in explained and "η = a cos ωt" in explained


def test_generic_sentences_name_only_what_the_system_has(client):
    # the engine's own sentences (what a typed system gets; these two scenes print their reasons instead)
    from app.engine.document.contract import derivation_json
    from app.service.chapter.derivations import derivation

    def generic(scene: str) -> dict[str, dict]:
        return {s["key"]: s for s in derivation_json(derivation(scene), beyond=False)["steps"]}

    shown = generic("coupled-oscillators")
    assert "sin²" not in shown["squared-speeds"]["explanation"]
    assert "− Q" not in shown["euler-lagrange"]["explanation"]
    served = steps(client, "coupled-oscillators")
    assert " b" not in served["legendre"]["explanation"] and "(p − b)" not in served["hamiltonian-pq"]["explanation"]
    # the double pendulum's v² does use the identity
    pendulum = generic("double-pendulum")
    assert "sin² + cos² = 1" in pendulum["squared-speeds"]["explanation"]


def test_the_symbols_table_lists_units_and_the_momenta(client):
    rows = {r["unicode"]: r for r in client.get("/api/scenes/rail-two-body/derivation").json()["notation"]}
    assert rows["x₁"]["unit"] == "m" and rows["p_x₁"]["unit"] == "kg·m/s" and rows["ω"]["unit"] == "rad/s"
    assert all(rows[e]["unit"] == "J" for e in ("T", "U", "L", "h", "H", "E")) and rows["t"]["unit"] == "s"
    assert "η" in rows and "a" in rows and "f" in rows
    angles = {r["unicode"]: r for r in client.get("/api/scenes/double-pendulum/derivation").json()["notation"]}
    assert angles["θ₁"]["unit"] == "rad" and angles["p_θ₁"]["unit"] == "kg·m²/s"
    assert "kg·m/s" in client.get("/scenes/rail-two-body").text


def test_the_pulley_tension_is_lambda_times_the_gradient_in_the_end_mass(client):
    shown = steps(client, "pulley")
    force = shown["constraint-forces"]["latex"]
    assert r"\frac{\partial \mathcal{C}_{1}}{\partial \vec r_{1}}" in force and r"\nabla" not in force
    assert "ζ₁, ζ₂, ζ₃ the heights of m₁, m₂ and M" in shown["constraints"]["explanation"]
    assert "every position is an equilibrium" in shown["equilibria"]["explanation"]


def test_the_wedge_height_is_z_and_the_parabola_alpha_is_not_called_curvature(client):
    wedge = client.get("/scenes/movable-incline").text
    assert "height z = −D sin α" in wedge and "(X + D cos α, −D sin α)" not in wedge
    alpha = client.get("/api/scenes/rotating-parabola/derivation").json()["parameters"]["alpha"]["description"]
    assert not alpha.startswith("curvature") and "curvature at the bottom is 2α" in alpha
    assert "signed horizontal distance" in client.get("/scenes/rotating-parabola").text


def test_the_symbols_table_lists_the_letters_of_the_optional_steps(client):
    def rows(scene: str) -> dict[str, dict]:
        return {r["unicode"]: r for r in client.get(f"/api/scenes/{scene}/derivation").json()["notation"]}

    rail = rows("rail-two-body")
    assert rail["X"]["unit"] == "m" and "(m₁x₁ + m₂x₂)/(m₁ + m₂)" in rail["X"]["meaning"]
    assert rail["μ"]["unit"] == "kg" and rail["x"]["unit"] == "m"
    pulley = rows("pulley")
    assert {"𝒞", "λ", "ζ₁", "ζ₂", "ζ₃"} <= set(pulley) and pulley["F₁"]["unit"] == "N"
    assert pulley["F₁"]["meaning"] == "string tension" and "F" not in pulley
    assert pulley["ζ₃"]["meaning"] == "Cartesian z of the middle mass"
    parabola = rows("rotating-parabola")
    # ρ's unit is told from m (1 + 4α²ρ²), so the energies are in J
    assert parabola["ρ"]["unit"] == "m" and parabola["h"]["unit"] == "J"
    assert parabola["U_eff"]["unit"] == "J" and parabola["m_eff"]["unit"] == "kg" and "bead" in parabola["z"]["meaning"]
    # −L at q̇ = 0 is the effective potential here: one name, U_eff, never a third letter V (prof-g 41)
    assert "V" not in parabola
    wedge = rows("movable-incline")
    assert wedge["x₂"]["meaning"] == "Cartesian x of the block" and wedge["m_eff"]["unit"] == "kg"
    # each letter once
    for scene in ("rail-two-body", "pulley", "rotating-parabola", "movable-incline"):
        letters = [r["unicode"] for r in client.get(f"/api/scenes/{scene}/derivation").json()["notation"]]
        assert len(letters) == len(set(letters))
    assert "Cartesian z of the middle mass" in client.get("/scenes/pulley").text


def scene_data(client, scene: str) -> dict:
    page = client.get(f"/scenes/{scene}").text
    return json.loads(re.search(r'<script type="application/json" id="scene-data">(.*?)</script>', page, re.S)[1])


def test_the_small_oscillations_panel_gets_the_pages_frequency_letter(client):
    # the parabola turns at ω, so its small-oscillation frequency is Ω, in the derivation and in the panel
    assert scene_data(client, "rotating-parabola")["frequency_letter"] == "Ω"
    assert scene_data(client, "tabletop-spring")["frequency_letter"] == "ω"


def test_the_rail_lists_the_total_momentum_in_its_own_coordinates(client):
    conserved = {c["name"]: c for c in client.get("/api/scenes/rail-two-body/derivation").json()["conserved"]}
    total = conserved["p_x1 + p_x2"]
    assert total["latex"] == r"m_{1} \dot{x}_{1} + m_{2} \dot{x}_{2}" and "∂L/∂x₁ + ∂L/∂x₂ = 0" in total["reason"]
    # the springs to the walls break the translation: the coupled oscillators conserve only E
    assert [c["name"] for c in client.get("/api/scenes/coupled-oscillators/derivation").json()["conserved"]] == ["E"]
    assert scene_data(client, "rail-two-body")["labels"]["p_x1 + p_x2"] == "p_x₁ + p_x₂"


def test_the_pulley_derives_the_middle_masss_acceleration_from_the_engines_two(client):
    doc = client.get("/api/scenes/pulley/derivation").json()
    accelerations = {q: sp.sympify(a["sympy"]) for q, a in doc["accelerations"].items()}
    m1, m2, M, g = sp.symbols("m1 m2 M g")
    middle = -(accelerations["y1"] + accelerations["y2"]) / 2
    # the sentence writes it over the common denominator (prof-g 36: no fraction inside a denominator)
    assert sp.simplify(middle - (4 * m1 * m2 - M * (m1 + m2)) * g / (4 * m1 * m2 + M * (m1 + m2))) == 0
    explained = {s["key"]: s for s in doc["steps"]}["accelerations"]["explanation"]
    assert "Ÿ = −(ÿ₁ + ÿ₂)/2 = [4m₁m₂ − M(m₁ + m₂)] g/[4m₁m₂ + M(m₁ + m₂)]" in explained


def test_the_coupled_oscillators_derive_their_beats(client):
    shown = steps(client, "coupled-oscillators")
    beats = shown["beats:1"]
    assert r"\omega_1 &= \sqrt{\frac{k}{m}},\quad \omega_2 = \sqrt{\frac{k + 2 \kappa}{m}}" in beats["latex"]
    assert (
        r"= A \cos\left(\tfrac{\omega_2 - \omega_1}{2}\, t\right) \cos\left(\tfrac{\omega_1 + \omega_2}{2}\, t\right)"
        in (beats["latex"])
    )
    # π/(ω₂ − ω₁) and 2π/(ω₂ − ω₁) at the page's default k, κ and m
    p = {
        n: v["default"]
        for n, v in client.get("/api/scenes/coupled-oscillators/derivation").json()["parameters"].items()
    }
    w1, w2 = (p["k"] / p["m"]) ** 0.5, ((p["k"] + 2 * p["kappa"]) / p["m"]) ** 0.5
    assert (
        f"{3.141592653589793 / (w2 - w1):.4g} s and {2 * 3.141592653589793 / (w2 - w1):.4g} s" in beats["explanation"]
    )
    # modes that are not a symmetric pair get no beats step
    assert not any(k.startswith("beats") for k in steps(client, "double-pendulum"))
    assert "A" in {r["unicode"] for r in client.get("/api/scenes/coupled-oscillators/derivation").json()["notation"]}


def test_the_parameters_table_prints_ranges_as_the_sliders_do(client):
    import re

    page = client.get("/scenes/tabletop-spring").text
    table = " ".join(
        re.sub(r"<[^>]+>", " ", re.search(r'<table class="parameters">.*?</table>', page, re.S)[0]).split()
    )
    assert "0.01 to 1,000 N/m" in table and "e+" not in table


def test_a_cyclic_coordinates_momentum_is_named_in_its_conservation_sentence(client):
    page = client.get("/scenes/movable-incline").text
    assert "so dp<sub>X</sub>/dt = ∂L/∂X = 0" in page and "so dp/dt" not in page


def test_initial_conditions_print_their_ranges_with_a_true_minus(client):
    page = client.get("/scenes/simple-pendulum").text
    assert "allowed: −3.142 to 3.142 rad" in page and "allowed: −10 to 10 rad/s" in page
    assert "allowed: -3.142" not in page


@pytest.mark.parametrize(
    "scene", ["simple-pendulum", "helix-bead", "incline-block", "tabletop-spring", "damped-pendulum"]
)
def test_h_equals_e_is_not_given_as_the_reason_h_is_conserved(client, scene):
    # prof-e 4: "The positions do not depend on t, so h = E and both are conserved." mixes two conditions
    said = steps(client, scene)["h-vs-e"]["explanation"]
    assert "so h = E" in said and "both are conserved" not in said and "so h = E and" not in said
    # conservation has its own reason: no explicit t in L and no work by a non-conservative force (or drag's work)
    assert ("L has no explicit t and no non-conservative force does work, so h is conserved" in said) is (
        scene != "damped-pendulum"
    )
    assert ("the drag does work, so h (and E with it) decays" in said) is (scene == "damped-pendulum")


def test_m_eff_is_defined_as_what_the_results_print(client):
    # prof-f: the wedge's Symbols row said "∂²L/∂Ḋ²" (that is m) beside m_eff = (M + m sin²α) m/(M + m)
    page = client.get("/scenes/movable-incline").text
    assert "∂²L/∂Ḋ²" not in page
    assert "effective mass of D: the mass D moves with once the conserved momenta are held fixed" in page


@pytest.mark.parametrize("scene", ["simple-pendulum", "damped-pendulum", "coupled-oscillators", "spherical-pendulum"])
def test_linearised_is_spelled_one_way(client, scene):
    # prof-g 5: "Linearizing" in one step and "Linearised" in the next; the site spells it with an s
    page = client.get(f"/scenes/{scene}").text
    assert not re.search(r"lineari[zZ]", page, re.I), re.search(r".{40}lineariz.{20}", page, re.I)
    if scene == "simple-pendulum":
        assert "Linearising sin θ about each equilibrium" in page


def test_a_one_coordinate_equilibrium_is_part_of_its_equation(client):
    # prof-g 5: a lone row "θ = 0" stood above ω² = g/R, reading as an equation of its own
    shown = steps(client, "simple-pendulum")
    assert shown["normal-modes:1"]["latex"].startswith(r"\text{about } \theta=0:\quad \omega^2 = \frac{g}{R}")
    for key in ("normal-modes:1", "normal-modes:2"):
        assert not shown[key]["latex"].replace(r"\begin{aligned}", "").startswith(r"\theta")


# ---- issue 40, part A: the time integral between the turning points (prof-g 6) -----------------------------


@pytest.mark.parametrize(
    ("scene", "letter"),
    [("simple-pendulum", r"\theta"), ("tabletop-spring", "r"), ("spherical-pendulum", r"\theta"),
     ("rotating-parabola", r"\rho"), ("helix-bead", None), ("incline-block", None)],
)  # fmt: skip
def test_where_the_motion_can_turn_back_the_time_integral_has_its_limits_and_says_half_the_period(
    client, scene, letter
):
    step = steps(client, scene)["time-integral"]
    latex = step["latex"] if isinstance(step["latex"], str) else "".join(step["latex"])
    if letter is None:
        # the helix and the incline have no minimum of U_eff: nothing turns the motion back twice
        assert r"\text{min}" not in latex and "period" not in latex, latex
        return
    limits = rf"\int_{{{letter}_\text{{min}}}}^{{{letter}_\text{{max}}}}"
    assert rf"\tfrac{{1}}{{2}}\,\text{{period}} &= {limits}" in latex, latex
    # the words beside it say what the limits are and what the integral between them is
    assert "turning" in step["explanation"] and "half the" in step["explanation"], step["explanation"]


def test_the_spherical_pendulums_steady_cone_is_also_given_from_the_downward_vertical(client):
    # θ is measured from the upward vertical (prof-g 27): beside each steady motion, π − θ, from the API's own θ
    doc = client.get("/api/scenes/spherical-pendulum/derivation").json()
    titles = {s["key"]: s["title"] for s in doc["steps"]}
    steady = [(i, e) for i, e in enumerate(doc["normal_modes"], start=1) if f"steady-motion:{i}" in titles]
    assert steady, titles
    for i, e in steady:
        theta = e["equilibrium"]["theta"]
        assert 1.5708 < theta < 3.1416  # a cone below the pivot, measured from above
        below = f"{math.pi - theta:.4g}"
        assert titles[f"steady-motion:{i}"].endswith(f"(π − θ = {below} rad from the downward vertical)"), titles
    # the page prints the same title
    assert f"π − θ = {below} rad from the downward vertical" in html.unescape(client.get("/scenes/spherical-pendulum").text)
    # a pendulum measured from below says nothing of the kind
    assert "from the downward vertical)" not in client.get("/scenes/tabletop-spring").text


def test_a_slider_shows_a_usable_range_and_the_wider_typed_range_is_said_apart(client):
    # prof-g 30: "allowed: 0.01 to 100,000,000 N/m" on a slider no one can use
    page = html.unescape(client.get("/scenes/rail-two-body").text)
    control = re.search(r'<div class="control" data-group="[^"]*" data-name="k".*?<p class="hint".*?</p>', page, re.S)
    assert control, "no control for k"
    attrs = dict(re.findall(r'data-([\w-]+)="([^"]*)"', control.group(0)))
    lo, hi = float(attrs["slider-min"]), float(attrs["slider-max"])
    assert float(attrs["min"]) < lo < hi < float(attrs["max"]), attrs  # the slider spans less than may be typed
    assert hi / lo <= 1000  # three decades at most: a physical range
    hint = re.search(r'<p class="hint"[^>]*>(.*?)</p>', control.group(0), re.S).group(1)
    assert hint == f"slider: {lo:g} to {hi:g} N/m; type any value from 0.01 to 100,000,000 N/m", hint
    assert "allowed: 0.01 to 100,000,000" not in page


@pytest.mark.parametrize(("scene", "printed"), [("simple-pendulum", r"I_\text{eff} = m R^{2}"),
                                               ("tabletop-spring", r"m_\text{eff} = m")])  # fmt: skip
def test_the_results_name_an_angles_inertia_i_and_a_lengths_m(client, scene, printed):
    # prof-n 5: the simple pendulum's Results printed m_eff = mR², a moment of inertia written as a mass
    page = html.unescape(client.get(f"/scenes/{scene}").text)
    results = page[page.index("<dt>Effective potential</dt>") :]
    assert f'data-tex="{printed}"' in results[: results.index("</dd>")]
