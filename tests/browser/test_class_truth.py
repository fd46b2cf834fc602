"""The student's side of a class tells the truth (issue 44), on a phone at 390×844: a step typed right after "Show
this step" is said to be right and not done, and the count says so as the dashboard does; after a reload and on
another phone the page comes back as the student left it (the answers, their verdicts, the step shown, the text
being typed); the recovery code stays until "I have kept it"; the first answer box is on the first screen."""

from __future__ import annotations

import pytest

from tests.browser.test_classroom import (
    classes,  # noqa: F401 - the module's classes in a database of their own
    phone_page,
)

pytestmark = pytest.mark.browser

RIGHT_T = "m*R**2*theta_dot**2/2"
RIGHT_U = "m*g*R*(1 - cos(theta))"
WRONG_U = "-m*g*R*(1 - cos(theta))"
SHOWN_WORDS = "Right — but this step was shown before you answered it, so it does not count as done for the grade."




def _check(step, answer, verdict):
    step.locator("textarea").fill(answer)
    step.locator("textarea").press("Enter")
    step.locator(".practice-verdict[data-verdict]").wait_for()
    said = step.locator(".practice-verdict")
    assert said.get_attribute("data-verdict") == verdict, said.inner_text()


def test_a_phone_says_what_the_grade_counts_and_keeps_what_was_done(browser, live_server, classes, artifacts):  # noqa: F811
    context, page, errors = phone_page(browser, live_server)
    made = page.request.post("/api/classes", data={"title": "Mechanics II, Tuesday practice"}).json()
    teacher = {"Authorization": f"Bearer {made['teacher_key']}"}
    item = {"scene": "simple-pendulum", "steps": [{"step": "kinetic"}, {"step": "potential"}]}
    assert page.request.post(f"/api/classes/{made['code']}/assignments", headers=teacher,
                             data={"title": "Week 3: pendulums and the pulley", "items": [item]}).status == 201

    page.goto(f"/join?code={made['code']}")
    page.fill("#join-name", "Mei")
    page.click("#join-form button[type=submit]")
    page.wait_for_selector("#join-recovery:not([hidden])")
    page.wait_for_selector('.practice-step[data-step="kinetic"] textarea')
    code = page.locator("#join-recovery-code").inner_text()
    # item 5: the first answer box is whole on the first screen, the recovery code above it
    page.screenshot(path=artifacts / "join-first-screen-390.png")
    box = page.locator('.practice-step[data-step="kinetic"] textarea').bounding_box()
    assert box["y"] + box["height"] <= 844, box
    assert page.locator("#join-syntax").is_hidden()  # folded behind "How to type an answer"
    page.screenshot(path=artifacts / "join-first-screen-390.png")

    # item 3: a reload before "I have kept it" keeps the code
    page.reload()
    page.wait_for_selector('.practice-step[data-step="kinetic"] textarea')
    assert page.locator("#join-recovery").is_visible() and page.locator("#join-recovery-code").inner_text() == code

    kinetic = page.locator('.practice-step[data-step="kinetic"]')
    potential = page.locator('.practice-step[data-step="potential"]')
    _check(kinetic, RIGHT_T, "correct")
    kinetic.locator(".practice-done-label", has_text="Done: this step is answered right.").wait_for()
    _check(potential, WRONG_U, "incorrect")
    potential.locator(".join-reveal").click()
    potential.locator(".practice-done-label", has_text="You were shown this step").wait_for()
    # item 1: typed right after it was shown: right, not done, and the count says which
    _check(potential, RIGHT_U, "correct")
    potential.locator(".practice-done-label", has_text=SHOWN_WORDS).wait_for()
    assert "step-done" not in potential.get_attribute("class")
    progress = "1 of 2 steps done · 1 right after it was shown"
    page.wait_for_function(f"document.getElementById('joined-progress').textContent === {progress!r}")
    assert page.locator(".join-assignment-progress").inner_text() == progress
    # the dashboard's figures agree: one step done on her own, one shown
    [mei] = page.request.get(f"/api/classes/{made['code']}/students", headers=teacher).json()["students"]
    assert (mei["own"], mei["shown"], mei["counted"]) == (1, 1, 1)
    page.screenshot(path=artifacts / "join-shown-right-390.png", full_page=True)

    # item 2: a text being typed, not checked, survives a reload; the checked answers come back with their verdicts
    potential.locator("textarea").fill("m*g*R")
    page.reload()
    page.wait_for_selector('.practice-step[data-step="potential"] textarea')
    page.wait_for_function(f"document.getElementById('joined-progress').textContent === {progress!r}")
    assert potential.locator("textarea").input_value() == "m*g*R"
    assert kinetic.locator("textarea").input_value() == RIGHT_T
    assert kinetic.locator(".practice-verdict").get_attribute("data-verdict") == "correct"
    assert potential.locator(".practice-verdict").get_attribute("data-verdict") == "correct"
    assert potential.locator(".practice-done-label").inner_text() == SHOWN_WORDS
    # the verdict kept is said to be of the last answer checked, not of the text typed since
    assert potential.locator(".join-last-checked").inner_text() == f"Your last answer checked, {RIGHT_U}:"
    assert kinetic.locator(".join-last-checked").count() == 0
    kinetic.locator(".practice-preview .katex").wait_for()  # the answer brought back is typeset as if typed
    assert page.locator("#join-recovery-code").inner_text() == code
    page.screenshot(path=artifacts / "join-reloaded-390.png", full_page=True)

    # item 3: once kept, the code is gone for good
    page.click("#join-recovery-done")
    page.reload()
    page.wait_for_selector('.practice-step[data-step="potential"] textarea')
    assert page.locator("#join-recovery").is_hidden()

    # on another phone, from the record: the last answers, their verdicts and the step shown
    other_context, other, other_errors = phone_page(browser, live_server)
    other.goto(f"/join?code={made['code']}")
    other.locator("#join-again summary").click()
    other.fill("#rejoin-name", "mei")  # the pseudonym in another case opens the same record
    other.fill("#rejoin-recovery", code)
    other.click("#rejoin-form button[type=submit]")
    other.wait_for_function(f"document.getElementById('joined-progress').textContent === {progress!r}")
    assert other.locator("#joined-name").inner_text() == "Mei"
    there = other.locator('.practice-step[data-step="potential"]')
    assert there.locator("textarea").input_value() == RIGHT_U
    assert there.locator(".practice-done-label").inner_text() == SHOWN_WORDS
    assert there.locator(".practice-verdict").get_attribute("data-verdict") == "correct"
    assert other.locator("#join-recovery").is_hidden()  # a rejoin gets no new code
    other.screenshot(path=artifacts / "join-other-phone-390.png", full_page=True)
    assert errors == other_errors == []
    for each in (context, other_context):
        each.close()
