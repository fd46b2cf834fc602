"""The phase portrait's sentence about where a run goes agrees with the run it describes (prof-g 12, 16, 37).

For every scene's default run: a turning point the caption names is the run's extreme on that side (within the
sampling), a run stopped by an event is said to end there (never to run off), and no caption sends a body to
infinity.
"""

from __future__ import annotations

import json
import re

import pytest

from app.scenes import SCENES

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# the caption is written (level sets of one coordinate, or the projection of several)
WRITTEN = "document.querySelector('#panel-phase .readout')?.textContent.includes('against its rate')"
NUMBER = r"(−?[\d.]+(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)"


def _number(text: str) -> float:
    if "×" in text:
        mantissa, power = text.split(" × 10")
        digits = power.replace("⁻", "-").translate(str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789"))
        return float(mantissa.replace("−", "-")) * 10 ** int(digits)
    return float(text.replace("−", "-"))


def _extreme(t: list[float], x: list[float], highest: bool) -> float:
    """The run's extreme on one side: the vertex of the parabola through the extreme sample and its neighbours."""
    sign = 1 if highest else -1
    k = max(range(len(x)), key=lambda i: sign * x[i])
    if 0 < k < len(x) - 1:
        a, b, c = x[k - 1], x[k], x[k + 1]
        curve = a - 2 * b + c
        if curve != 0:
            return b - (c - a) ** 2 / (8 * curve)
    return x[k]


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


@pytest.mark.parametrize("scene_id", list(SCENES))
def test_the_caption_tells_where_the_default_run_goes(page, scene_id):
    text, (turning, coordinate), run = _caption_and_run(page, scene_id)
    if text is None:
        pytest.skip(f"{scene_id} has no phase portrait")
    assert "infinity" not in text, text
    event = run["stats"]["event"]
    if event is not None:
        # a run stopped by its event ends there: the caption says when, and sends nothing off without bound
        assert "the run ends at t = " in text and "without bound" not in text, text
    named = re.search(r"it turns at (\S+) = " + NUMBER, text)
    if named:
        x_t = float(turning or "nan")
        assert abs(_number(named.group(2)) - x_t) <= 5e-4 * abs(x_t), (named.group(0), x_t)
        # the turning point is where the run's coordinate has its extreme on that side
        x = run["state"][coordinate]
        hi, lo = _extreme(run["t"], x, True), _extreme(run["t"], x, False)
        assert min(abs(hi - x_t), abs(lo - x_t)) <= 2e-3 * max(abs(x_t), hi - lo), (text, x_t, hi, lo)


def test_a_value_below_the_tolerance_prints_as_zero(page):
    # prof-g 17: "X at t = 1.276 s = 8.674 × 10⁻¹⁹" where the block is at the foot of the ramp, X = 0
    _caption_and_run(page, "incline-block")
    rows = page.locator("#panel-phase table tbody tr")
    first = rows.first.locator("td").all_text_contents()
    assert first[1] == "0", first
    assert "10⁻¹⁸" not in page.content() and "10⁻¹⁹" not in page.content()
