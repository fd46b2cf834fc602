"""The correct part a named mistake points at, behind a click, on a phone at 390×844 (review student-l, section 3
item 3): the verdict names the place and the kind of slip; "Show the correct denominator" is closed until tapped,
then shows the formula typeset; "Show this step" stays for giving up. The same on a class page at /join."""

from __future__ import annotations

import pytest

from tests.browser.test_classroom import (
    classes,  # noqa: F401 - the module's classes in a database of their own
    phone_page,
)
from tests.browser.test_practice import STEP, answer, sized_page, verdict_of, words

pytestmark = pytest.mark.browser

# the pulley's ÿ₁ with the denominator of an Atwood machine (student-l 3)
PULLEY_SLIP = "g*(M - 2*m1)/(M + 4*m1 + m2)"
# the rail's spring with the natural length's sign reversed
RAIL_SLIP = "k*(x2 - x1 + l0)**2/2"


def _closed_then_typeset(part, summary: str) -> str:
    """The disclosure closed, its formula not shown; tapped open, the formula typeset: the LaTeX KaTeX set."""
    assert part.locator("summary").inner_text() == summary
    assert part.evaluate("e => e.open") is False
    assert part.locator(".verdict-correct-math").is_hidden()
    part.locator("summary").tap()
    part.locator(".verdict-correct-math .katex").wait_for()
    assert part.evaluate("e => e.open") is True
    assert part.locator(".katex-error").count() == 0
    return part.locator(".verdict-correct-math annotation").evaluate("e => e.textContent")


def test_the_correct_denominator_is_behind_a_tap_on_a_phone(browser, live_server, artifacts):
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/pulley?practice")
        key = "acceleration:y1"
        page.wait_for_selector(STEP.format(key))
        answer(page, key, PULLEY_SLIP)
        verdict = verdict_of(page, key)
        part = verdict.locator("details.verdict-correct")
        part.wait_for(state="attached")
        said = words(verdict)
        # the place and the kind of slip are named; the correct denominator is not printed
        assert "the denominator M + m₂ + 4 m₁" in said and "where the correct one" not in said, said
        assert "M m₁ + M m₂" not in said and "4 m₁ m₂" not in said, said
        verdict.screenshot(path=artifacts / "practice-correct-part-closed-390.png")
        math = _closed_then_typeset(part, "Show the correct denominator")
        assert "M m_{1}" in math and "4 m_{1} m_{2}" in math, math
        assert "(up to a constant factor)" in part.inner_text()
        assert verdict.evaluate("e => e.getBoundingClientRect().right") <= 391
        verdict.screenshot(path=artifacts / "practice-correct-part-open-390.png")
        # giving up is still the step's own button
        assert page.locator(STEP.format(key)).get_by_role("button", name="Show this step").count() == 1
    finally:
        context.close()


def test_a_class_phone_shows_the_correct_stretch_behind_a_tap(browser, live_server, classes, artifacts):  # noqa: F811
    context, page, errors = phone_page(browser, live_server)
    try:
        made = page.request.post("/api/classes", data={"title": "Mechanics II, springs"}).json()
        teacher = {"Authorization": f"Bearer {made['teacher_key']}"}
        item = {"scene": "rail-two-body", "steps": [{"step": "potential"}]}
        assert page.request.post(f"/api/classes/{made['code']}/assignments", headers=teacher,
                                 data={"title": "Week 4: springs", "items": [item]}).status == 201  # fmt: skip
        page.goto(f"/join?code={made['code']}")
        page.fill("#join-name", "Ana")
        page.click("#join-form button[type=submit]")
        step = page.locator('.practice-step[data-step="potential"]')
        step.locator("textarea").wait_for()
        step.locator("textarea").fill(RAIL_SLIP)
        step.locator("textarea").press("Enter")
        step.locator('.practice-verdict[data-verdict="incorrect"]').wait_for()
        said = words(step.locator(".practice-verdict"))
        assert "the sign of l₀" in said and "x₂ − x₁ − l₀" not in said, said
        math = _closed_then_typeset(step.locator("details.verdict-correct"), "Show the correct stretch")
        assert "x_{2} - x_{1} - l_{0}" in math, math
        step.screenshot(path=artifacts / "join-correct-part-open-390.png")
        assert not errors, errors
    finally:
        context.close()
