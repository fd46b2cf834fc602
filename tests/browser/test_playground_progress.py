"""While /playground works out the rest of a typed triple pendulum it says which part it is on and for how long,
and "Stop deriving" stops it, keeping the equations already shown (issue 45, item 6); desktop and phone."""

from __future__ import annotations

import pytest

from tests.browser import test_playground_stages as stages
from tests.browser.test_playground_stages import FIRST, type_chain

pytestmark = pytest.mark.browser
sized = stages.sized  # the same two sizes and page set-up as the stages' test


def test_the_part_being_worked_on_is_shown_and_stop_keeps_the_equations(sized, artifacts):
    name, page = sized
    # five links: the rest takes a few seconds even on a quiet machine, so the part being worked on is shown
    # (a triple pendulum's rest now ends within the page's first poll, a second after its equations)
    type_chain(page, {"desktop": "9.771", "phone": "9.772"}[name], 5)
    page.click('#system-form button[type="submit"]')
    page.wait_for_selector(FIRST)
    page.wait_for_selector("#derive-now:not([hidden])")
    now = page.inner_text("#derive-part")
    assert now.startswith("Now: ") and " s in all)." in now
    page.screenshot(path=artifacts / f"playground-progress-{name}.png")
    page.click("#derive-cancel")
    page.wait_for_selector('#derived[data-stage="stopped"]')
    assert page.inner_text("#derive-progress").startswith("Stopped, as you asked: the equations above stay.")
    assert page.locator("#derive-now").is_hidden()
    # what was shown stays: the five equations, typeset
    assert page.locator("#results dd").first.locator(".math-display").count() == 5
    assert page.console_errors == []
