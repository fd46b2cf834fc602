"""An assignment is edited in place on /teach (issue 45, review inst-b items 29 and 30): "Edit…" loads its title,
due time and ticked steps into the editor, whose step boxes name each step in words as the student reads it
("Energy function h", "ω² of small oscillations"); saving replaces it in its place and keeps its answers."""

from __future__ import annotations

import json

import pytest

from app.service.classroom import store
from tests.browser.test_classroom import DESK, classes  # noqa: F401 - the module's classes in a database of their own

pytestmark = pytest.mark.browser


@pytest.mark.slow
def test_an_assignment_is_edited_and_keeps_its_answers(browser, live_server, classes, artifacts):  # noqa: F811
    context = browser.new_context(base_url=live_server, **DESK)
    page = context.new_page()
    page.set_default_timeout(60_000)
    errors: list[str] = []
    page.on("pageerror", lambda exc: errors.append(str(exc)))
    made = page.request.post("/api/classes", data={"title": "Mechanics"}).json()
    code, key = made["code"], made["teacher_key"]
    db = classes[0].db
    class_id = store.access(db, code, key).class_id
    store.set_first(db, class_id, [{"item": "simple-pendulum", "system": None, "parameters": {},
                                    "steps": [{"step": "kinetic", "coordinate": None}]}])
    ada = store.join(db, code, "Ada")[1]
    first = store.series(db, class_id)[0]["id"]
    store.record(db, ada, "simple-pendulum", "kinetic", None, "correct", None, "T", assignment_id=first)

    page.goto("/teach")
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(json.dumps({'code': code, 'key': key, 'title': 'M'}))})")
    page.reload()
    page.click('#assign-series button[data-edit="1"]')
    assert page.locator("#assign-editor-title").inner_text() == "Editing assignment 1"
    assert page.input_value("#assign-title-input") == "Assignment 1"
    steps = page.locator('#assign-scenes li:has(> input[data-scene="simple-pendulum"]) .assign-steps')
    page.wait_for_selector('#assign-scenes input[data-scene="simple-pendulum"] ~ .assign-steps input[data-step="kinetic"]')
    # the steps in words, as the student reads them; the one assigned ticked
    labels = steps.locator("label").all_inner_texts()
    assert "Energy function h" in labels and "ω² of small oscillations about θ = 0" in labels, labels
    assert steps.locator('input[data-step="kinetic"]').is_checked()
    assert not steps.locator('input[data-step="potential"]').is_checked()

    page.fill("#assign-title-input", "Week 1: the pendulum")
    page.fill("#assign-due", "2031-03-04T17:00")
    steps.locator('input[data-step="potential"]').check()
    page.click("#assign-save")
    page.wait_for_function("document.getElementById('assign-status').textContent.startsWith('Saved')")
    assert page.locator("#assign-status").inner_text() == "Saved: 1. Week 1: the pendulum (its answers are kept)."
    assert page.locator("#assign-editor-title").inner_text() == "A new assignment"
    page.screenshot(path=artifacts / "teach-edited-1366.png", full_page=True)

    [edited] = page.request.get(f"/api/classes/{code}/assignments", headers={"Authorization": f"Bearer {key}"}).json()[
        "assignments"]
    assert edited["title"] == "Week 1: the pendulum" and edited["due"] is not None
    assert [s["step"] for s in edited["items"][0]["steps"]] == ["kinetic", "potential"]
    summary = page.request.get(f"/api/classes/{code}/summary", headers={"Authorization": f"Bearer {key}"}).json()
    assert summary["attempts"] == 1  # Ada's answer is still recorded
    assert errors == []
    context.close()


SPRING = {"coordinates": ["x"], "parameters": ["m", "k"], "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}
SPRING_SETUP = "x is the stretch of the spring from its natural length; U = 0 at x = 0."


@pytest.mark.slow
def test_a_typed_system_is_edited_as_typed_and_a_past_due_time_is_said_in_the_forms_words(
        browser, live_server, classes, artifacts):  # noqa: F811
    """Review inst-c 5 and 6: "Edit…" on a typed system's assignment loads its set-up and the system as the teacher
    typed it (pretty-printed, no nulls), so changing only the due time saves; a due time already past is said in
    the form's words and its local time, never as ISO 8601."""
    context = browser.new_context(base_url=live_server, **DESK)
    page = context.new_page()
    page.set_default_timeout(60_000)
    errors: list[str] = []
    page.on("pageerror", lambda exc: errors.append(str(exc)))
    made = page.request.post("/api/classes", data={"title": "Mechanics"}).json()
    code, key = made["code"], made["teacher_key"]
    auth = {"Authorization": f"Bearer {key}"}
    item = {"name": "spring", "system": SPRING, "setup": SPRING_SETUP, "steps": [{"step": "kinetic"}]}
    r = page.request.post(f"/api/classes/{code}/assignments", headers=auth,
                          data={"title": "Week 5: a spring you are given", "items": [item]})
    assert r.status == 201, r.text()

    page.goto("/teach")
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(json.dumps({'code': code, 'key': key, 'title': 'M'}))})")
    page.reload()
    page.click('#assign-series button[data-edit="1"]')
    page.wait_for_selector('#assign-system-steps input[data-step="kinetic"]')
    assert page.input_value("#assign-system-setup") == SPRING_SETUP
    typed = page.input_value("#assign-system")
    assert json.loads(typed) == SPRING and "null" not in typed and "\n" in typed, typed

    # a due time two hours ago, picked in the form's local time: said in its words, nothing saved
    past = page.evaluate("(() => { const t = new Date(Date.now() - 2 * 3600e3); const p = (n) => String(n).padStart(2, '0');"
                         " return `${t.getFullYear()}-${p(t.getMonth() + 1)}-${p(t.getDate())}T${p(t.getHours())}:${p(t.getMinutes())}`; })()")
    page.fill("#assign-due", past)
    page.click("#assign-save")
    said = page.locator("#assign-status").inner_text()
    assert said.startswith("That time (") and said.endswith(") has passed: choose a later one."), said
    assert "ISO" not in said and "Z" not in said.split("(")[1], said

    # the due time changed to one to come: saved, the set-up and system as they were
    page.fill("#assign-due", "2031-03-04T17:00")
    page.click("#assign-save")
    page.wait_for_function("document.getElementById('assign-status').textContent.startsWith('Saved')")
    [edited] = page.request.get(f"/api/classes/{code}/assignments", headers=auth).json()["assignments"]
    assert edited["due"] is not None and edited["items"][0]["setup"] == SPRING_SETUP
    page.screenshot(path=artifacts / "teach-typed-edited-1366.png", full_page=True)
    assert errors == []
    context.close()
