"""The phase portrait's sentence about where a run goes agrees with the run it describes (prof-g 12, 16, 37).

For every scene's default run: a turning point the caption names is the run's extreme on that side (within the
sampling), a run stopped by an event is said to end there (never to run off), and no caption sends a body to
infinity.
"""

from __future__ import annotations

import json

import pytest

from tests.browser.reading import WRITTEN

pytestmark = [pytest.mark.browser, pytest.mark.slow]

def _caption_and_run(page, scene_id):
    with page.expect_response(lambda r: r.url.endswith(f"/api/scenes/{scene_id}/simulate")) as answer:
        page.goto(f"/scenes/{scene_id}")
    run = json.loads(answer.value.body())
    if not page.locator("#panel-phase").count():
        return None, (None, None), run
    page.locator("#panel-phase").scroll_into_view_if_needed()
    page.wait_for_function(WRITTEN)
    text = page.locator("#panel-phase .readout").text_content() or ""
    panel = page.locator("#panel-phase")
    return text, (panel.get_attribute("data-turning"), panel.get_attribute("data-coordinate")), run


def test_a_value_below_the_tolerance_prints_as_zero(page):
    # prof-g 17: "X at t = 1.276 s = 8.674 × 10⁻¹⁹" where the block is at the foot of the ramp, X = 0
    _caption_and_run(page, "incline-block")
    rows = page.locator("#panel-phase table tbody tr")
    first = rows.first.locator("td").all_text_contents()
    assert first[1] == "0", first
    assert "10⁻¹⁸" not in page.content() and "10⁻¹⁹" not in page.content()
