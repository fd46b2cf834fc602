"""Every panel follows the sliders: the modes, the effective potential, the phase portrait and the small
oscillations are computed for the parameters the controls say, never silently at the defaults."""

from __future__ import annotations

import math

import pytest

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'


def settle(page, selector: str, value: str) -> None:
    """Type a value and wait for the server's run at it (the panels that need the server redraw after it)."""
    runs = int(page.get_attribute("#simulation", "data-runs") or 0)
    page.fill(selector, value)
    page.wait_for_function(f"Number(document.getElementById('simulation').dataset.runs) > {runs}")
    page.wait_for_selector(READY, state="attached")


def test_the_modes_follow_the_coupling(page):
    page.goto("/scenes/coupled-oscillators")
    page.wait_for_selector(READY, state="attached")
    page.locator("#panel-modes").scroll_into_view_if_needed()
    # the scene's k = 10 N/m, m = 1 kg: at the default kappa = 1 N/m mode 2 is sqrt(k/m + 2 kappa/m) = sqrt(12)
    page.wait_for_function(
        "/ω = 3.464 rad\\/s/.test(document.querySelector('label[for=panel-modes-mode-1]').textContent)"
    )
    settle(page, "#ctl-kappa", "0.1")
    expected = math.sqrt(10 / 1 + 2 * 0.1 / 1)
    assert f"{expected:.4g}" == "3.194"
    page.wait_for_function(
        "/ω = 3.194 rad\\/s/.test(document.querySelector('label[for=panel-modes-mode-1]').textContent)"
    )
    assert "ω = 3.162 rad/s" in page.inner_text("label[for=panel-modes-mode-0]")
    # the panel names the values it was computed at, and measures at them too
    assert "κ = 0.1 N/m" in page.inner_text("#panel-modes .frequencies caption")
    page.wait_for_function(
        "JSON.parse(document.querySelector('#panel-modes .frequencies').dataset.measured || '[]').some(([p]) => Math.abs(p - 3.1937) < 1e-3)"
    )
    pairs = page.evaluate("JSON.parse(document.querySelector('#panel-modes .frequencies').dataset.measured)")
    assert all(abs(m / p - 1) < 1e-3 for p, m in pairs)
    page.check("#panel-modes-mode-1")
    assert "κ = 0.1 N/m" in page.inner_text("#panel-modes-readout")
    assert "default" not in page.inner_text("#panel-modes")
    assert page.console_errors == []


def test_the_pendulum_panels_follow_gravity(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    settle(page, "#ctl-g", "4.9")
    # U_eff at theta(0) = 1 with the bob at rest: m g R (1 - cos 1), m = R = 1
    level = 4.9 * (1 - math.cos(1.0))
    page.locator("#panel-effective-potential").scroll_into_view_if_needed()
    page.wait_for_function(
        f"document.querySelector('#panel-effective-potential .readout').textContent.includes('Energy level {level:.4g} J')"
    )
    # the separatrix of the phase portrait is the level of the top, 2 m g R
    page.locator("#panel-phase").scroll_into_view_if_needed()
    page.wait_for_function("Math.abs(Number(document.getElementById('panel-phase').dataset.separatrix) - 9.8) < 0.05")
    # small oscillations: omega = sqrt(g / R)
    page.locator("#panel-small-oscillations").scroll_into_view_if_needed()
    omega = math.sqrt(4.9)
    page.wait_for_function(
        f"document.querySelector('#panel-small-oscillations .readout').textContent.includes('predicted ω = {omega:.4g} rad/s')"
    )
    assert page.console_errors == []
