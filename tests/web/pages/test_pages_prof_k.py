"""What prof-k's review found in the words a student reads (issue 40), pinned by what the pages and the API serve:
the string's pull along ∇𝒞, the tabletop's exact frequency (not its waveform), ξ, η, ζ said where they first
appear, the small-angle approximation written with ≈, the energy's decay with its conditions, plain words for the
folded panels and the action panel, the practice's axes in words, and the contents page's sections."""

from __future__ import annotations

import html
import json
import re

import pytest

from tests.web.pages.test_page_shared_text import steps_of, words


@pytest.fixture(scope="module")
def pages(client):
    ids = ("simple-pendulum", "spherical-pendulum", "helix-bead", "pulley", "tabletop-spring", "damped-pendulum")
    return {s: client.get(f"/scenes/{s}").text for s in ids}


def _explanation(page: str, title: str) -> str:
    """A step's explanation as a reader sees it (subscripts written as plain letters)."""
    said = [e for t, e, _ in steps_of(page) if t == title]
    assert said, title
    return words(said[0])


def test_the_string_pulls_along_grad_c_toward_the_pivot(pages):
    # prof-k 2: 2(x, y, z) points from the pivot to the ball; the force is λ∇𝒞 with ∇𝒞 = −2(x, y, z), λ > 0 taut
    spherical = _explanation(pages["spherical-pendulum"], "Lagrangian with the multipliers")
    assert (
        "∇𝒞 = −2(x, y, z) points from the ball to the pivot" in spherical
        and "λ > 0 while the string is taut" in spherical
    )
    assert "−∇𝒞 = 2(x, y, z), toward the pivot" not in spherical
    simple = _explanation(pages["simple-pendulum"], "Lagrangian with the multipliers")
    assert "∇𝒞 = −2(x, z − R) points from the bob to the pivot" in simple and "−∇𝒞 ∝ (x, z − R)" not in simple
    # the sign the sentences claim is the page's own: λ₁ = (m/2R)(Rθ̇² + g cos θ) > 0 hanging at rest
    assert r"\lambda_{1} = \frac{m}{2 R} \left(R \dot{\theta}^{2} + g \cos {\theta}\right)" in html.unescape(
        pages["simple-pendulum"]
    )


def test_the_tabletop_says_only_the_frequency_is_exact(pages):
    # prof-k 6: the dashed linear curve differs from the simulated r; its frequency 2√(k/m) is what is exact
    data = json.loads(re.search(r'id="scene-data">(.*?)</script>', pages["tabletop-spring"], re.S).group(1))
    said = data["exact_frequency"]
    assert "the frequency is exact at every amplitude" in said and "not a sine wave" in said
    assert "the prediction is exact" not in said


def test_the_cartesian_greek_letters_are_explained_where_they_first_appear(pages):
    # prof-k 7: the helix's 𝒞₁ = −ξ² − η² + R² = 0 came with no word on why x, y, z became ξ, η, ζ
    helix = _explanation(pages["helix-bead"], "Constraints in Cartesian form")
    assert "The Cartesian coordinates are written ξ, η, ζ here, since z already names a coordinate" in helix
    pulley = _explanation(pages["pulley"], "Constraints in Cartesian form")
    assert "ξᵢ, ηᵢ, ζᵢ for body i here, since y₁ and y₂ already name coordinates" in pulley
    # the helix's multipliers step speaks of the same letters, never of an x the page does not print
    solved = _explanation(pages["helix-bead"], "The multipliers solved")
    assert "ξ = R cos αz and η = R sin αz" in solved
    # a scene whose letters are x, y, z says nothing of the kind
    assert "The Cartesian coordinates are written" not in words(pages["spherical-pendulum"])


def test_the_small_angle_equation_is_an_approximation_never_correct(pages):
    # prof-k 8: θ̈ = −(g/R)θ under "Correct" beside the chapter's sin θ
    page = html.unescape(pages["simple-pendulum"])
    errata = page.split('class="errata-details"', 1)[1].split("</details>", 1)[0]
    assert r"\ddot{\theta} \approx - \frac{g}{R} \theta, \quad \text{for } |\theta| \ll 1" in errata
    assert ">Correct<" not in errata and 'data-label="Correct"' not in errata
    assert ">What holds<" in errata


def test_the_energy_decay_says_when_it_holds(pages):
    # prof-k 9: E ∝ e^(−2βt) only on average over a swing and only for β ≪ ω₀
    tex = html.unescape(pages["damped-pendulum"])
    assert r"\langle E \rangle \propto e^{-2\beta t}" in tex
    assert r"(\text{averaged over a swing, for } \beta \ll \omega_0)" in tex
    assert r"E \propto" not in tex


def test_the_panels_speak_plain_words_and_the_focus_families_only_where_there_are_several(pages):
    # prof-k 10: "(every integrator compared …)" and the paragraph on each coordinate's own focus
    simple = words(pages["simple-pendulum"])
    assert "every integrator compared" not in simple
    assert "has a focus of its own" not in simple and "family of variations" not in simple
    spherical = words(pages["spherical-pendulum"])
    assert "Varying one coordinate alone, with the others kept on the true path, has a focus of its own." in spherical
    assert "family of variations" not in spherical


@pytest.mark.slow
def test_the_practice_says_the_axes_and_origin_in_words_the_figure_supports(client):
    # prof-k 14: "Use the figure's axes … and its origin", beside a figure that draws neither
    served = client.get("/api/scenes/simple-pendulum/practice").json()
    notes = {e.get("note", "") for e in served["exercises"] if e.get("note")}
    assert notes and all("figure's axes" not in n for n in notes)
    assert any(
        n.startswith("Measure x across and z up") and "the origin the problem statement names" in n for n in notes
    )


def test_the_contents_page_lists_the_sections_it_has(client):
    # prof-k 15: "sections 4.1 to 4.9" with no 4.8 among them; U_eff'' in ASCII
    served = client.get("/").text
    text = words(served)
    assert "sections 4.1 to 4.7 and 4.9" in text and "4.1 to 4.9" not in text
    # U_eff″ typeset, over the inertia in words (a mass for a length, a moment of inertia for an angle: prof-n 5)
    assert "U_eff''" not in text and "ω² is U<sub>eff</sub>″ over the effective inertia" in served
