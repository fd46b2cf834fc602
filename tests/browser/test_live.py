"""The live page: phones, privacy, math without JavaScript, the painted event, dragging a body."""

from __future__ import annotations

from urllib.parse import urlsplit

import pytest

from tests.browser.conftest import unfold_panels

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'
PAGES = ["/", "/playground"]  # the scene pages: test_scene_read.py (no_overflow)


@pytest.fixture
def phone(browser, live_server):
    context = browser.new_context(
        base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    page.set_default_timeout(60_000)
    yield page
    context.close()


@pytest.mark.parametrize("path", PAGES)
def test_no_horizontal_overflow_on_a_phone(phone, artifacts, path):
    phone.goto(path)
    if path != "/":
        phone.wait_for_selector(f'{READY}, #run-status[data-state="error"]', state="attached")
        phone.wait_for_timeout(300)
    width = phone.evaluate("document.documentElement.scrollWidth")
    wide = phone.evaluate(
        """() => [...document.querySelectorAll('main *')].filter((el) => el.getBoundingClientRect().right > 391
             && !el.ownerSVGElement && !el.closest('.table-scroll, .math-display, .data-summary .table, math, .katex-display'))
             .map((el) => el.tagName + '.' + el.className).slice(0, 5)"""
    )
    assert width <= 390 and wide == [], (width, wide)
    name = path.strip("/").replace("/", "-") or "contents"
    phone.screenshot(path=artifacts / f"phone-{name}.png")


def test_a_swipe_on_a_plot_scrolls_the_page(phone):
    phone.goto("/scenes/simple-pendulum")
    phone.wait_for_selector(READY, state="attached")
    unfold_panels(phone, "#panel-energy")  # a phone shows the panels folded under the animation
    plot = phone.locator("[data-panel=energy] .plot")
    plot.scroll_into_view_if_needed()
    phone.wait_for_function("(el) => el.data && el.data.length > 0", arg=plot.element_handle())
    box = plot.bounding_box()
    before = phone.evaluate("window.scrollY")
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    # a finger put down on the plot and moved 225 px up
    cdp = phone.context.new_cdp_session(phone)
    cdp.send("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [{"x": x, "y": y}]})
    for k in range(1, 16):
        cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [{"x": x, "y": y - 15 * k}]})
    cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
    phone.wait_for_timeout(300)
    assert phone.evaluate("window.scrollY") > before + 100
    # and the plot kept its axes: no drag-zoom happened
    assert phone.evaluate("(el) => el.layout.xaxis.autorange", plot.element_handle()) is True


def test_nothing_leaves_the_machine_and_nothing_offers_to_upload(page, live_server):
    hosts = set()
    page.on("request", lambda request: hosts.add(urlsplit(request.url).hostname))
    page.set_viewport_size({"width": 1280, "height": 2400})
    for path in ("/scenes/spherical-pendulum", "/playground"):
        page.goto(path)
        page.wait_for_selector(READY, state="attached")
        page.wait_for_function("document.querySelector('[data-panel=energy] .plot').data?.length > 0")
        page.hover("[data-panel=energy] .plot")
        # no tool bar at all, not even on hover (prof-c S12: camera and home icons on a book's figure)
        assert page.locator(".modebar, .modebar-btn").count() == 0
        html = page.content()
        assert "Chart Studio" not in html and "plot.ly" not in html.replace("plotly", "")
    assert hosts == {urlsplit(live_server).hostname}


def test_the_derivation_reads_without_javascript(browser, live_server):
    context = browser.new_context(base_url=live_server, java_script_enabled=False)
    page = context.new_page()
    page.goto("/scenes/spherical-pendulum")
    steps = page.locator("#derivation .step")
    assert steps.count() > 10 and steps.nth(steps.count() - 1).is_visible()  # nothing folded away
    maths = page.locator("#derivation .math")
    assert maths.count() > 10
    assert page.locator("#derivation .math math").count() == maths.count()  # MathML, typeset by the browser
    assert "\\frac" not in page.inner_text("#derivation") and "\\dot" not in page.inner_text("#results")
    assert page.locator("noscript").count() >= 1
    context.close()


def painted_events(page) -> None:
    # what the page shows at the moment each paint is announced (the server's run may follow the preview
    # within milliseconds, before the test could look)
    page.evaluate(
        """window.painted = []; window.shown = {}; document.addEventListener('lagrange:painted', (e) => {
             window.painted.push(e.detail.source);
             window.shown[e.detail.source] ??= {
               source: document.getElementById('simulation')?.dataset.source,
               bodies: document.querySelector('[data-panel=animation-2d] canvas')?.dataset.bodies,
               message: document.querySelector('#run-status .message')?.textContent};
           })"""
    )


def test_an_input_is_painted_first_by_the_preview_then_by_the_server(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    painted_events(page)
    start = page.evaluate("document.querySelector('[data-panel=animation-2d] canvas').dataset.bodies")
    page.focus("#ctl-theta-range")
    page.keyboard.press("ArrowLeft")
    page.wait_for_function("window.painted.includes('preview')")
    preview = page.evaluate("window.shown.preview")
    assert preview["source"] == "preview"
    assert preview["bodies"] != start
    assert preview["message"].startswith("Preview:")
    page.wait_for_function("window.painted.includes('server')")
    page.wait_for_selector(READY, state="attached")
    assert page.get_attribute("#simulation", "data-source") == "server"
    assert page.evaluate("window.painted") == ["preview", "server"]


@pytest.mark.parametrize("scene_id", ["simple-pendulum", "incline-block"])
def test_dragging_a_body_sets_the_initial_state(page, scene_id):
    page.goto(f"/scenes/{scene_id}")
    page.wait_for_selector(READY, state="attached")
    painted_events(page)
    q = page.eval_on_selector("#controls .controls-initial .control", "el => el.dataset.name")
    before = float(page.input_value(f"#ctl-{q}"))
    canvas = page.locator("[data-panel=animation-2d] canvas")
    box = canvas.bounding_box()
    body = page.evaluate("JSON.parse(document.querySelector('[data-panel=animation-2d] canvas').dataset.bodies)[0]")
    x, y = box["x"] + body["x"], box["y"] + body["y"]
    page.mouse.move(x, y)
    page.mouse.down()
    # up the slope for the block (it starts at the foot, and X(0) stays on the ramp)
    dx = 12 if scene_id == "incline-block" else -12
    for k in range(1, 6):
        page.mouse.move(x + dx * k, y - 6 * k)
    page.mouse.up()
    page.wait_for_function("window.painted.includes('preview')")
    after = float(page.input_value(f"#ctl-{q}"))
    assert after != pytest.approx(before, abs=1e-3)
    moved = page.evaluate("JSON.parse(document.querySelector('[data-panel=animation-2d] canvas').dataset.bodies)[0]")
    assert (moved["x"], moved["y"]) != (body["x"], body["y"])
    page.wait_for_function("window.painted.includes('server')")
    assert float(page.input_value(f"#ctl-{q}")) == after
    # the keyboard does the same from the canvas
    canvas.focus()
    page.keyboard.press("ArrowRight")
    page.wait_for_function(f"Number(document.querySelector('#ctl-{q}').value) !== {after}")


HANDLE = "JSON.parse(document.querySelector('[data-panel=animation-2d] canvas').dataset.handle || 'null')"


def test_dragging_the_velocity_handle_sets_the_initial_rate(page, artifacts):
    page.set_viewport_size({"width": 1366, "height": 768})
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    painted_events(page)
    before = float(page.input_value("#ctl-theta_dot"))
    handle = page.evaluate(HANDLE)
    body = page.evaluate("JSON.parse(document.querySelector('[data-panel=animation-2d] canvas').dataset.bodies)[0]")
    assert handle is not None and (handle["x"], handle["y"]) != (body["x"], body["y"])
    box = page.locator("[data-panel=animation-2d] canvas").bounding_box()
    x, y = box["x"] + handle["x"], box["y"] + handle["y"]
    # pull the handle further out along its arrow: the rate grows in the handle's direction
    ux, uy = handle["x"] - body["x"], handle["y"] - body["y"]
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 6):
        page.mouse.move(x + ux * 0.4 * k, y + uy * 0.4 * k)
    page.mouse.up()
    page.wait_for_function("window.painted.includes('preview')")
    after = float(page.input_value("#ctl-theta_dot"))
    assert abs(after - before) > 0.1
    # the body stays where it was; only its velocity changed
    assert (
        page.evaluate("JSON.parse(document.querySelector('[data-panel=animation-2d] canvas').dataset.bodies)[0]")
        == body
    )
    moved = page.evaluate(HANDLE)
    assert (moved["x"], moved["y"]) != (handle["x"], handle["y"])
    page.wait_for_function("window.painted.includes('server')")
    assert float(page.input_value("#ctl-theta_dot")) == after
    page.screenshot(path=artifacts / "velocity-handle-simple-pendulum.png")


def test_shift_and_an_arrow_key_change_the_initial_rate(page):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    painted_events(page)
    theta, rate = float(page.input_value("#ctl-theta")), float(page.input_value("#ctl-theta_dot"))
    page.locator("[data-panel=animation-2d] canvas").focus()
    page.keyboard.press("Shift+ArrowRight")
    page.wait_for_function("window.painted.includes('preview')")
    assert float(page.input_value("#ctl-theta_dot")) > rate
    assert float(page.input_value("#ctl-theta")) == theta
    assert "starts at" in page.inner_text("[data-panel=animation-2d] .drag-status")


def test_a_touch_on_the_velocity_handle_drags_it(phone, artifacts):
    phone.goto("/scenes/movable-incline")
    phone.wait_for_selector(READY, state="attached")
    canvas = phone.locator("[data-panel=animation-2d] canvas")
    canvas.scroll_into_view_if_needed()
    painted_events(phone)
    handle = phone.evaluate(HANDLE)
    assert handle is not None
    phone.screenshot(path=artifacts / "phone-velocity-handle-movable-incline.png")
    name = phone.eval_on_selector("#controls .controls-initial .control", "el => el.dataset.name")
    rates = {
        n: float(phone.input_value(f"#ctl-{n}"))
        for n in phone.eval_on_selector_all(
            "#controls .controls-initial .control", "els => els.map((e) => e.dataset.name)"
        )
        if n.endswith("_dot")
    }
    box = canvas.bounding_box()
    x, y = box["x"] + handle["x"], box["y"] + handle["y"]
    before = phone.evaluate("window.scrollY")
    cdp = phone.context.new_cdp_session(phone)
    cdp.send("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [{"x": x, "y": y}]})
    for k in range(1, 8):
        cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [{"x": x + 6 * k, "y": y - 6 * k}]})
    cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
    phone.wait_for_function("window.painted.includes('preview')")
    assert phone.evaluate("window.scrollY") == before  # the page did not scroll under the finger
    assert any(float(phone.input_value(f"#ctl-{n}")) != v for n, v in rates.items()), (name, rates)
