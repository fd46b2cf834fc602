"""The error-against-run-time panel while its report is still being measured: the page says what is happening."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.browser


def test_a_report_still_being_measured_is_explained(page):
    # prof-a D: the panel sat on "Loading the error-against-run-time chart…" while the server measured the report
    held = []
    page.route("**/work-precision", lambda route: held.append(route))  # never answered while the test looks
    page.goto("/scenes/damped-pendulum")
    page.locator("#panel-work-precision").scroll_into_view_if_needed()
    page.wait_for_function(
        "document.querySelector('#panel-work-precision .readout').textContent.includes('being measured on the server')",
        timeout=30_000,
    )
    assert held, "the panel asked for the report"
    text = page.locator("#panel-work-precision .readout").text_content()
    assert "Loading" not in text and "the chart appears here when it is done" in text
