"""The pages in headless Chromium: they load cleanly, typeset, animate, re-simulate, and work from the keyboard."""

from __future__ import annotations

import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from app.scenes import SCENES

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'


def open_scene(page, scene_id: str) -> None:
    """Open a scene page and wait for its first simulation (failing fast, with the page's message, if it fails)."""
    page.goto(f"/scenes/{scene_id}")
    page.wait_for_selector(f'{READY}, #run-status[data-state="error"]', state="attached")
    state = page.get_attribute("#run-status", "data-state")
    assert state == "ready", page.inner_text("#run-status .message")


def trace_values(page, selector: str, trace: int, key: str = "x") -> list:
    return page.evaluate(
        "([sel, i, key]) => Array.from(document.querySelector(sel).data[i][key] || [])", [selector, trace, key]
    )


def bodies(page, kind: str = "animation-2d") -> list:
    """The bodies the animation's canvas shows: label and position in CSS pixels."""
    return page.evaluate(f"JSON.parse(document.querySelector('[data-panel={kind}] canvas').dataset.bodies || '[]')")


def cursor(page, kind: str = "energy") -> float:
    """The time at which a plot's cursor overlay stands."""
    return float(page.evaluate(f"document.querySelector('[data-panel={kind}] .plot-overlay line.cursor').dataset.value"))


def test_contents_page(page, artifacts):
    page.goto("/")
    page.wait_for_load_state("load")
    assert page.locator(".card").count() == len(SCENES)
    assert page.locator("svg.diagram").count() == len(SCENES)
    page.screenshot(path=artifacts / "contents.png", full_page=True)
    assert page.console_errors == []


def test_animation_plays_and_moves_the_cursors(page, artifacts):
    page.set_viewport_size({"width": 1280, "height": 2400})  # the animation and the energy plot both in view
    open_scene(page, "simple-pendulum")
    page.wait_for_selector("[data-panel=energy] .plot-overlay line.cursor", state="attached")
    start = bodies(page)
    before = cursor(page)
    page.click("[data-panel=animation-2d] [data-action=play]")
    page.wait_for_timeout(900)
    moving = bodies(page)
    page.click("[data-panel=animation-2d] [data-action=play]")  # pause
    page.wait_for_timeout(300)
    assert moving != start
    assert page.get_attribute("[data-panel=animation-2d] [data-action=play]", "aria-pressed") == "false"
    paused = bodies(page)
    page.wait_for_timeout(300)
    assert bodies(page) == paused
    assert cursor(page) > before
    # scrubbing with the keyboard
    page.focus("[data-panel=animation-2d] input.scrub")
    page.keyboard.press("End")
    page.wait_for_timeout(300)
    t_end = cursor(page)
    assert t_end == pytest.approx(SCENES["simple-pendulum"].t_end)
    assert page.inner_text("[data-panel=animation-2d] output.time").startswith(f"t = {t_end:.2f} s · θ = ")
    page.locator("[data-panel=animation-2d]").screenshot(path=artifacts / "animation.png")
    assert page.console_errors == []


def test_moving_a_slider_resimulates_without_reloading(page, artifacts):
    page.set_viewport_size({"width": 1280, "height": 2400})  # the energy plot in view: panels out of view wait
    open_scene(page, "simple-pendulum")
    page.wait_for_function("document.querySelector('[data-panel=energy] .plot').data?.length > 0")
    page.evaluate("window.notReloaded = true")
    runs = page.get_attribute("#simulation", "data-runs")
    energy = trace_values(page, "[data-panel=energy] .plot", 0, "y")
    page.focus("#ctl-g-range")
    for _ in range(40):
        page.keyboard.press("ArrowRight")
    page.wait_for_function(f"document.querySelector('#simulation').dataset.runs !== '{runs}'")
    page.wait_for_selector(READY, state="attached")
    assert float(page.input_value("#ctl-g")) > 9.81
    assert trace_values(page, "[data-panel=energy] .plot", 0, "y") != energy
    assert page.evaluate("window.notReloaded") is True
    page.screenshot(path=artifacts / "after-slider.png")
    assert page.console_errors == []


def test_bad_input_and_refusals_are_shown_in_place(page):
    open_scene(page, "spherical-pendulum")
    page.fill("#ctl-R", "1000")
    page.dispatch_event("#ctl-R", "change")
    assert page.get_attribute("#ctl-R", "aria-invalid") == "true"
    assert "must be a number from" in page.inner_text("#ctl-R-hint")
    # an invalid value is not run: the page says so next to Play and greys the plots
    assert page.get_attribute("#run-status", "data-state") == "invalid"
    assert page.inner_text("#run-status .message").startswith("Not re-run: ")
    assert "stale" in page.get_attribute("#simulation", "class")
    page.fill("#ctl-R", "1")
    page.dispatch_event("#ctl-R", "change")
    page.wait_for_selector(READY, state="attached")
    # Verlet needs a constant mass matrix, which the spherical pendulum has not: the API refuses, the page says why
    page.click(".controls-run-details > summary")
    page.select_option("#ctl-method", "Verlet")
    page.wait_for_selector('#run-status[data-state="error"]', state="attached")
    message = page.inner_text("#run-status .message")
    assert message.startswith("The simulation failed:") and "Verlet" in message
    assert page.get_attribute("#run-status", "role") == "status"
    page.route(
        "**/simulate",
        lambda route: route.fulfill(
            status=422, content_type="application/json", body='{"detail": "t_end: too much work"}'
        ),
    )
    page.select_option("#ctl-method", "auto")
    page.wait_for_selector('#run-status[data-state="error"]', state="attached")
    assert "t_end: too much work" in page.inner_text("#run-status .message")
    # the refusals are answers, not failures of the page
    assert all("422" in message for message in page.console_errors)


def test_keyboard_focus_reaches_every_control(page):
    open_scene(page, "spherical-pendulum")
    page.click(".controls-run-details > summary")  # the integration settings, folded by default
    controls = page.evaluate(
        """() => [...document.querySelectorAll('main input, main select, main button')]
              .filter((el) => el.checkVisibility() && !el.disabled).map((el) => el.id || el.outerHTML.slice(0, 80))"""
    )
    assert len(controls) > 20
    page.focus("main")
    seen = set()
    for _ in range(400):
        page.keyboard.press("Tab")
        seen.add(page.evaluate("document.activeElement.id || document.activeElement.outerHTML.slice(0, 80)"))
        if seen >= set(controls):
            break
    assert set(controls) <= seen, set(controls) - seen
    assert page.console_errors == []


def test_work_precision_chart(page, artifacts):
    open_scene(page, "simple-pendulum")
    # the simple pendulum is integrated well by every method: the comparison is one click away, under details
    folded = page.locator("details#details-work-precision")
    assert folded.get_attribute("open") is None
    folded.locator("> summary").click()
    panel = page.locator("[data-panel=work-precision]")
    panel.scroll_into_view_if_needed()
    try:
        page.wait_for_function(
            "document.querySelector('[data-panel=work-precision] .plot').data?.length >= 4", timeout=120_000
        )
    except PlaywrightTimeout:
        # say what the reader saw instead of a bare timeout: the run's status and the panel's own words
        status = page.locator("#run-status").all_inner_texts()
        raise AssertionError(f"no chart after 120 s; run status {status}; panel: {panel.inner_text()!r}") from None
    names = page.evaluate("document.querySelector('[data-panel=work-precision] .plot').data.map((t) => t.name)")
    assert any(n.startswith("this run (estimate") for n in names) and len(set(names)) >= 5  # four methods and this run
    assert "Reference:" in panel.locator(".readout").inner_text()
    panel.screenshot(path=artifacts / "work-precision.png")
    assert page.console_errors == []


def test_unknown_scene_page(page):
    response = page.goto("/scenes/no-such-scene")
    assert response.status == 404
    assert "no-such-scene" in page.inner_text("h1")
    assert page.locator("main a[href^='/scenes/']").count() == len(SCENES)
    # the only console message allowed is the browser's note that this document is a 404
    assert all("404" in message for message in page.console_errors)


def test_print_shows_the_derivation_without_the_simulation(page, artifacts):
    open_scene(page, "double-pendulum")  # its normal modes are long as read, so they start collapsed
    collapsed = page.locator("details.long-step:not([open])").count()
    assert collapsed > 0  # long steps start collapsed on screen ...
    page.evaluate("window.dispatchEvent(new Event('beforeprint'))")
    assert page.locator("details.long-step:not([open])").count() == 0  # ... and print in full
    page.emulate_media(media="print")
    assert page.locator("#simulation").is_hidden()
    assert page.locator("#derivation .step").first.is_visible()
    assert page.locator(".summary-box").is_visible()
    page.pdf(path=str(artifacts / "double-pendulum.pdf"))
    page.evaluate("window.dispatchEvent(new Event('afterprint'))")
    assert page.locator("details.long-step:not([open])").count() == collapsed
    assert page.console_errors == []
