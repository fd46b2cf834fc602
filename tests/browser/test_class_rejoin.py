"""A student changes device (issue 45), on phones: the recovery code shown once at joining, the taken name opening
the way back filled in, and the same record (a step done) on the second phone; the teacher's "new code"."""

from __future__ import annotations

import json

import pytest

from tests.browser.test_classroom import (
    classes,  # noqa: F401 - the module's classes in a database of their own
    phone_page,
)

pytestmark = pytest.mark.browser

RIGHT_T = "m*R**2*theta_dot**2/2"




def test_a_student_gets_back_to_their_record_on_another_phone(browser, live_server, classes, artifacts):  # noqa: F811
    first_context, first, first_errors = phone_page(browser, live_server)
    made = first.request.post("/api/classes", data={"title": "Two phones"}).json()
    teacher = {"Authorization": f"Bearer {made['teacher_key']}"}
    item = {"scene": "simple-pendulum", "steps": [{"step": "kinetic"}]}
    assert first.request.post(f"/api/classes/{made['code']}/assignments", headers=teacher,
                              data={"title": "Week 1", "items": [item]}).status == 201

    first.goto(f"/join?code={made['code']}")
    first.fill("#join-name", "ana")
    first.click("#join-form button[type=submit]")
    first.wait_for_selector("#join-recovery:not([hidden])")
    code = first.locator("#join-recovery-code").inner_text()
    assert len(code) == 14 and code.count("-") == 2
    first.screenshot(path=artifacts / "join-recovery-390.png")
    first.click("#join-recovery-done")
    assert first.locator("#join-recovery").is_hidden() and first.locator("#join-recovery-code").inner_text() == ""
    step = first.locator(".practice-step")
    step.locator("textarea").fill(RIGHT_T)
    step.locator("textarea").press("Enter")
    first.wait_for_selector(".practice-step.step-done")

    second_context, second, second_errors = phone_page(browser, live_server)
    second.goto(f"/join?code={made['code']}")
    second.fill("#join-name", "ana")
    second.click("#join-form button[type=submit]")
    second.wait_for_function("document.getElementById('join-status').textContent.includes('is taken')")
    assert "I joined before on another device" in second.locator("#join-status").inner_text()
    # the way back is opened, the code and the name filled in: only the recovery code to type
    assert second.locator("#join-again").get_attribute("open") is not None
    assert (second.locator("#rejoin-code").input_value(), second.locator("#rejoin-name").input_value()) == (
        made["code"], "ana")
    second.fill("#rejoin-recovery", code.lower())
    second.screenshot(path=artifacts / "join-rejoin-390.png")
    second.click("#rejoin-form button[type=submit]")
    second.wait_for_selector(".practice-step.step-done")
    assert second.locator("#joined-name").inner_text() == "ana"
    assert second.locator("#joined-progress").inner_text() == "1 of 1 steps done"
    assert second.evaluate("document.documentElement.scrollWidth <= window.innerWidth")

    # the teacher gives ana a new code from the dashboard, beside her name
    teach_context, teach, teach_errors = phone_page(browser, live_server)
    teach.goto("/teach")
    stored = json.dumps({"code": made["code"], "key": made["teacher_key"], "title": "Two phones"})
    teach.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(stored)})")
    teach.reload()
    teach.click("#names-shown")  # the names are hidden as the dashboard opens
    teach.on("dialog", lambda dialog: dialog.accept())
    row = teach.locator('#dash-students tr[data-student="ana"]')
    row.locator(".dash-new-code").click()
    given = row.locator(".dash-code")
    given.wait_for()
    assert len(given.inner_text()) == 14 and given.inner_text() != code
    # the one refused join (the taken name, a 422 the browser logs) and nothing else
    assert first_errors == teach_errors == [] and [e for e in second_errors if "status of 422" not in e] == []
    for context in (first_context, second_context, teach_context):
        context.close()
