"""Beyond the chapter on the page: the normal-modes animation, the phase portrait's separatrix, Poincaré sections."""

from __future__ import annotations

import math
from urllib.parse import urlencode

import pytest

from app.web.api.examples_user import DOUBLE_PENDULUM
from app.web.pages.playground import form_of, query_of

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'


def painted_events(page) -> None:
    # the phase panel's preview lines as each paint is announced: read in a microtask, after the panels in
    # view have drawn (also in microtasks) and before the server's run can replace the preview
    page.evaluate(
        """window.painted = []; window.lines = {}; document.addEventListener('lagrange:painted', (e) => {
             window.painted.push(e.detail.source);
             queueMicrotask(() => {
               window.lines[e.detail.source] ??= document.querySelector('#panel-phase canvas.plot-preview')?.dataset.lines;
             });
           })"""
    )


def test_modes_animation_runs_and_a_superposition_can_be_chosen(page):
    page.goto("/scenes/coupled-oscillators")
    page.wait_for_selector(READY, state="attached")
    section = page.locator("#panel-modes")
    section.scroll_into_view_if_needed()
    page.wait_for_function("document.getElementById('panel-modes').dataset.playing === 'true'")
    assert section.get_attribute("data-modes") == "1"
    frame = int(section.get_attribute("data-frame"))
    page.wait_for_function(f"Number(document.getElementById('panel-modes').dataset.frame) !== {frame}")
    # mode 1 moves the masses together, so both bodies move the same way
    page.check("#panel-modes-mode-1")
    page.wait_for_function("document.getElementById('panel-modes').dataset.modes === '1,2'")
    before = page.evaluate("document.querySelector('#panel-modes canvas').dataset.bodies")
    page.wait_for_timeout(300)
    assert page.evaluate("document.querySelector('#panel-modes canvas').dataset.bodies") != before
    assert "modes 1,2" in page.inner_text("#panel-modes-readout")
    # predicted against measured, from the server's small-amplitude runs
    page.wait_for_function("document.querySelector('#panel-modes .frequencies').dataset.measured")
    pairs = page.evaluate("JSON.parse(document.querySelector('#panel-modes .frequencies').dataset.measured)")
    assert len(pairs) == 2 and all(abs(m / p - 1) < 0.01 for p, m in pairs)
    page.uncheck("#panel-modes-mode-0")
    page.wait_for_function("document.getElementById('panel-modes').dataset.modes === '2'")
    assert page.console_errors == []


def test_an_over_the_top_pendulum_has_a_separatrix_and_wrapped_angles(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    page.locator("#panel-phase").scroll_into_view_if_needed()
    painted_events(page)
    page.fill("#ctl-theta_dot", "8")
    page.wait_for_function("window.painted.includes('server')")
    page.wait_for_selector(READY, state="attached")
    traces = page.evaluate(
        "document.querySelector('#panel-phase .plot').data.map((t) => ({name: t.name, x: t.x.filter((v) => v !== null)}))"
    )
    by_name = {t["name"]: t["x"] for t in traces}
    assert set(by_name) == {"level sets of h", "separatrix", "this run"}
    assert len(by_name["separatrix"]) > 100
    # the run goes round and round: without wrapping it would reach tens of radians
    run = by_name["this run"]
    assert max(map(abs, run)) <= math.pi + 1e-9 and max(run) - min(run) > 6
    # the separatrix is the level of the top: h = 2 m g R at the defaults
    assert float(page.get_attribute("#panel-phase", "data-separatrix")) == pytest.approx(2 * 9.81, rel=0.01)
    assert "above the separatrix" in page.inner_text("#panel-phase .readout")
    # a live preview redraws it at once (lines over the plot), before the server's run
    painted_events(page)
    page.fill("#ctl-theta_dot", "3")
    page.wait_for_function("window.painted.includes('preview')")
    assert page.evaluate("window.lines.preview") == "3"
    page.wait_for_function("window.painted.includes('server')")
    page.wait_for_function("/below the separatrix/.test(document.querySelector('#panel-phase .readout').textContent)")
    assert page.console_errors == []


@pytest.mark.parametrize(
    "path",
    ["/scenes/double-pendulum", "/playground?" + urlencode(query_of(form_of(DOUBLE_PENDULUM)), doseq=True)],
)
def test_the_poincare_panel_draws_points(page, path):
    page.goto(path)
    page.wait_for_selector(READY, state="attached")
    page.locator("#panel-poincare").scroll_into_view_if_needed()
    page.wait_for_function("Number(document.getElementById('panel-poincare').dataset.points) > 100", timeout=90_000)
    orbits = page.evaluate("document.querySelector('#panel-poincare .plot').data.length")
    assert orbits == 6
    readout = page.inner_text("#panel-poincare .readout")
    assert "orbits with h =" in readout
    # the plane and its side as a textbook writes them (prof-m 9: "crossing upward" before)
    assert "where θ₂ = 0 with θ̇₂ > 0." in readout and "crossing" not in readout, readout
    assert [e for e in page.console_errors if "status of 429" not in e] == []


def test_orbits_stopped_early_are_named_by_number_and_colour(page):
    # prof-g 49: "4 orbits were cut short: computing it further would take longer than this page allows" said
    # neither which orbits nor why in a reader's words; the server's own section, with orbits 2 and 4 reported
    # as stopped before their full time (as a busy server does)
    def stopped(route):
        answer = route.fetch().json()
        for k, orbit in enumerate(answer["orbits"]):
            orbit["complete"] = k not in (1, 3)
        route.fulfill(json=answer)

    page.route("**/api/scenes/double-pendulum/poincare*", stopped)
    page.goto("/scenes/double-pendulum")
    page.wait_for_selector(READY, state="attached")
    page.locator("#panel-poincare").scroll_into_view_if_needed()
    page.wait_for_function("Number(document.getElementById('panel-poincare').dataset.points) > 100", timeout=90_000)
    readout = page.inner_text("#panel-poincare .readout")
    assert "Orbits 2 (orange) and 4 (purple) were stopped before its full time" not in readout
    assert "Orbits 2 (orange) and 4 (purple) were stopped before their full time" in readout, readout
    assert "cut short" not in readout and "this page allows" not in readout
    table = page.text_content("#panel-poincare")  # the data table is folded under the plot
    assert table.count("(stopped early)") == 2, table
    assert "1 (blue)" in table and "6 (ochre)" in table
