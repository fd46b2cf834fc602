"""Keys: an arrow on the canvas moves the body the way it points on screen, in fine steps; a slider's arrow
keys take fine steps and Shift with them coarse ones; tap targets on a phone are at least 24 px."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'
BODY = "JSON.parse(document.querySelector('[data-panel=animation-2d] canvas').dataset.bodies)[0]"


def test_arrows_on_the_canvas_move_the_bob_the_way_they_point(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    canvas = page.locator("[data-panel=animation-2d] canvas")
    canvas.focus()
    start_theta = float(page.input_value("#ctl-theta"))
    start = page.evaluate(BODY)
    for _ in range(3):
        theta = page.input_value("#ctl-theta")
        page.keyboard.press("ArrowLeft")
        page.wait_for_function(f"document.querySelector('#ctl-theta').value !== '{theta}'")
    page.wait_for_function(f"({BODY}).x < {start['x']} - 5")
    after = page.evaluate(BODY)
    assert after["x"] < start["x"]
    # fine steps: three presses move theta(0) by a few hundredths of a radian, not tenths
    moved = abs(float(page.input_value("#ctl-theta")) - start_theta)
    assert 0.005 < moved < 0.15
    # and Right brings it back
    for _ in range(3):
        theta = page.input_value("#ctl-theta")
        page.keyboard.press("ArrowRight")
        page.wait_for_function(f"document.querySelector('#ctl-theta').value !== '{theta}'")
    assert float(page.input_value("#ctl-theta")) == pytest.approx(start_theta, abs=0.02)


def test_slider_arrows_are_fine_and_shift_is_coarse(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    page.focus("#ctl-g-range")
    before = float(page.input_value("#ctl-g-range"))
    page.keyboard.press("ArrowRight")
    fine = float(page.input_value("#ctl-g-range")) - before
    page.keyboard.press("Shift+ArrowRight")
    coarse = float(page.input_value("#ctl-g-range")) - before - fine
    assert fine == 5 and coarse == 50  # of the slider's 1000 positions


def test_tap_targets_on_a_phone_are_at_least_24_px(browser, live_server):
    context = browser.new_context(
        base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    page.goto("/scenes/pulley")
    page.wait_for_selector(READY, state="attached")
    small = page.evaluate(
        """() => [...document.querySelectorAll('main input, main button, main select, main summary')]
             .filter((e) => e.offsetParent !== null && e.type !== 'hidden')
             .map((e) => { const r = e.getBoundingClientRect(); return [e.id || e.className || e.tagName, Math.round(r.width), Math.round(r.height)]; })
             .filter(([, w, h]) => w < 24 || h < 24)"""
    )
    assert small == []
    context.close()
