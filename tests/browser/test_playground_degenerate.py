"""At a degenerate equilibrium (U_eff″ = 0) the small-oscillations panel decides by the first derivative that does
not vanish (prof-g 54): the spinning hoop at R w² = g has a quartic minimum at θ = 0, stable with no frequency."""

from __future__ import annotations

from urllib.parse import urlencode

import pytest

from app.web.examples_user import SPINNING_HOOP
from app.web.playground_form import form_of, query_of

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# R w² = g exactly: U_eff = −m g R (1 − θ⁴/8 + …) about θ = 0 with m = R = g = w = 1
AT_THE_BIFURCATION = {
    **SPINNING_HOOP,
    "parameters": [{**p, "value": 1.0} for p in SPINNING_HOOP["parameters"]],  # type: ignore[dict-item]
}


def test_a_quartic_minimum_is_stable_with_no_small_oscillation_frequency(page):
    query = urlencode({**query_of(form_of(AT_THE_BIFURCATION)), "stage": "whole"}, doseq=True)
    # the page derives the system on the server before it answers: minutes on a busy machine
    page.set_default_timeout(300_000)
    page.goto(f"/playground?{query}")
    panel = page.locator("#panel-small-oscillations")
    panel.scroll_into_view_if_needed()
    page.wait_for_function("document.querySelector('#panel-small-oscillations .readout')?.textContent.includes('θ')")
    text = panel.locator(".readout").text_content() or ""
    assert "No stable equilibrium" not in text, text
    assert "U_eff″ = 0 there, so there is no small-oscillation frequency" in text and "fourth power" in text
    assert "the equilibrium is stable" in text
