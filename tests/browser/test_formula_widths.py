"""No typeset formula wider than its box on the playground's double pendulum with every step shown, at 1366×768
(nothing may overflow) and 390×844 with touch (a formula is broken where it can, and may only be wider than its
box inside a box that scrolls, that the keyboard can reach and that shows it goes on).  Every scene page:
test_scene_read.py."""

from __future__ import annotations

from urllib.parse import urlencode

import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from tests.browser.reading import CUES_SETTLED, TYPESET, WIDTHS, width_problems

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# a user's double pendulum typed as two particles (the playground's shareable address)
PLAYGROUND_DOUBLE_PENDULUM = "/playground?" + urlencode(
    {
        "q": "theta1, theta2",
        "form": "particles",
        "pn": ["m1", "m2", "l1", "l2", "g"],
        "pv": ["1", "1", "1", "1", "9.81"],
        "m": ["m1", "m2"],
        "x": ["l1*sin(theta1)", "l1*sin(theta1) + l2*sin(theta2)"],
        "y": ["0", "0"],
        "z": ["-l1*cos(theta1)", "-l1*cos(theta1) - l2*cos(theta2)"],
        "U": "-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)",
    },
    doseq=True,
)


@pytest.mark.parametrize("width, height, phone", [(1366, 768, False), (390, 844, True)])
def test_no_formula_wider_than_its_box_on_the_playground(browser, live_server, artifacts, width, height, phone):
    context = browser.new_context(
        base_url=live_server, viewport={"width": width, "height": height}, has_touch=phone, is_mobile=phone
    )
    page = context.new_page()
    page.set_default_timeout(120_000)
    try:
        page.goto(PLAYGROUND_DOUBLE_PENDULUM)
        page.wait_for_selector(TYPESET, state="attached", timeout=120_000)
        page.wait_for_selector("#derivation .math-display .katex", state="attached", timeout=120_000)
        assert page.locator(".katex-error").count() == 0
        # the scroll cues are set at the frame after a box's layout changes (fonts loading, formulas broken):
        # measured once they agree with the boxes, or after 15 s as they are (the assertions then say which)
        try:
            page.wait_for_function(CUES_SETTLED, timeout=15_000)
        except PlaywrightTimeout:
            pass
        assert (problems := width_problems(page.evaluate(WIDTHS), phone)) == [], problems[:5]
        page.screenshot(path=artifacts / f"widths-playground-{width}.png")
    finally:
        context.close()
