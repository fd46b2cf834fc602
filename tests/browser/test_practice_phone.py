"""Practice on a phone (issue 41, student-k 8–10): a way from the top of the page down to the steps, the steps
numbered as the panels that give them away name them, and a shown formula too wide for the screen marked as one
that scrolls sideways."""

from __future__ import annotations

import re

import pytest

from tests.browser.conftest import unfold_panels
from tests.browser.test_practice import STEP, sized_page

pytestmark = pytest.mark.browser


def test_the_top_of_the_page_leads_to_the_numbered_steps(browser, live_server, artifacts):
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/double-pendulum")
        page.wait_for_selector("#practice-switch")
        # only while practising
        assert page.locator(".practice-jump a").count() == 1 and page.locator(".practice-jump a").is_hidden()
        page.locator("#practice-switch").tap()
        page.wait_for_selector(STEP.format("potential"))
        page.evaluate("scrollTo(0, 0)")
        jump = page.get_by_role("link", name="Go to the practice steps ↓")
        # on the first screen, under the statement
        assert jump.is_visible() and jump.bounding_box()["y"] + jump.bounding_box()["height"] <= 844
        page.screenshot(path=artifacts / "practice-jump-390.png")
        first = page.locator(".practice-step").first
        # the steps are screens down: the link is needed
        assert first.evaluate("e => e.getBoundingClientRect().top + scrollY") > 2 * 844
        jump.tap()
        page.wait_for_function("document.querySelector('.practice-step').getBoundingClientRect().top < innerHeight")
        # each step numbered; the panel that gives a step away names it by that number and title
        numbers = page.locator(".practice-step h3 .practice-number").all_inner_texts()
        assert numbers == [f"Step {k + 1}:" for k in range(len(numbers))] and len(numbers) > 5
        unfold_panels(page)
        said = re.fullmatch(r"Show \(gives away step (\d+): (.+)\)", page.locator(".gives-away").first.inner_text())
        assert said is not None
        headings = page.locator(".practice-step h3").all_inner_texts()
        assert headings[int(said[1]) - 1] == f"Step {said[1]}: {said[2]}"
    finally:
        context.close()


def test_a_shown_answer_too_wide_for_a_phone_says_it_scrolls(browser, live_server, artifacts):
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/double-pendulum?practice")
        key = "acceleration:theta1"
        page.wait_for_selector(STEP.format(key))
        step = page.locator(STEP.format(key))
        # every font loaded and the page's own late looks over (1.5 s): the box is shown to a page at rest, as a
        # student shows it, so only its showing can set the cue
        page.evaluate("Promise.all([...document.fonts].map((f) => f.load()))")
        page.wait_for_timeout(2000)
        step.locator("button[aria-controls]").tap()
        shown = step.locator(".practice-engine .math-display")
        shown.locator(".katex").wait_for()
        assert shown.evaluate("e => e.scrollWidth > e.clientWidth + 1")
        # the cue: the right edge fades, with its arrow (site.css), once the box is shown
        cue = f"document.querySelector('{STEP.format(key)} .practice-engine .math-display').dataset.more === 'right'"
        page.wait_for_function(cue, timeout=5_000)
        step.screenshot(path=artifacts / "practice-shown-wide-390.png")
    finally:
        context.close()
