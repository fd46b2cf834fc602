"""What every scene page prints from the shared templates, pinned by the pages served (issue 40, part A)."""

from __future__ import annotations

import html
import re

import pytest

from app.scenes import SCENES

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

ALL = list(SCENES)


def page(client, scene: str) -> str:
    served = client.get(f"/scenes/{scene}")
    assert served.status_code == 200
    return served.text


def symbols_table(text: str) -> tuple[str, str]:
    """(the Symbols table's markup, the page without it)."""
    start = text.index('<table class="symbols">')
    end = text.index("</table>", start) + len("</table>")
    return text[start:end], text[:start] + text[end:]


def maths(text: str) -> list[str]:
    return re.findall(r"<math\b.*?</math>", text, flags=re.S)


def inner(math: str) -> str:
    """A formula's MathML inside its outer <math><mrow>."""
    body = re.sub(r"^<math[^>]*>|</math>$", "", math)
    return re.sub(r"^<mrow>(.*)</mrow>$", r"\1", body, flags=re.S)


def words(text: str) -> str:
    """The running text a reader sees: no scripts, styles, formulas or markup."""
    text = re.sub(r"<(script|style|math)\b.*?</\1>", " ", text, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", " ", text))


def in_words(letter: str, text: str) -> bool:
    """``letter`` stands alone in the running text; "a" and "A" count only as mathematics (beside an = sign)."""
    for m in re.finditer(re.escape(letter), text):
        before, after = text[max(0, m.start() - 3) : m.start()], text[m.end() : m.end() + 3]
        if re.match(r"[\w\u0300-\u036f]", after[:1] or " ") and not re.match(r"[₀-₉]", after[:1]):
            continue
        if re.search(r"[\w\u0300-\u036f]$", before):
            continue
        if letter in ("a", "A") and "=" not in before + after:
            continue
        return True
    return False


@pytest.mark.parametrize("scene", ALL)
def test_every_symbol_row_names_a_letter_the_page_prints(client, scene):
    table, rest = symbols_table(page(client, scene))
    notation = {r["latex"]: r["unicode"] for r in client.get(f"/api/scenes/{scene}/derivation").json()["notation"]}
    formulas = "".join(inner(m) for m in maths(rest))
    prose = words(rest)
    rows = re.findall(r'<tr><td><span class="math" data-tex="([^"]*)">(.*?)</span></td>', table, flags=re.S)
    assert rows
    missing = [
        tex for tex, math in rows if inner(math) not in formulas and not in_words(notation[html.unescape(tex)], prose)
    ]
    assert missing == [], f"{scene}: the Symbols table lists {missing}, which the page never prints"


def test_a_planar_pendulum_lists_no_beats_and_no_mode_shape(client):
    table, _ = symbols_table(page(client, "simple-pendulum"))
    assert "displacement the beats start from" not in table and "amplitudes of a normal mode" not in table
    coupled, _ = symbols_table(page(client, "coupled-oscillators"))
    assert "displacement the beats start from" in coupled


def steps_of(text: str) -> list[tuple[str, str, str]]:
    """(title, explanation, formula's LaTeX) of every step on a page, the folded ones too."""
    found = re.findall(
        r'<h3 class="step-title">(.*?)</h3>\s*<p class="explanation">(.*?)</p>.*?data-tex="([^"]*)"', text, flags=re.S
    )
    return [(html.unescape(a), html.unescape(b), html.unescape(c)) for a, b, c in found]


@pytest.mark.parametrize("scene", ALL)
def test_the_word_hamiltonian_names_only_h_of_the_momenta(client, scene):
    text = page(client, scene)
    shown = steps_of(text)
    assert len(shown) > 10
    for title, explanation, tex in shown:
        tex = tex.removeprefix(r"\begin{aligned}").replace("&", "")
        if tex.startswith(r"h = \sum_k p_k"):
            assert "Hamiltonian" not in title and title == "Energy function h"
            assert not explanation.startswith("The Hamiltonian")
        if "Hamiltonian" in title:
            assert tex.startswith("H =")
    prose = words(text)
    assert "the Hamiltonian is conserved" not in prose and "level sets of the Hamiltonian" not in prose


# words about the program, not the mechanics: none belongs in what a student reads
PROGRAM_WORDS = [r"\bengine\b", r"\bserver\b", r"SymPy", r"[Cc]ompiled", r"singular", r"\b\d+(?:\.\d+)?e[+-]?\d+\b",
                 r"q_exact", r"orbit\(s\)", r"time budget", r"Marked:", r"right-hand-side evaluations"]  # fmt: skip


def read_by_a_student(text: str) -> str:
    """All the page's words and formulas' text, the folded steps too ("Show all steps" only unfolds them)."""
    return words(re.sub(r"<math\b.*?</math>", lambda m: re.sub(r"<[^>]+>", "", m.group(0)), text, flags=re.S))


@pytest.mark.parametrize("scene", ALL)
def test_no_program_words_in_what_a_student_reads(client, scene):
    text = read_by_a_student(page(client, scene))
    found = [(w, text[max(0, m.start() - 40) : m.end() + 20]) for w in PROGRAM_WORDS for m in re.finditer(w, text)]
    assert found == []


def test_the_browsers_sentences_say_no_program_words(client):
    for module in ("simulation", "plots", "reduction", "action"):
        source = client.get(f"/static/js/{module}.js").text
        # the strings a page writes, without the comments about the code
        said = re.sub(r"/\*.*?\*/|^\s*//.*$|\s//[^`\"']*$", "", source, flags=re.S | re.M)
        for phrase in ("the engine", "server's more accurate", "server's run follows", "q_exact",
                       "right-hand-side evaluations"):  # fmt: skip
            assert phrase not in said, (module, phrase)


START = {"theta": 1.0, "theta_dot": 0.0}


def test_methods_and_tolerances_have_readable_labels_and_keep_the_apis_values(client):
    text = page(client, "double-pendulum")
    menu = re.search(r'<select id="ctl-method".*?</select>', text, flags=re.S)
    assert menu is not None
    options = dict(re.findall(r'<option value="([^"]+)"[^>]*>([^<]+)</option>', menu.group(0)))
    assert options["Vern8"] == "Verner 8(7)" and options["Radau-compiled"] == "Radau IIA, implicit"
    assert options["auto"] == "automatic choice" and "compiled" not in " ".join(options.values())
    tolerances = re.search(r'<select id="ctl-rtol".*?</select>', text, flags=re.S)
    assert tolerances is not None
    assert '<option value="1e-8" selected>10⁻⁸</option>' in tolerances.group(0).replace("\n", "")
    # the API still takes the names
    run = client.post(
        "/api/scenes/simple-pendulum/simulate", json={"initial": START, "method": "Radau-compiled", "rtol": 1e-6}
    )
    assert run.status_code == 200


def test_autos_reason_is_one_sentence_without_nested_brackets(client):
    stats = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": START}).json()["stats"]
    reason = stats["reason"]
    assert "engine" not in reason and "compiled" not in reason and "among ours" not in reason
    depth = deepest = 0
    for c in reason:
        depth += {"(": 1, ")": -1}.get(c, 0)
        deepest = max(deepest, depth)
    assert deepest <= 1, reason


@pytest.mark.parametrize(
    "scene", ["helix-bead", "incline-block", "tabletop-spring", "spherical-pendulum", "simple-pendulum"]
)
def test_equilibria_are_one_step(client, scene):
    titles = [t for t, _, _ in steps_of(page(client, scene))]
    equilibria = [t for t in titles if t.startswith("Equilibria")]
    assert equilibria == ["Equilibria"], titles
    if scene in ("tabletop-spring", "spherical-pendulum"):
        # with a momentum held, the reduction's rest points are steady motions, not equilibria
        assert "Steady motions and small oscillations" in titles


def test_one_coordinate_has_no_mode_shape_and_an_unstable_point_runs_away(client):
    shown = steps_of(page(client, "simple-pendulum"))
    modes = [(t, e, x) for t, e, x in shown if "about θ" in t]
    assert [t for t, _, _ in modes] == ["Small oscillations about θ = 0", "No oscillation about θ = π"]
    for _, _, tex in modes:
        assert "shape" not in tex and r"\begin{matrix}" not in tex and "K =" not in tex
    top = modes[1][2]
    assert r"\text{(no oscillation: it runs away)}" in top and r"\text{rate } \sqrt{-\omega^2}" in top
    # 3.132 s⁻¹ = √(9.81 m/s² / 1 m), four figures, labelled as the defaults' value
    assert r"\approx 3.132\,\mathrm{s}^{-1}\quad \text{at the defaults}" in top
    assert modes[0][1] != modes[1][1]
    # numbers in a symbolic step say they are at the defaults
    bottom = modes[0][2]
    assert r"\approx 9.81\,\mathrm{s}^{-2}\quad \text{at the defaults}" in bottom


def test_the_damped_exponents_are_defined_with_a_unit_and_four_figures(client):
    shown = {t: x for t, _, x in steps_of(page(client, "damped-pendulum"))}
    bottom = shown["Small motions about θ = 0"]
    # prof-h 10: the exponent, a root of the auxiliary equation, is never r, which names the position r⃗, nor s,
    # the unit beside it (prof-g 60), nor λ, the string's multiplier λ₁ on this page: σ, as the Symbols table says
    assert r"\eta \propto e^{\sigma t}:\quad \sigma^2 + 2\beta \sigma + \omega_0^2 &= 0" in bottom
    assert r"\sigma &= -0.15 \pm 3.128\,i\,\mathrm{s}^{-1}" in bottom and "e^{r t}" not in bottom and "e^{s t}" not in bottom
    assert "3.1285" not in bottom
    assert r"\sigma &= -3.286,\; 2.986\,\mathrm{s}^{-1}" in shown["No oscillation about θ = π"]
    table, _ = symbols_table(page(client, "damped-pendulum"))
    assert "rate in one of the exponentials that make up a small motion" in table and "e^(" not in table


def test_the_damped_roots_are_a_formula_with_the_critical_damping_and_the_energy_decay(client):
    # prof-g 61: σ = −β ± √(β² − ω₀²) with β = b/(2mR²), ω₀² = g/R, b_c = 2mR²√(g/R), E ∝ e^{−2βt}
    bottom = {t: x for t, _, x in steps_of(page(client, "damped-pendulum"))}["Small motions about θ = 0"]
    assert r"\beta = \frac{b}{2 m R^{2}},\quad \omega_0^2 = \frac{g}{R}" in bottom
    assert r"\sigma = -\beta \pm \sqrt{\beta^2 - \omega_0^2}" in bottom
    # the critical value, 2 · 1 kg · (1 m)² · √(9.81 s⁻²) = 6.264 kg·m²/s, the b slider's own mark
    assert r"b_\text{c} = 2 m R^{2} \sqrt{\frac{g}{R}} \approx 6.264\,\mathrm{kg\,m^{2}\,s^{-1}}" in bottom
    # prof-k 9: the energy decays so only averaged over a swing and only for light damping
    assert (
        r"\langle E \rangle \propto e^{-2\beta t},\quad 2\beta &= \frac{b}{m R^{2}}"
        r"\quad (\text{averaged over a swing, for } \beta \ll \omega_0)"
    ) in bottom


def test_about_the_top_the_damped_equation_has_a_negative_stiffness_and_a_growth_rate(client):
    # prof-h 10: a squared frequency cannot be negative; about θ = π a textbook writes η̈ + 2βη̇ − (g/R)η = 0
    text = page(client, "damped-pendulum")
    top = {t: x for t, _, x in steps_of(text)}["No oscillation about θ = π"]
    assert r"\ddot{\eta} + 2\beta\,\dot{\eta} - \frac{g}{R}\,\eta &= 0" in top
    assert "omega_0" not in top and "-9.81" not in text and "−9.81" not in text
    assert r"\sigma = -\beta \pm \sqrt{\beta^2 + \frac{g}{R}}" in top
    # the growth rate −0.15 + √(0.15² + 9.81) = 2.986 s⁻¹, the positive root the exponents' row lists
    assert r"\text{growth rate } \sigma_+ &= -\beta + \sqrt{\beta^2 + \frac{g}{R}} \approx 2.986\,\mathrm{s}^{-1}" in top
    why = {t: e for t, e, _ in steps_of(text)}["No oscillation about θ = π"]
    assert "σ₊ ≈ 2.986 s⁻¹" in why and "unstable equilibrium" in why


def test_a_steady_motion_heading_has_four_figures_and_a_unit(client):
    titles = [t for t, _, _ in steps_of(page(client, "tabletop-spring"))]
    assert "Small oscillations about the steady motion at r = 0.7071 m" in titles
    titles = [t for t, _, _ in steps_of(page(client, "spherical-pendulum"))]
    # θ measured from above, also given from below (prof-g 27)
    assert "Small oscillations about the steady motion at θ = 2.486 rad (π − θ = 0.6556 rad from the downward vertical)" in titles


def test_a_rest_point_with_a_momentum_held_is_a_steady_motion_and_the_momentum_has_its_unit(client):
    # prof-h 13: the tabletop's circular orbit was called "Equilibrium at r₀⁴ = …" and its p_θ = 1 had no unit
    text = page(client, "tabletop-spring")
    results = text[text.index("<dt>Effective potential</dt>") : text.index("</dd>", text.index("<dt>Effective potential</dt>"))]
    assert "Steady motion at" in results and "Equilibrium at" not in results
    shown = {t: x for t, _, x in steps_of(text)}["Small oscillations about the steady motion at r = 0.7071 m"]
    assert r"p_{\theta} = 1\,\mathrm{kg\,m^{2}\,s^{-1}}" in shown
    # with no momentum held, a rest point stays an equilibrium (the rotating parabola's ρ = 0)
    plain = page(client, "rotating-parabola")
    start = plain.index("<dt>Effective potential</dt>")
    rest = plain[start : plain.index("</dd>", start)]
    assert "Equilibrium at" in rest and "Steady motion at" not in rest


def test_the_coordinates_failing_at_a_pole_is_said_and_phi_is_not_listed_there(client):
    shown = {t: x for t, _, x in steps_of(page(client, "spherical-pendulum"))}
    eq = shown["Equilibria"]
    assert r"\theta &= \pi:\quad \text{stable},\quad \omega^2 = \frac{g}{R} \\ &(\text{a minimum of } U" in eq
    assert r"&(\text{the coordinates fail: } \varphi \text{ has no value})" in eq
    assert r"\varphi = 0" not in eq and "singular" not in eq
    mass = {t: x for t, _, x in steps_of(page(client, "simple-pendulum"))}["The equations in matrix form"]
    assert r"\begin{matrix}" not in mass and r"\left[" not in mass


def test_a_further_example_is_headed_as_a_textbook_heads_it(client):
    header = page(client, "double-pendulum").split('class="section-tag">')[1].split("<")[0]
    assert header.startswith("Further example, extending section") and "our example" not in header


def test_nothing_conserved_names_the_cause_that_applies(client):
    damped = words(page(client, "damped-pendulum"))
    assert (
        "Nothing is conserved here: a generalized force that no potential describes acts on θ and does work, so h changes"
        in damped
    )
    assert " or L depends on time" not in damped


@pytest.mark.parametrize("scene", ["rail-two-body", "pulley", "double-pendulum", "simple-pendulum"])
def test_the_mass_matrix_has_one_letter_on_every_page(client, scene):
    doc = client.get(f"/api/scenes/{scene}/derivation").json()
    mass = next(r for r in doc["notation"] if r["meaning"].startswith("mass matrix"))
    assert (mass["latex"], mass["unicode"]) == (r"\mathcal{M}", "ℳ")
    shown = {t: x for t, _, x in steps_of(page(client, scene))}
    assert shown["The equations in matrix form"].removeprefix(r"\begin{aligned}").startswith(r"\mathcal{M} &= ")
    # the rail's errata may write M for the total mass: M is never the mass matrix
    for erratum in doc["errata"]:
        assert r"\mathcal{M}" not in erratum.get("correct_latex", "")


def test_the_potential_energys_sentence_is_true_of_a_driven_support_and_nothing_conserved_names_time(client):
    from app.engine.document.model import Document
    from app.viz.page_model import nothing_conserved

    driven = {
        "coordinates": ["theta"],
        "parameters": ["m", "g", "l", "a", "w"],
        "kinetic": "m*(l**2*theta_dot**2 + a**2*w**2*sin(w*t)**2 - 2*a*w*l*sin(w*t)*sin(theta)*theta_dot)/2",
        "potential": "m*g*(a*cos(w*t) - l*cos(theta))",
    }
    served = client.post("/api/derive", json=driven)
    assert served.status_code == 200, served.text
    doc = served.json()
    potential = next(s for s in doc["steps"] if s["key"] == "potential")
    assert "positions only" not in potential["explanation"] and "explicitly, on the time t" in potential["explanation"]
    assert doc["conserved"] == []
    assert nothing_conserved(Document.model_validate(doc)) == (
        "Nothing is conserved here: L depends explicitly on time (∂L/∂t ≠ 0), so h changes, and no momentum stays constant."
    )


def test_words_a_professor_flagged_read_as_a_textbook_does(client):
    # prof-g 43: a reciprocal unit is a negative power ("0.8155 m⁻¹", never "0.8155 1/m")
    parabola = page(client, "rotating-parabola")
    assert re.search(r"The slider marks [^<]*\d m⁻¹ \(", parabola) and not re.search(r"\d 1/m", parabola)
    # prof-g 40, 41: ρ is signed; U_eff has one name (no V beside it)
    assert "signed distance of the bead from the axis" in parabola and "V = −L" not in parabola
    # prof-g 15: the winding adds inertia, not weight (no "diluted" or "shared" weight beside step 5)
    helix = page(client, "helix-bead")
    assert "diluted" not in helix and "shared between" not in helix and "inertia, not weight" in helix
    # prof-g 34, 33: λ is itself the tension; 2 metres, not "2 m" on a page of masses
    pulley = html.unescape(page(client, "pulley"))
    assert "λ itself is the tension: the string's upward pull" in pulley and "λ times ∂𝒞" not in pulley
    # the string's constant is a named length now (c), with the heights' letters the formula prints (ζ)
    assert "ζ₁ + ζ₂ + 2ζ₃ = −2c, the constant c placing M" in pulley and "constant 2 m " not in pulley
