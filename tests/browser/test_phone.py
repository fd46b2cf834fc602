"""A phone (390×844) in the order a student reads: title, problem statement, animation and controls, set-up
figure with parameters, derivation, then the plots; the statement on the first screen."""

from __future__ import annotations

import pytest

from app.scenes import SCENES

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"], #run-status[data-state="untrusted"]'
ORDER = [
    "h1",
    ".statement",
    "canvas.mechanism",
    "#controls",
    "figure.setup",
    "table.parameters",
    "#derivation",
    ".panels",
]


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


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_a_phone_reads_in_order(browser, live_server, artifacts, scene_id):
    context, page = _phone_page(browser, live_server, scene_id)
    tops = page.evaluate(
        "(sels) => sels.map((s) => { const e = document.querySelector('.scene ' + s); return e ? e.getBoundingClientRect().top + scrollY : null; })",
        ORDER,
    )
    present = [(s, t) for s, t in zip(ORDER, tops, strict=True) if t is not None]
    assert [s for s, _ in sorted(present, key=lambda x: x[1])] == [s for s, _ in present], present
    # the problem statement is on the first screen
    statement = page.locator(".scene .statement").bounding_box()
    assert statement["y"] < 844
    page.screenshot(path=artifacts / f"phone-{scene_id}.png")
    context.close()


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "spherical-pendulum"])
def test_the_energy_panel_fits_a_phone_after_scrolling_through(browser, live_server, scene_id):
    # prof-a D: after scrolling down the page the energy panel grew to 509 px on a 390 px screen
    context, page = _phone_page(browser, live_server, scene_id)
    height = page.evaluate("document.documentElement.scrollHeight")
    for y in range(0, height, 700):  # every lazy panel comes into view and draws
        page.evaluate(f"window.scrollTo(0, {y})")
        page.wait_for_timeout(100)
    page.locator("#panel-energy").scroll_into_view_if_needed()
    page.wait_for_timeout(1500)
    box = page.locator("#panel-energy").bounding_box()
    assert box["x"] >= 0 and box["x"] + box["width"] <= 390, box
    assert page.evaluate("document.documentElement.scrollWidth") <= 390  # the page never scrolls sideways
    context.close()
