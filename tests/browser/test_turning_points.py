"""The effective potential's markers agree with its caption: both turning points are diamonds, the current state a
smaller red dot that never hides one (issue 40, part A)."""

from __future__ import annotations

import json

import pytest

READY = '#run-status[data-state="ready"]'

pytestmark = pytest.mark.browser


def test_both_turning_points_show_as_diamonds_at_a_start_from_rest(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    page.locator("#panel-effective-potential").scroll_into_view_if_needed()
    page.wait_for_function(
        "document.querySelector('#panel-effective-potential .readout').textContent.includes('the motion turns at')"
    )
    caption = page.locator("#panel-effective-potential p").first.text_content() or ""
    assert "turning points (purple diamonds)" in caption and "red dot is the current state" in caption
    panel = page.locator("#panel-effective-potential")
    diamonds = panel.locator("g.turning path")
    assert diamonds.count() == 2
    # the run starts at rest at θ = 1 rad: the red dot sits on the right turning point, inside its diamond
    turning = json.loads(panel.locator("g.turning").get_attribute("data-points") or "[]")
    now = json.loads(panel.locator("g.now").get_attribute("data-points") or "[]")
    assert abs(now[0][0] - max(x for x, _ in turning)) < 1e-6
    dot = panel.locator("g.now circle").bounding_box()
    right = max((diamonds.nth(k).bounding_box() for k in range(2)), key=lambda b: b["x"])
    assert dot is not None and right["width"] > dot["width"] + 4 and right["height"] > dot["height"] + 4
    assert page.console_errors == []
