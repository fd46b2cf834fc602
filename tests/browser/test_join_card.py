"""A student's card on the class page (issue 45, instructor review items 14-18): a refusal keeps the student's
symbol's case, an empty Check clears the old verdict, a done step says so in words after a reload, a right answer
after the due time says it is late on the card, and the taken name's message is a sentence."""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

import pytest
from sqlalchemy import update

from app.service.classroom import store
from app.service.classroom.database import now
from app.service.classroom.models import ClassAssignmentRow
from tests.browser.test_classroom import (
    DESK,
    _errors_of,
    classes,  # noqa: F401 - the module's classes in a database of their own
)

pytestmark = [pytest.mark.browser, pytest.mark.slow]

RIGHT_T = "m*R**2*theta_dot**2/2"


def _desk(browser, live_server):
    context = browser.new_context(base_url=live_server, **DESK)
    page = context.new_page()
    page.set_default_timeout(60_000)
    return context, page, _errors_of(page)


def _check(step, text: str) -> str:
    step.locator("textarea").fill(text)
    step.locator("button[type=submit]").click()
    step.locator(".practice-verdict[data-verdict]").wait_for()
    return step.locator(".practice-verdict").inner_text()


def test_a_students_card_says_each_outcome_in_words(browser, live_server, classes, artifacts):  # noqa: F811
    context, page, errors = _desk(browser, live_server)
    made = page.request.post("/api/classes", data={"title": "Cards"}).json()
    teacher = {"Authorization": f"Bearer {made['teacher_key']}"}
    due = datetime.now(UTC) + timedelta(hours=1)
    item = {"scene": "simple-pendulum", "steps": [{"step": "kinetic"}, {"step": "potential"}]}
    assert page.request.post(f"/api/classes/{made['code']}/assignments", headers=teacher,
                             data={"title": "Week 3", "due": due.strftime("%Y-%m-%dT%H:%M:%SZ"), "items": [item]}).status == 201  # fmt: skip
    page.goto(f"/join?code={made['code']}")
    page.fill("#join-name", "Ivo")
    page.click("#join-form button[type=submit]")
    kinetic = page.locator('.practice-step[data-step="kinetic"]')
    kinetic.locator("textarea").wait_for()
    # 14: a name the problem does not have keeps its case: x, never X
    said = _check(kinetic, "m*R**2*x**2/2")
    assert said.startswith("Not checked: x is not a name"), said
    # 15: an empty Check clears the old verdict and says what to do
    assert _check(kinetic, "") == "Type an answer first."
    # 16: right; after a reload the card says it is done, in words
    assert _check(kinetic, RIGHT_T).startswith("Correct")
    label = kinetic.locator(".practice-done-label")
    label.wait_for(state="visible")  # set once the record has answered, a moment after the verdict
    assert label.inner_text() == "Done: this step is answered right."
    page.reload()
    kinetic.locator(".practice-done-label").wait_for(state="visible")
    assert page.locator('.practice-step[data-step="potential"] .practice-done-label').is_hidden()
    # 17: after the due time a right answer's card says it is late: the server's record says so (issue 44), so the
    # due time is moved into the past in the class's database, and the browser's clock past it for the header
    db = classes[0].db
    class_id = store.access(db, made["code"], made["teacher_key"]).class_id
    with db.session() as session:
        session.execute(update(ClassAssignmentRow).where(ClassAssignmentRow.class_id == class_id)
                        .values(due=now() - timedelta(minutes=1)))
    page.clock.set_fixed_time(due + timedelta(minutes=5))
    potential = page.locator('.practice-step[data-step="potential"]')
    said = _check(potential, "-m*g*R*cos(theta)")
    assert said.startswith("Equivalent"), said
    late = potential.locator(".practice-done-label", has_text="Right, but late")
    late.wait_for()
    assert late.inner_text() == "Right, but late: it is recorded after the due time and does not count toward the grade."
    page.screenshot(path=artifacts / "join-card-late-1366.png", full_page=True)
    # (the answers the checker refused are 422 responses, which the console lists; nothing else went wrong)
    assert [e for e in errors if "status of 422" not in e] == []
    # 18: the taken name, as a sentence
    other, second, _ = _desk(browser, live_server)
    second.goto(f"/join?code={made['code']}")
    second.fill("#join-name", "Ivo")
    second.click("#join-form button[type=submit]")
    second.wait_for_function("document.getElementById('join-status').textContent.includes('is taken')")
    assert second.locator("#join-status").inner_text() == (
        "The name “Ivo” is taken in this class: if it is you, choose “I joined before on another device” and type "
        "your recovery code (or ask your teacher for a new one); otherwise choose another name.")
    other.close()
    context.close()
