"""The scene page's "Put this in a course page" as a lecturer uses it (issue 45, instructor review items 23 and
24): the frame's code is of the view as it is now and its address opens on that view; the plot is chosen by its
title; and after "Link to this view" the offer's line stays in sight at 1366 × 768."""

from __future__ import annotations

import re
from urllib.parse import urlsplit

import pytest

pytestmark = [pytest.mark.browser, pytest.mark.slow]

DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'


@pytest.fixture
def desktop(browser, live_server):
    context = browser.new_context(base_url=live_server, viewport={"width": 1366, "height": 768})
    context.grant_permissions(["clipboard-read", "clipboard-write"])
    page = context.new_page()
    page.set_default_timeout(90_000)
    page.errors = []
    page.on("pageerror", lambda exc: page.errors.append(str(exc)))
    yield page
    context.close()


def _set(page, name: str, value: str) -> None:
    field = page.locator(f"#ctl-{name}")
    field.fill(value)
    field.dispatch_event("change")


def _src(page, view: str) -> str:
    code = page.locator(f"#embed-code-{view}").input_value()
    found = re.fullmatch(r'<iframe src="([^"]+)" title="[^"]+" width="100%" height="\d+"></iframe>', code)
    assert found, code
    return found[1].replace("&amp;", "&")


def test_the_frame_offered_opens_on_the_view_set_up(desktop, live_server):
    page = desktop
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(DONE, state="attached")
    # the offer at first: the default view, this site's address
    page.click("#embed-offer > summary")
    assert _src(page, "full") == f"{live_server}/embed/scenes/simple-pendulum"
    _set(page, "R", "2")
    _set(page, "theta", "0.5")
    full = _src(page, "full")
    assert urlsplit(full).fragment in ("R=2&theta=0.5", "theta=0.5&R=2")
    # the plot beside the animation, chosen by its title: the code offered changes with it
    titles = page.locator("#embed-panel option").all_inner_texts()
    assert titles[0] == "None: the animation alone" and "Energy against time" in titles
    page.select_option("#embed-panel", label="Energy against time")
    compact = _src(page, "compact")
    assert urlsplit(compact).query == "view=compact&panel=energy" and urlsplit(compact).fragment == urlsplit(full).fragment
    # the changed plot's choice is not a run: the page did not run again for it (the settings' run has the new R)
    assert page.locator("#ctl-R").input_value() == "2"
    for address in (full, compact):
        page.goto(address)
        page.wait_for_selector(DONE, state="attached")
        assert float(page.locator("#ctl-R").input_value()) == 2
        assert float(page.locator("#ctl-theta").input_value()) == 0.5
    # the compact frame shows the energy plot beside the animation
    assert page.locator("[data-panel=energy]").count() == 1
    assert page.errors == []


def test_after_link_copied_the_course_page_line_is_in_sight(desktop, artifacts):
    page = desktop
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(DONE, state="attached")
    _set(page, "R", "2")
    page.wait_for_selector(DONE, state="attached")
    # the reader scrolled down to the animation, as one does to watch it
    page.evaluate("window.scrollTo(0, document.querySelector('.stage').getBoundingClientRect().top + window.scrollY - 10)")
    page.click("#view-link")
    # copied, or (where the browser refuses the page the clipboard) the link in a field to copy: either pushes down
    page.wait_for_function("['yes', 'no'].includes(document.getElementById('view-link-status').dataset.copied)")
    page.wait_for_timeout(400)
    seen = page.evaluate(
        """() => {
          const s = document.querySelector('#embed-offer > summary').getBoundingClientRect();
          const f = document.getElementById('controls').getBoundingClientRect();
          // the line's box lies inside the form's visible box (to a pixel's rounding) and the window, and nothing covers
          // any of its corners
          const corners = [[s.left + 2, s.top + 2], [s.right - 2, s.top + 2], [s.left + 2, s.bottom - 2], [s.right - 2, s.bottom - 2]];
          const summary = document.querySelector('#embed-offer > summary');
          return { inside: s.top >= f.top - 1 && s.bottom <= f.bottom + 1 && s.top >= 0 && s.bottom <= window.innerHeight,
                   covered: corners.filter(([x, y]) => !summary.contains(document.elementFromPoint(x, y))).length,
                   box: [s.top, s.bottom, f.top, f.bottom] };
        }"""
    )
    page.screenshot(path=artifacts / "embed-offer-after-link-1366.png")
    assert seen["inside"] and seen["covered"] == 0, seen
    assert page.errors == []
