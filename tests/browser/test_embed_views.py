"""Embed pages as a reader meets them (issue 45, part B): the compact view within a phone's screen and a
desktop's, the heights the scene page offers holding every scene, every scene's first view honest (no green
over a warning, no timings, the energies' range said), and the velocity handle naming what dragging it does
on a scene page, an embed and the playground, at both sizes (the phone with touch)."""

from __future__ import annotations

from urllib.parse import urlencode

import pytest

from app.scenes import SCENES
from app.web.pages.playground_form import form_of, query_of
from app.web.rendering.embed_views import VIEWS

pytestmark = pytest.mark.browser

SIZES = {
    "desktop": {"viewport": {"width": 1280, "height": 900}},
    "phone": {"viewport": {"width": 390, "height": 844}, "has_touch": True, "is_mobile": True},
}
DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'
# a pendulum declared as a particle: the playground draws it, with its velocity handle
PENDULUM = {
    "coordinates": ["theta"],
    "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "l", "value": 1.0, "unit": "m"},
                   {"name": "g", "value": 9.81, "unit": "m/s^2"}],
    "particles": [{"mass": "m", "position": ["l*sin(theta)", "0", "-l*cos(theta)"]}],
    "potential": "-m*g*l*cos(theta)",
}  # fmt: skip


@pytest.fixture(params=list(SIZES))
def sized(request, browser, live_server):
    context = browser.new_context(base_url=live_server, **SIZES[request.param])
    page = context.new_page()
    page.set_default_timeout(90_000)
    page.errors = []
    page.on("pageerror", lambda exc: page.errors.append(str(exc)))
    yield request.param, page
    context.close()


# the page's height as drawn: the bottom of <main> (the document's own height is at least the viewport's)
BOTTOM = "Math.ceil(document.querySelector('main').getBoundingClientRect().bottom + window.scrollY)"


@pytest.mark.parametrize(
    "address",
    ["pulley?view=compact", "pulley?view=compact&panel=energy", "incline-block?view=compact&panel=energy",
     "spherical-pendulum?view=compact&panel=phase"],
)  # fmt: skip
def test_the_compact_embed_fits_the_screen_without_scrolling(sized, address, artifacts):
    size, page = sized
    page.goto(f"/embed/scenes/{address}")
    page.wait_for_selector(DONE, state="attached")
    page.wait_for_timeout(300)
    height = page.evaluate("window.innerHeight")
    assert page.evaluate(BOTTOM) <= height
    assert page.evaluate("document.scrollingElement.scrollHeight") <= height
    # the animation, its player and the panel are in view; no form, no paragraph of text
    assert page.locator("canvas.mechanism").first.is_visible() and page.locator("[data-action=play]").is_visible()
    assert page.locator("#controls").is_hidden()
    assert all(not p.is_visible() for p in page.locator(".panel-text, .animation-caption").all())
    page.screenshot(path=artifacts / f"embed-compact-{address.split('?')[0]}-{size}.png")
    assert page.errors == []


@pytest.mark.slow
def test_every_scene_first_view_is_honest_and_fits_the_offered_heights(browser, live_server):
    """A frame 900 px wide as the scene page offers it: every scene's page fits its view's height; the run
    status never shows a good run's green over a warning nor a computing time, and the energies' line says
    where the run goes."""
    context = browser.new_context(base_url=live_server, viewport={"width": 900, "height": 600})
    page = context.new_page()
    page.set_default_timeout(90_000)
    for scene in SCENES:
        for view, about in VIEWS.items():
            # the frame as offered: its height sets the page's vh, and so the picture's height
            page.set_viewport_size({"width": 900, "height": about["height"]})
            page.goto(f"/embed/scenes/{scene}?{urlencode({'view': view})}")
            page.wait_for_selector(DONE, state="attached")
            assert page.evaluate(BOTTOM) <= about["height"], (scene, view)
        status = page.locator("#run-status")
        warnings = page.locator("#run-status .warnings li:not(.event)").count()
        state, warned = status.get_attribute("data-state"), status.get_attribute("data-warned")
        assert not (warnings and state == "ready" and warned != "true"), scene
        text = status.inner_text()
        assert " ms" not in text and "computed in" not in text, scene
        assert state == "ready", (scene, text)  # every scene's default run meets its tolerance
        energies = page.inner_text(".energy-bars .ebar-range")
        assert energies.startswith("Over the ") and " run: T " in energies, scene
    context.close()


def _handle_label(page) -> dict:
    return page.evaluate(
        """() => {
          const canvas = document.querySelector('[data-panel^=animation] canvas.mechanism');
          const label = canvas.parentElement.querySelector('.handle-label');
          const handle = canvas.dataset.handle ? JSON.parse(canvas.dataset.handle) : null;
          if (!label || !handle) return { label: label && label.textContent, handle };
          const c = canvas.getBoundingClientRect(), r = label.getBoundingClientRect();
          const x = c.left + canvas.clientLeft + handle.x, y = c.top + canvas.clientTop + handle.y;
          // the label's distance from the handle's centre, and whether it lies within the canvas
          const dx = Math.max(r.left - x, 0, x - r.right), dy = Math.max(r.top - y, 0, y - r.bottom);
          // the first body (the one selected on a first view), whose velocity the handle sets
          const body = JSON.parse(canvas.dataset.bodies)[0];
          return { label: label.hidden ? null : label.textContent, distance: Math.hypot(dx, dy),
                   inside: r.left >= c.left - 1 && r.right <= c.right + 1 && r.top >= c.top - 1 && r.bottom <= c.bottom + 1,
                   handle: [x, y], body: [c.left + canvas.clientLeft + body.x, c.top + canvas.clientTop + body.y] };
        }"""
    )


@pytest.mark.parametrize(
    "address",
    [
        "/scenes/double-pendulum",
        "/embed/scenes/pulley",
        "/playground?" + urlencode(query_of(form_of(PENDULUM)), doseq=True),
    ],
    ids=["scene", "embed", "playground"],
)
def test_the_velocity_handle_says_what_dragging_it_does(sized, address, artifacts):
    size, page = sized
    page.goto(address)
    page.wait_for_selector(DONE, state="attached")
    page.wait_for_function("document.querySelector('[data-panel^=animation] canvas.mechanism').dataset.handle !== ''")
    label = page.locator("[data-panel^=animation] .handle-label")
    label.wait_for(state="visible")
    # (the screenshot scrolls the picture into view: before the handle's place on the screen is read)
    page.locator("[data-panel^=animation]").first.screenshot(path=artifacts / f"handle-label-{address[1:6]}-{size}.png")
    seen = _handle_label(page)
    # at rest the label says so: the arrow has no length yet
    assert seen["label"] == "drag: initial velocity (now 0)", seen
    # beside the handle, or a line of words (22 px) higher or lower where a body, a rod, a string or a wheel
    # leaves no room beside it (arrows.js handleWordsBox)
    assert seen["distance"] < 30 + 22 and seen["inside"], seen
    # the reader holds the handle and drags it: a start with speed, and the label has done its work
    # pulled further out along its arrow (nearer the body than the arrow's stub asks for rest)
    (x, y), (bx, by) = seen["handle"], seen["body"]
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + 1.5 * (x - bx), y + 1.5 * (y - by), steps=4)
    page.mouse.up()
    page.wait_for_function(
        "[...document.querySelectorAll('#controls .control[data-name$=\"_dot\"] input[type=number]')].some((i) => Number(i.value) !== 0)"
    )
    assert label.is_hidden()
    assert page.errors == []


@pytest.mark.parametrize("clipboard", ["granted", "refused"])
def test_link_to_this_view_confirms_the_copy_or_selects_the_link(browser, live_server, clipboard):
    context = browser.new_context(base_url=live_server, **SIZES["desktop"])
    if clipboard == "granted":
        context.grant_permissions(["clipboard-read", "clipboard-write"])
    else:
        # a browser that refuses the page the clipboard (as one without the permission, or over plain http, does)
        context.add_init_script(
            "navigator.clipboard.writeText = () => Promise.reject(new DOMException('refused', 'NotAllowedError'));"
        )
    page = context.new_page()
    page.set_default_timeout(90_000)
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(DONE, state="attached")
    page.click("#view-link")
    status = page.locator("#view-link-status")
    page.wait_for_function("['yes', 'no'].includes(document.getElementById('view-link-status').dataset.copied)")
    link = status.get_attribute("data-link")
    assert status.get_attribute("aria-live") == "polite"  # a screen reader hears which
    if clipboard == "granted":
        assert status.get_attribute("data-copied") == "yes"
        assert status.inner_text().startswith("Link copied to the clipboard: ")
        assert page.evaluate("navigator.clipboard.readText()") == link
    else:
        assert status.get_attribute("data-copied") == "no"
        assert "copy this link by hand" in status.inner_text()
        field = page.locator("#view-link-field")
        assert field.input_value() == link and field.is_visible()
        # the link is selected in the focused field, ready for Ctrl+C
        assert page.evaluate(
            "(() => { const f = document.activeElement; return f.id === 'view-link-field' && f.selectionStart === 0 && f.selectionEnd === f.value.length; })()"
        )
    context.close()
