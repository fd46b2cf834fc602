"""The phase portrait's words: a steady motion is not called an equilibrium, and the top of a swing is at π."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.browser

LEVELS = "document.querySelector('#panel-phase')?.dataset.xrange"


def _readout(page, scene_id):
    page.goto(f"/scenes/{scene_id}")
    page.locator("#panel-phase").scroll_into_view_if_needed()
    page.wait_for_function(LEVELS)
    return page.locator("#panel-phase .readout").text_content()


def test_a_circular_orbit_is_a_steady_motion(page):
    # prof-a A10: "Equilibria in view: r = 0.7071 (stable)" while the page says no rest position but the anchor
    text = _readout(page, "tabletop-spring")
    assert "Equilibria" not in text
    assert "Steady motions in view (rest points of the reduced problem in r" in text and "r = 0.7071 m (stable)" in text


def test_the_top_is_at_pi_inside_the_wrapped_interval(page):
    # prof-a A10: "θ = −3.142 (unstable)" beside "angles are wrapped into (−π, π]"
    text = _readout(page, "simple-pendulum")
    assert "Equilibria in view: θ = π (unstable), θ = 0 (stable)." in text and "3.142" not in text


def test_a_damped_run_names_only_the_level_it_starts_on(page):
    # prof-c 5: "Its level H = 9.116 J lies below the separatrix" for a run that crosses the level sets
    text = _readout(page, "damped-pendulum")
    assert "It starts on the level h = " in text and "below the separatrix" in text
    assert "Its level" not in text and "swings back and forth" not in text
    # the undamped pendulum keeps its level
    assert "Its level h = " in _readout(page, "simple-pendulum")


def _small_oscillations(page, scene_id):
    page.goto(f"/scenes/{scene_id}")
    page.locator("#panel-small-oscillations").scroll_into_view_if_needed()
    page.wait_for_function("document.querySelector('#panel-small-oscillations .readout')?.textContent.includes('measured')")
    return page.locator("#panel-small-oscillations .readout").text_content()


def test_the_tabletop_frequency_is_said_to_be_exact_at_every_amplitude(page):
    # prof-c 30: 2√(k/m) is exact for the isotropic oscillator, not a limit as the amplitude goes to zero
    text = _small_oscillations(page, "tabletop-spring")
    assert "exact at every amplitude" in text and "goes to zero" not in text
    # prof-e 21: "at amplitude 0.2929 m" was the start's distance from r₀; the swing is not symmetric about it
    assert "amplitude 0." not in text and "from r = 1 m, which swings between r = 0.5 and 1 m" in text
    assert "holds as the amplitude goes to zero" in _small_oscillations(page, "simple-pendulum")


def test_one_cyclic_coordinate_is_singular_and_every_value_has_its_unit(page):
    # prof-e 5: "The other coordinates are cyclic: their momenta stay at p_θ = 1" and "r = 0.7071 (stable)"
    text = _readout(page, "tabletop-spring")
    # p_θ is set as p<sub>θ</sub> (static/js/prose.js): its text reads pθ
    assert "The other coordinate is cyclic: its momentum stays at pθ = 1 kg·m²/s" in text
    assert "coordinates are cyclic" not in text and "r = 0.7071 m (stable)" in text
    # prof-e 5: "θ = 2.486 (stable)" and "p_φ = 1.307" on the spherical pendulum
    text = _readout(page, "spherical-pendulum")
    assert "pφ = 1.307 kg·m²/s" in text and "θ = 2.486 rad (stable)" in text


def test_a_portrait_without_equilibria_says_it_has_none(page):
    # prof-e 5: the caption promises dots and a separatrix that the helix and incline portraits do not have
    for scene_id in ("helix-bead", "incline-block"):
        text = _readout(page, scene_id)
        assert "No equilibrium lies in view, so there are no dots and no separatrix." in text, scene_id


def test_an_unbounded_run_is_not_said_to_swing(page):
    # prof-f 16: at ω = 6 rad/s (ω² > 2gα) U = (gα − ω²/2) m ρ² has its only maximum at ρ = 0, where h = 0;
    # the bead starts beyond it and runs off, which the caption said "swings back and forth" beside a
    # sampled separatrix of −2.406 × 10⁻⁴ J
    page.goto("/scenes/rotating-parabola")
    page.locator("#panel-phase").scroll_into_view_if_needed()
    page.wait_for_function(LEVELS)
    page.fill("#ctl-omega", "6")
    page.press("#ctl-omega", "Enter")
    page.wait_for_function("document.querySelector('#panel-phase .readout').textContent.includes('separatrix')")
    text = page.locator("#panel-phase .readout").text_content()
    # and runs outward until it leaves the wire at its end (prof-m 8: the wire is finite, the run ends there)
    assert "below the separatrix (0 J)" in text and "infinity" not in text
    assert "the run ends at t = 0.8349 s: the bead reached the end of the wire" in text
    assert "swings back and forth" not in text
    assert page.locator("#panel-phase").get_attribute("data-separatrix") == "0"


def test_the_parabola_default_swing_is_small_enough_for_the_prediction(page):
    # prof-f 17: from ρ = 0.5 m (4α²ρ² = 1) the panel showed the measurement 18 % below the small-oscillation Ω
    import re

    text = _small_oscillations(page, "rotating-parabola")
    (percent,) = re.findall(r"\(([−+-]?[\d.]+) %\)", text)
    assert abs(float(percent.replace("−", "-"))) <= 3, text
