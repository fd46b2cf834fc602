"""Issue 40: what a scene's problem asks is stated in its Results box, as the page serves it, and the scene's
prose says what is true there (reviews prof-c and prof-d)."""

from __future__ import annotations

import html
import re

import pytest


def results(client, scene_id: str) -> str:
    """The page's Results box, as served (its formulas' LaTeX unescaped, alignment marks taken out)."""
    page = client.get(f"/scenes/{scene_id}").text
    start = page.index('<section id="results"')
    return html.unescape(page[start : page.index("</section>", start)]).replace("&=", "=")


def answers(box: str) -> str:
    """The "What the problem asks" entry of a Results box ('' when there is none)."""
    if "What the problem asks" not in box:
        return ""
    start = box.index("What the problem asks")
    return box[start : box.index("<dt>", start)]


def step(client, scene_id: str, key: str) -> dict:
    return next(s for s in client.get(f"/api/scenes/{scene_id}/derivation").json()["steps"] if s["key"] == key)


def test_coupled_oscillators_state_modes_frequencies_and_beats_in_results(client):
    box = answers(results(client, "coupled-oscillators"))
    # ω₁² = k/m with a₁ = (1, 1)ᵀ, ω₂² = (k + 2κ)/m with a₂ = (1, −1)ᵀ, and the beat
    assert r"\omega_{1}^2 = \frac{k}{m}" in box and r"a_{1} = \begin{pmatrix}1\\1\end{pmatrix}" in box
    assert r"\omega_{2}^2 = \frac{k + 2 \kappa}{m}" in box and r"a_{2} = \begin{pmatrix}1\\-1\end{pmatrix}" in box
    assert "Beats" in box and r"\cos\left(\tfrac{\omega_2 - \omega_1}{2}\, t\right)" in box
    # nothing of it behind a button, on the page either: four short lines are no "long" expression
    assert "details" not in box
    assert "Show the full expression" not in client.get("/scenes/coupled-oscillators").text


def test_double_pendulum_states_the_four_equilibria_and_their_modes_in_results(client):
    box = answers(results(client, "double-pendulum"))
    titles = re.findall(r'class="answer-title">([^<]*)<', box)
    assert titles == [
        "Equilibria",
        "Normal modes about θ₁ = 0, θ₂ = 0",
        "Normal modes about θ₁ = 0, θ₂ = π",
        "Normal modes about θ₁ = π, θ₂ = 0",
        "Normal modes about θ₁ = π, θ₂ = π",
    ]
    # the method is explained once in the derivation and once in Results, not once per equilibrium
    steps = client.get("/api/scenes/double-pendulum/derivation").json()["steps"]
    assert sum("Near the equilibrium" in s["explanation"] for s in steps) == 1
    assert box.count("Near the equilibrium") == 1
    # a folded display says how long it is, counted from what it shows
    page = client.get("/scenes/double-pendulum").text
    labels = set(re.findall(r"Show the full expression \(([^)]*)\)", page))
    assert labels and all(re.fullmatch(r"\d+ lines", label) for label in labels), labels


def test_rail_shows_the_reduced_mass_oscillation_in_results(client):
    box = results(client, "rail-two-body")
    assert r"\mu \ddot{x} = -k \left(x - l_{0}\right)" in box
    assert r"\omega = \sqrt{\frac{k}{\mu}}" in box


@pytest.mark.parametrize(
    ("scene_id", "tex"),
    [
        # the damped pendulum's rate of energy loss
        ("damped-pendulum", r"- b \dot{\theta}^{2}"),
        # the tabletop's time as an integral over r, with this U_eff written in
        ("tabletop-spring", r"\int \frac{dr}{\sqrt{\frac{2}{m}\left(E - \frac{1}{2} k r^{2} - \frac{p_{\theta}^{2}}{2 m r^{2}}\right)}}"),
    ],
)
def test_the_asked_result_is_in_results(client, scene_id, tex):
    assert tex in answers(results(client, scene_id))


def test_scenes_that_ask_nothing_further_add_no_answers(client):
    assert answers(results(client, "simple-pendulum")) == ""


def test_the_rotating_wire_says_why_e_minus_h_is_2t0(client):
    doc = client.get("/api/scenes/rotating-parabola/derivation").json()
    assert "T₁ = 0" in doc["hamiltonian_energy_reason"] and "E − h = 2T₀" in doc["hamiltonian_energy_reason"]


@pytest.mark.parametrize(
    ("scene_id", "key", "says", "never"),
    [
        ("tabletop-spring", "euler-lagrange", "only on the circular orbit", "balances spring and centrifugal"),
        ("incline-block", "lagrangian", "constant force", "free particle"),
        ("helix-bead", "velocities", "at the rate α ż", "turns by α ż"),
        ("pulley", "accelerations", "Y = −(y₁ + y₂)/2 − c", "− 1 m"),
        ("pulley", "kinetic", "⅛ M (ẏ₁ + ẏ₂)²", "through the term in"),
        ("movable-incline", "effective-potential", "is a constant", "\u0000"),
    ],
)
def test_scene_prose_says_what_is_true_there(client, scene_id, key, says, never):
    text = step(client, scene_id, key)["explanation"]
    assert says in text and never not in text


def test_the_incline_and_the_ball_are_named_one_way(client):
    incline = client.get("/api/scenes/incline-block/derivation").json()["scene"]
    assert "from the foot" in incline["statement"] and "from the foot" in incline["figure"]
    ball = client.get("/api/scenes/spherical-pendulum/derivation").json()["scene"]
    assert ball["parameters"]["m"]["description"] == "mass of the ball"


@pytest.mark.parametrize(
    ("scene_id", "key", "tex"),
    [
        # a common factor out of a position: R(1 − cos θ), not −R cos θ + R
        ("simple-pendulum", "positions", r"R \left(1 - \cos {\theta}\right)"),
        # a linear force grouped by coordinate over its shared denominator
        ("coupled-oscillators", "accelerations", r"\frac{\kappa x_{2} - \left(k + \kappa\right) x_{1}}{m}"),
        ("coupled-oscillators", "mass-matrix", r"\kappa x_{2} - \left(k + \kappa\right) x_{1}"),
        # one fourth root of one fraction
        ("tabletop-spring", "reduced-equilibria", r"r_0 = \left(\frac{p_{\theta}^{2}}{m k}\right)^{1/4}"),
        # the frequency at the root θ₀, not at every θ, with p_φ eliminated by U_eff′(θ₀) = 0 (prof-m 5)
        ("spherical-pendulum", "reduced-equilibria", r"\frac{\left(1 + 3 \cos^{2} {\theta_{0}}\right) g}{R \cos {\theta_{0}}}"),
        # issue 40 (prof-h 6): 2/m_eff as one fraction, never 2 over m(M + m sin²α)/(M + m)
        (
            "movable-incline",
            "time-integral",
            r"\sqrt{\frac{2 \left(M + m\right)}{m \left(M + m \sin^{2} {\alpha}\right)}\left(E + m g D \sin {\alpha}",
        ),
    ],
)
def test_steps_print_textbook_forms(client, scene_id, key, tex):
    assert tex in step(client, scene_id, key)["latex"]


def test_the_spherical_frequency_names_no_bare_theta(client):
    latex = step(client, "spherical-pendulum", "reduced-equilibria")["latex"]
    omega_row = latex.split(r"\omega^2")[1]
    assert not re.search(r"\\theta(?!_)", omega_row), omega_row


def test_the_double_pendulum_says_how_each_equation_is_scaled(client):
    text = step(client, "double-pendulum", "euler-lagrange")["explanation"]
    assert "the θ₁ equation by l₁" in text and "the θ₂ equation by m₂l₂" in text


def test_a_polar_angle_starts_between_the_poles(client):
    # θ from the upward vertical runs over [0, π]; the planar pendulum's θ goes once round, (−π, π]
    spherical = client.get("/scenes/spherical-pendulum").text
    assert re.findall(r"allowed: ([^<]*) rad<", spherical)[0] == "0 to 3.142"
    planar = client.get("/scenes/simple-pendulum").text
    assert re.findall(r"allowed: ([^<]*) rad<", planar)[0] == "−3.142 to 3.142"
