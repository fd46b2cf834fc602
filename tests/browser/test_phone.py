"""A phone (390×844): the plots sit under the animation, folded to one line each, and unfold in place; the energy
panel fits after scrolling through.  The reading order, the labels and the handle's words are checked on every
scene page by tests/browser/test_scene_read.py."""

from __future__ import annotations

import pytest

from tests.browser.conftest import unfold_panels

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'


def _phone_page(browser, live_server, scene_id: str):
    """A scene page opened at 390×844 with touch, its panels attached."""
    context = browser.new_context(
        base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    page.set_default_timeout(60_000)
    page.goto(f"/scenes/{scene_id}")
    page.wait_for_selector(READY, state="attached")
    return context, page


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "spherical-pendulum"])
def test_the_energy_panel_fits_a_phone_after_scrolling_through(browser, live_server, scene_id):
    # prof-a D: after scrolling down the page the energy panel grew to 509 px on a 390 px screen
    context, page = _phone_page(browser, live_server, scene_id)
    height = page.evaluate("document.documentElement.scrollHeight")
    for y in range(0, height, 700):  # every lazy panel comes into view and draws
        page.evaluate(f"window.scrollTo(0, {y})")
        page.wait_for_timeout(100)
    page.locator("#panel-energy").scroll_into_view_if_needed()
    unfold_panels(page, "#panel-energy")  # it starts folded under the animation
    page.wait_for_timeout(1500)
    box = page.locator("#panel-energy").bounding_box()
    assert box["x"] >= 0 and box["x"] + box["width"] <= 390, box
    assert page.evaluate("document.documentElement.scrollWidth") <= 390  # the page never scrolls sideways
    context.close()


# The first plot panel's distance below the animation's canvas, in CSS pixels at 390×844: before the
# plots moved up (prof-c S10) the Energy panel sat about 14,000 px below it, after the whole derivation.
FIRST_PLOT = """() => {
  const canvas = document.querySelector('.scene canvas.mechanism');
  const panel = document.querySelector('.scene .panels > section.panel');
  return panel.getBoundingClientRect().top - canvas.getBoundingClientRect().bottom;
}"""


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "spherical-pendulum", "damped-pendulum"])
def test_the_plots_sit_under_the_animation_folded_on_a_phone(browser, live_server, artifacts, scene_id):
    # prof-c S10: on a phone the plots came after the derivation, Symbols and Errata, so "the dotted cursor
    # follows the same instant" could not be used; now they follow the animation, each folded to a line
    context, page = _phone_page(browser, live_server, scene_id)
    gap = page.evaluate(FIRST_PLOT)
    print(f"{scene_id}: first plot {gap:.0f} px below the animation")
    assert 0 <= gap < 844, gap  # within one screen of the animation
    panels = page.locator(".scene .panels > section.panel")
    count = panels.count()
    assert count >= 2
    # every panel starts folded: a button in its heading, no plot shown, and all of them together short
    for k in range(count):
        button = panels.nth(k).locator("h3 > button.fold")
        assert button.get_attribute("aria-expanded") == "false"
        assert not panels.nth(k).locator(".plot, .modes-body").first.is_visible()
    first, last = panels.nth(0).bounding_box(), panels.nth(count - 1).bounding_box()
    assert last["y"] + last["height"] - first["y"] < 130 * count, (first, last)
    assert page.locator(".scene .derivation, #derivation").first.bounding_box()["y"] > last["y"]
    # a tap unfolds the energy panel, which then draws its plot at the phone's width
    energy = page.locator("#panel-energy")
    energy.locator("h3 > button.fold").click()
    assert energy.locator("h3 > button.fold").get_attribute("aria-expanded") == "true"
    page.wait_for_selector("#panel-energy .plot .main-svg", timeout=30_000)
    box = energy.locator(".plot").bounding_box()
    assert 200 < box["width"] <= 390 and box["height"] > 150, box
    assert page.locator("#panel-energy .readout").inner_text().strip()
    page.screenshot(path=artifacts / f"phone-plots-{scene_id}.png")
    # a tap folds it again
    energy.locator("h3 > button.fold").click()
    assert not energy.locator(".plot").is_visible()
    context.close()


def test_a_wide_screen_shows_every_panel_unfolded(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    assert page.locator(".panels button.fold").count() == 0
    assert page.locator(".panels > section.panel.folded").count() == 0
