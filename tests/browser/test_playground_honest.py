"""The playground's Kepler problem with θ̇(0) = 0 (a radial fall): units per coordinate, and no null, NaN or
undefined shown anywhere, before or after the initial rate is set."""

from __future__ import annotations

import re
from urllib.parse import urlencode

import pytest

pytestmark = pytest.mark.browser

NOISE = re.compile(r"\b(null|NaN|undefined)\b")
KEPLER = {
    "q": "r, theta",
    "form": "energies",
    "pn": ["m", "k"],
    "pv": ["1", "1"],
    "pu": ["kg", "N*m**2"],
    "T": "m/2*(r_dot**2 + r**2*theta_dot**2)",
    "U": "-k/r",
    "nn": "r",
}
DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"], #run-status[data-state="error"]'


@pytest.mark.parametrize("size", [(1366, 768), (390, 844)])
def test_kepler_radial_fall_shows_units_and_no_raw_values(browser, live_server, artifacts, size):
    context = browser.new_context(base_url=live_server, viewport={"width": size[0], "height": size[1]})
    page = context.new_page()
    page.set_default_timeout(90_000)
    page.goto("/playground?" + urlencode(KEPLER, doseq=True))
    page.wait_for_selector(DONE, state="attached")
    assert page.inner_text("#ctl-theta-unit") == "rad"
    assert page.inner_text("#ctl-theta_dot-unit") == "rad/s"
    assert page.inner_text("#ctl-r-unit") == "m"
    runs = int(page.get_attribute("#simulation", "data-runs") or 0)
    page.fill("#ctl-theta_dot", "0")
    page.wait_for_function(
        f"Number(document.getElementById('simulation').dataset.runs || 0) > {runs} || document.getElementById('run-status').dataset.state === 'error'"
    )
    page.wait_for_selector(DONE, state="attached")
    page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
    page.wait_for_timeout(1500)
    text = page.inner_text("main")
    found = NOISE.search(text)
    assert not found, text[max(0, found.start() - 200) : found.end() + 100]
    assert "m/s" not in page.inner_text("label[for=ctl-theta_dot-range]")
    page.screenshot(path=artifacts / f"playground-kepler-{size[0]}.png", full_page=True)
    context.close()
