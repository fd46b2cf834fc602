"""The same answer reads the same on a class page and on the scene's own page in practice mode (issue 41,
student-f 23): the verdict, the named mistake, its reason and a refusal; and each box says what it takes in the
same words."""

from __future__ import annotations

import pytest

from tests.browser.test_classroom import (
    DESK,
    _errors_of,
    classes,  # noqa: F401 - the module's classes in a database of their own
)

pytestmark = pytest.mark.browser

SCENE = "incline-block"
SWAPPED_U = "m*g*X*cos(alpha)"  # sin and cos swapped
UNREADABLE = "m*g*("  # refused: not checked


def _said(step) -> dict[str, str]:
    """A verdict's words by part: its head, the named mistake, the reason, part by part."""
    box = step.locator(".practice-verdict")
    parts = {"head": "p:first-child", "mistake": ".verdict-mistake p", "reason": ".verdict-hint", "partial": ".verdict-partial"}
    return {part: box.locator(css).first.inner_text() if box.locator(css).count() else "" for part, css in parts.items()}


def _check(step, text: str, verdict: str) -> dict[str, str]:
    step.locator("textarea").fill(text)
    step.locator("textarea").press("Enter")
    step.locator(f'.practice-verdict[data-verdict="{verdict}"]').wait_for()
    return _said(step)


def test_a_slip_and_a_refusal_read_the_same_on_the_class_page_and_the_scene_page(browser, live_server, classes, artifacts):  # noqa: F811
    context = browser.new_context(base_url=live_server, **DESK)
    page = context.new_page()
    page.set_default_timeout(60_000)
    errors = _errors_of(page)
    made = page.request.post("/api/classes", data={"title": "Same words"}).json()
    teacher = {"Authorization": f"Bearer {made['teacher_key']}"}
    added = page.request.post(f"/api/classes/{made['code']}/assignments", headers=teacher,
                              data={"title": "Week 1", "items": [{"scene": SCENE, "steps": [{"step": "potential"}]}]})
    assert added.status == 201, added.text()
    page.goto(f"/join?code={made['code']}")
    page.fill("#join-name", "Ada")
    page.click("#join-form button[type=submit]")
    page.wait_for_selector('.practice-step[data-step="potential"] textarea')
    in_class = page.locator('.practice-step[data-step="potential"]')
    class_slip = _check(in_class, SWAPPED_U, "incorrect")
    page.screenshot(path=str(artifacts / "class-feedback-slip.png"), full_page=True)
    class_refusal = _check(in_class, UNREADABLE, "refused")
    class_help = in_class.locator(".practice-names").inner_text()
    page.locator(".join-howto summary").click()  # folded behind "How to type an answer" (issue 44)
    class_syntax = page.locator("#join-syntax").inner_text()

    scene = context.new_page()
    scene.set_default_timeout(60_000)
    scene_errors = _errors_of(scene)
    scene.goto(f"/scenes/{SCENE}#practice=on")
    scene.wait_for_selector('.practice-step[data-step="potential"] textarea')
    on_scene = scene.locator('.practice-step[data-step="potential"]')
    scene_slip = _check(on_scene, SWAPPED_U, "incorrect")
    scene_refusal = _check(on_scene, UNREADABLE, "refused")

    # the same words, part by part; "your" said once; the reason a sentence
    assert class_slip == scene_slip, (class_slip, scene_slip)
    assert class_slip["mistake"].startswith("The mistake: sin and cos swapped in your term"), class_slip
    assert class_slip["reason"].startswith("Why: ") and class_slip["reason"].endswith(".")
    assert class_slip["mistake"].count("your") == 1 and "your" not in class_slip["reason"]
    # a refusal: "Not checked:" then the reason in lower case, with a full stop
    assert class_refusal["head"] == scene_refusal["head"], (class_refusal, scene_refusal)
    said = class_refusal["head"].removeprefix("Not checked: ")
    assert said != class_refusal["head"] and said[0].islower() and said.endswith("."), class_refusal
    # each box says what it takes as the scene page does, before the names
    how = on_scene.locator(".practice-names").inner_text().partition("Names you may use:")[0]
    assert how.startswith("Type only the right-hand side.") and class_help.startswith(how), (how, class_help)
    assert class_syntax == scene.locator("#practice-syntax").inner_text()
    assert not [e for e in errors + scene_errors if "status of 422" not in e], errors + scene_errors
    context.close()
