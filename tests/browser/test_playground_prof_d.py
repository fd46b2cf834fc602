"""The playground in headless Chromium as a professor read it (issue 40, part D): what the page draws."""

from __future__ import annotations

from urllib.parse import urlencode

import pytest

from app.web.api.examples_user import FORCED_SPRING
from app.web.pages.playground_form import form_of, query_of
from tests.web.pages.test_playground_prof_d import MAGNETIC

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'


def address(spec) -> str:
    return "/playground?" + urlencode({**query_of(form_of(spec)), "stage": "whole"}, doseq=True)


def test_a_system_given_by_l_alone_draws_h_and_no_energy_e(page, artifacts):
    page.goto(address(MAGNETIC))
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    page.wait_for_selector(".energy-bars[data-ready=true]", state="attached")
    # E = T + U is not defined where T and U cannot be told apart: one bar, h
    assert page.eval_on_selector_all(".energy-bars .ebar", "rows => rows.map((r) => r.dataset.key)") == ["h"]
    plot = page.locator("[data-panel=energy] .plot")
    page.wait_for_function("(el) => el.data && el.data.length > 0", arg=plot.element_handle())
    names = page.evaluate("(el) => el.data.map((t) => t.name)", plot.element_handle())
    assert "h" in names and not any(n.startswith("E") for n in names)
    assert "E = T + U is not defined here" in page.inner_text("[data-panel=energy]")
    # the conserved momenta panel follows the angular momentum of the rotation
    # J_z is set as J<sub>z</sub> (static/js/prose.js): its text reads Jz
    assert "Jz stays at" in page.inner_text("[data-panel=momenta]")
    # one notice that there is no picture, not two
    assert not page.locator("[data-panel^=animation] canvas.mechanism").first.is_visible()
    assert page.get_by_text("No picture").count() == 1
    page.screenshot(path=artifacts / "playground-magnetic.png", full_page=True)
    assert page.console_errors == []


def test_on_a_phone_every_cell_of_the_form_reads_back_whole(browser, live_server, artifacts):
    context = browser.new_context(base_url=live_server, viewport={"width": 390, "height": 844})
    page = context.new_page()
    page.goto(address(FORCED_SPRING))
    cut = page.eval_on_selector_all(
        "#parameter-rows input, #force-rows input",
        "els => els.filter((i) => i.value && i.scrollWidth > i.clientWidth).map((i) => i.value)",
    )
    assert cut == []
    page.screenshot(path=artifacts / "playground-phone-form.png", full_page=True)
    context.close()


def test_a_driven_pendulum_draws_no_level_sets_of_h(page):
    # prof-f: L depends on time, yet the phase portrait drew level sets of h, a separatrix and
    # "it swings back and forth"; h changes along the run, so no orbit follows a level set
    from tests.web.pages.test_playground_prof_d import DRIVEN

    page.goto(address(DRIVEN))
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    page.locator("#panel-phase").scroll_into_view_if_needed()
    plot = page.locator("#panel-phase .plot")
    page.wait_for_function("(el) => el.data && el.data.length > 0", arg=plot.element_handle())
    names = page.evaluate("(el) => el.data.map((t) => t.name)", plot.element_handle())
    assert names == ["this run"]
    text = page.inner_text("#panel-phase .readout")
    assert "L depends explicitly on time (∂L/∂t ≠ 0), so h is not conserved" in text
    assert "separatrix" not in text and "swings back and forth" not in text
    assert page.console_errors == []
