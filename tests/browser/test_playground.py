"""/playground in headless Chromium: type a system, see it derived and simulated, share it, see errors in place."""

from __future__ import annotations

from urllib.parse import parse_qs, urlsplit

import pytest

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'


def tex_of(page, selector: str) -> str:
    """The LaTeX KaTeX typeset under ``selector`` (from its annotations)."""
    return page.eval_on_selector_all(f"{selector} annotation", "els => els.map((e) => e.textContent).join(' ')")


def test_the_default_system_is_derived_typeset_and_simulated(page, artifacts):
    page.goto("/playground")
    page.wait_for_selector(READY, state="attached")
    assert page.locator(".katex-error").count() == 0
    assert page.evaluate("document.body.dataset.katexErrors") == "0"
    assert page.locator("#derivation .step").count() >= 8
    assert page.locator(".math .katex").count() == page.locator(".math").count() > 0
    # the default system is given by T and U (no particle positions): no invented picture
    assert page.evaluate("JSON.parse(document.querySelector('[data-panel=animation-2d] canvas').dataset.drawn).none")
    assert "No picture" in page.inner_text("[data-panel=animation-2d] .animation-caption")
    for kind in ("energy", "phase"):
        plot = page.locator(f"[data-panel={kind}] .plot")
        page.wait_for_function("(el) => el.data && el.data.length > 0", arg=plot.element_handle())
        assert plot.locator(".main-svg").count() > 0, kind
        assert page.evaluate("(el) => el.data.length", plot.element_handle()) > 0, kind
    page.screenshot(path=artifacts / "playground.png", full_page=True)
    assert page.console_errors == []


def test_a_typed_system_is_derived_shared_and_animated(page, artifacts, browser, live_server):
    page.goto("/playground?new")
    assert page.locator("#derivation").count() == 0 and page.locator("#form-error").count() == 0
    page.check('input[name="form"][value="particles"]')
    assert page.locator("#f-T").is_hidden() and page.locator("#f-particle-0-mass").is_visible()
    page.fill("#f-coordinates", "phi")
    for i, (name, value, low) in enumerate([("m", "2", "0.01"), ("l", "1.5", "0.01"), ("g", "9.81", "")]):
        if i >= page.locator("#parameter-rows tbody tr").count():
            page.click('[data-target="parameter-rows"]')
        page.fill(f"#f-param-{i}-name", name)
        page.fill(f"#f-param-{i}-value", value)
        page.fill(f"#f-param-{i}-min", low)
    page.fill("#f-particle-0-mass", "m")
    page.fill("#f-particle-0-x", "l*sin(phi)")
    page.fill("#f-particle-0-z", "-l*cos(phi)")
    page.fill("#f-U", "-m*g*l*cos(phi)")
    page.click('#system-form button[type="submit"]')
    page.wait_for_selector(READY, state="attached")

    # the system is in the address: anyone opening it gets the same derivation
    query = parse_qs(urlsplit(page.url).query)
    assert query["q"] == ["phi"] and query["form"] == ["particles"] and query["x"] == ["l*sin(phi)"]
    assert query["pn"] == ["m", "l", "g"] and "fQ" not in query and "T" not in query
    accelerations = tex_of(page, "#results dd:nth-of-type(2)")
    assert r"\sin" in accelerations and "g" in accelerations and "l" in accelerations
    other = browser.new_context(base_url=live_server).new_page()
    other.goto(page.url)
    other.wait_for_selector(READY, state="attached")
    assert tex_of(other, "#results dd:nth-of-type(2)") == accelerations
    other.context.close()

    # the pendulum bob swings: the animation moves when played
    canvas = "document.querySelector('[data-panel=animation-2d] canvas')"
    assert page.evaluate(f"JSON.parse({canvas}.dataset.bodies)[0].label") == "mass 1"
    where = f"{canvas}.dataset.bodies"
    start = page.evaluate(where)
    page.click("[data-panel=animation-2d] [data-action=play]")
    page.wait_for_function(f"{where} !== {start!r}")
    # changing a parameter re-simulates through /api/simulate
    runs = int(page.get_attribute("#simulation", "data-runs"))
    page.fill("#ctl-l", "0.5")
    page.dispatch_event("#ctl-l", "change")
    page.wait_for_function(f"Number(document.querySelector('#simulation').dataset.runs) > {runs}")
    page.screenshot(path=artifacts / "playground-typed.png", full_page=True)
    assert page.console_errors == []


@pytest.mark.parametrize(
    ("query", "field", "marked"),
    [
        ("q=x&form=energies&pn=k&pv=1&T=x_dot**2/2&U=2^x^2", "f-U", "2^x^2"),
        ("q=x&form=lagrangian&L=x_dot**2/2 - __import__('os')", "f-L", "'"),
        ("q=x&form=particles&m=1&x=x&z=y&U=0", "f-particle-0-z", "y"),
        ("q=x,+sin&form=lagrangian&L=x_dot**2", "f-coordinates", ""),
        ("q=x&form=lagrangian&L=x_dot*x", "f-L", ""),
    ],
)
def test_errors_point_at_what_was_typed(page, query, field, marked):
    page.goto(f"/playground?{query}")
    error = page.locator("#form-error")
    assert error.is_visible() and error.get_attribute("data-field") == field
    assert page.get_attribute(f"#{field}", "aria-invalid") == "true"
    assert page.evaluate("document.activeElement.id") == field
    assert page.locator(f"#{field}-error").inner_text().strip()
    if marked:
        assert page.locator("#form-error mark").inner_text() == marked
    assert page.locator("#simulation").count() == 0
    # the page itself answers 422 (the system was refused), which Chromium logs; nothing else may fail
    assert [e for e in page.console_errors if "status of 422" not in e] == []
