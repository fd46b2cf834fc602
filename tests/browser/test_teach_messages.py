"""/teach says what went wrong in a teacher's words, at the box concerned, and its dashboard's first screen says
who is done (issue 45; review inst-a, items 2–5, 14, 15, 17).

In headless Chromium at 1366×768: a teacher link cut short and an open with no key say what to type; an
assignment with nothing ticked, a typed system with a syntax error (at the system's box, naming "The potential
U", gone once the system is corrected) and a typed system with no step ticked (every step, as for a scene).
The list of assignments: no numbered empty state, no "due —" on an undated one, its steps named, a "Delete…"
that asks.  The dashboard: the assignments' "Done" on the first screen, step cards counting students and
answers apart, the steps nobody answered behind "Show every step", and on a phone each student's last step
named as the page prints it ("equation of motion for θ"), within the screen's width.
"""

from __future__ import annotations

import json
import re

import pytest

from app.service.classroom import store
from tests.browser.test_classroom import (
    DESK,
    PHONE,
    classes,  # noqa: F401 - the module's classes in a database of their own
)

pytestmark = pytest.mark.browser

SPRING = {"coordinates": ["x"], "parameters": ["m", "k"], "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}
NO_KEY = "Type the recovery code or the instructor key you were given when you made the class"


def _teacher(browser, live_server, size=DESK):
    context = browser.new_context(base_url=live_server, **size)
    page = context.new_page()
    page.set_default_timeout(60_000)
    page.errors = []
    page.on("pageerror", lambda exc: page.errors.append(str(exc)))
    return context, page


def _status(page, which: str) -> str:
    return page.locator(f"#{which}").inner_text().strip()


@pytest.mark.slow
def test_refusals_are_said_in_words_at_the_box_they_concern(browser, live_server, classes, artifacts):  # noqa: F811
    context, page = _teacher(browser, live_server)
    made = page.request.post("/api/classes", data={"title": "Mechanics II, Tuesday"}).json()
    code = made["code"]

    # a teacher link cut short, as mail programs do: the recovery code is incomplete
    page.goto(f"/teach#class={code}&recover={made['recovery_code'][:4]}")
    page.wait_for_function("document.getElementById('start-status').textContent.length > 0")
    said = _status(page, "start-status")
    assert said.startswith("This recovery code is incomplete: it has 4 of its 24 letters and digits"), said
    assert "Bearer" not in said
    # cut before its recovery code: the class code is filled in, and the page says what is missing
    page.goto("about:blank")
    page.goto(f"/teach#class={code}")
    page.wait_for_function("document.getElementById('start-status').textContent.length > 0")
    assert _status(page, "start-status").startswith("This teacher link is incomplete: it has no recovery code.")
    assert page.locator("#open-code").input_value() == code
    # the class code alone: nothing to open it with
    page.locator("#start-status").evaluate("e => e.textContent = ''")
    page.click("#open-form button[type=submit]")
    assert _status(page, "start-status").startswith(NO_KEY)

    # opened with the recovery code, as typed from paper
    page.fill("#open-recovery", made["recovery_code"])
    page.click("#open-form button[type=submit]")
    page.wait_for_selector("#class-live:not([hidden])")
    # no assignment: a sentence beside the list, not its item 1
    assert page.locator("#assign-series li").count() == 0
    assert page.locator("#assign-none").is_visible()

    # nothing ticked, nothing typed: said before asking the server
    page.click("#assign-save")
    assert _status(page, "assign-status") == "Tick at least one scene or add a typed system."

    # a typed system with a syntax error: at the system's box, in words, not beside "Add this assignment"
    page.click("#assign-system-box summary")
    page.fill("#assign-system-name", "spring")
    page.fill("#assign-system", json.dumps({**SPRING, "potential": "k*(x**2/2"}))
    page.click("#assign-system-load")
    page.wait_for_function("document.getElementById('assign-system-status').textContent.startsWith('The potential U:')")
    said = _status(page, "assign-system-status")
    assert "never closed" in said and "system.potential" not in said, said
    page.click("#assign-save")
    page.wait_for_function("document.getElementById('assign-system-status').textContent.startsWith('The potential U:')")
    assert _status(page, "assign-status") == ""
    page.screenshot(path=artifacts / "teach-system-refused-1366.png")
    # corrected: the old refusal goes and the steps come
    page.fill("#assign-system", json.dumps(SPRING))
    page.click("#assign-system-load")
    page.wait_for_selector('#assign-system-steps input[data-step="kinetic"]')
    assert _status(page, "assign-system-status") == ""

    # no set-up: said at the system's box before anything is sent
    page.click("#assign-save")
    assert _status(page, "assign-system-status").startswith("Write the system's set-up: what each coordinate is")
    page.fill("#assign-system-setup", "x is the stretch of the spring from its natural length; U = 0 at x = 0.")
    # no step ticked: every step of the system, as for a scene
    page.click("#assign-save")
    page.wait_for_function("document.getElementById('assign-status').textContent.startsWith('Added: 1.')")
    offered = page.locator("#assign-system-steps li").count()
    assert offered == 0  # the editor is cleared for the next assignment
    series = page.request.get(f"/api/classes/{code}/assignments",
                              headers={"Authorization": f"Bearer {made['teacher_key']}"}).json()["assignments"]
    steps = [s["step"] for s in series[0]["items"][0]["steps"]]
    practice = page.request.post("/api/practice", data=SPRING).json()
    assert steps == [e["step"] for e in practice["exercises"]] and "kinetic" in steps and "potential" in steps

    # the list: no numbered empty state, no "due —", the steps named, a Delete that says it asks first
    entry = page.locator("#assign-series .assign-entry")
    page.wait_for_function("!document.querySelector('#assign-series .assign-item-steps').textContent.includes('…')")
    text = entry.inner_text().replace("\xa0", " ")
    assert not page.locator("#assign-none").is_visible()
    assert "no due date" in text and "due —" not in text
    assert "spring:" in text and "equation of motion for" in text, text
    button = entry.locator("button[data-delete]")
    assert button.inner_text() == "Delete…" and "asks first" in button.get_attribute("aria-label")
    page.screenshot(path=artifacts / "teach-assignments-1366.png", full_page=True)
    assert page.errors == []
    context.close()


def _class_with_answers(room):
    """Two students on the simple pendulum's steps (Ada last got the equation of motion for θ right); the double
    pendulum's T, also assigned, answered by nobody."""
    db = room.db
    code, key, _recovery = store.create_class(db, "Mechanics II, Tuesday")
    class_id = store.access(db, code, key).class_id
    store.set_first(db, class_id, [
        {"item": "simple-pendulum", "system": None, "parameters": {},
         "steps": [{"step": "kinetic", "coordinate": None}, {"step": "equation", "coordinate": "theta"}]},
        {"item": "double-pendulum", "system": None, "parameters": {},
         "steps": [{"step": "kinetic", "coordinate": None}]}])
    first = store.series(db, class_id)[0]["id"]
    ada, bo = (store.join(db, code, name)[1] for name in ("Ada", "Bo"))
    store.record(db, bo, "simple-pendulum", "kinetic", None, "incorrect", None, "m*g", assignment_id=first)
    store.record(db, ada, "simple-pendulum", "kinetic", None, "correct", None, "T", assignment_id=first)
    store.record(db, bo, "simple-pendulum", "kinetic", None, "correct", None, "T", assignment_id=first)
    store.record(db, ada, "simple-pendulum", "equation", "theta", "correct", None, "E", assignment_id=first)
    return code, key


@pytest.mark.slow
@pytest.mark.parametrize("size", ["1366", "390"])
def test_the_first_screen_says_who_is_done(browser, live_server, classes, artifacts, size):  # noqa: F811
    context, page = _teacher(browser, live_server, DESK if size == "1366" else PHONE)
    assert page.request.post("/api/classes", data={"title": "first"}).status == 201  # the classroom starts
    code, key = _class_with_answers(classes[0])
    page.goto("/teach")
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(json.dumps({'code': code, 'key': key, 'title': 'M'}))})")
    page.reload()
    page.click("#names-shown")  # the names are hidden as the dashboard opens
    page.wait_for_selector("#dash-students tbody tr .dash-last .katex")
    height = DESK["viewport"]["height"] if size == "1366" else PHONE["viewport"]["height"]
    width = DESK["viewport"]["width"] if size == "1366" else PHONE["viewport"]["width"]

    # who is done, on the first screen (a desk's and a phone's)
    done = page.locator("#dash-assignments tbody tr .dash-done")
    assert done.inner_text() == "0 of 2"  # nobody has answered the double pendulum's T yet
    box = done.bounding_box()
    assert box is not None and box["y"] + box["height"] <= height, box

    # the step cards: the bar counts students, each once by their best answer (Bo's wrong T then right is one
    # student right), labelled with its one unit in words and in its aria-label; the step nobody answered behind
    # "Show every step"
    numbers = page.locator(".dash-step .dash-numbers").all_inner_texts()
    assert sorted(numbers) == ["1 of 2 students done, 0 stuck", "2 of 2 students done, 0 stuck"], numbers
    bars = page.locator(".dash-step .dash-bar-row").all_inner_texts()
    assert sorted(" ".join(b.split()) for b in bars) == ["Students 1 right, 0 wrong", "Students 2 right, 0 wrong"], bars
    said = sorted(page.locator(".dash-step .dash-bar").evaluate_all("bars => bars.map(b => b.getAttribute('aria-label'))"))
    assert said == ["Students who answered this step, of 2 students: 1 right, 0 wrong (green: right, red: wrong)",
                    "Students who answered this step, of 2 students: 2 right, 0 wrong (green: right, red: wrong)"], said
    legend = " ".join(page.locator(".dash-legend").inner_text().split())
    assert "counts the students who answered its step" in legend and "stuck: answered, not right yet" in legend
    toggle = page.locator("#dash-steps-all")
    assert toggle.inner_text() == "Show every step (1 more not answered yet)"
    toggle.click()
    page.wait_for_function("document.querySelectorAll('.dash-step').length === 3")
    last = " ".join(page.locator(".dash-step").last.inner_text().split())
    assert "0 right, 0 wrong" in last and "0 of 2 students done, 0 stuck" in last, last
    toggle.click()
    page.wait_for_function("document.querySelectorAll('.dash-step').length === 2")

    # each student's last step, by its name as the page prints it, whole within the screen's width
    ada = page.locator("#dash-students tbody tr", has=page.locator("th", has_text="Ada")).locator(".dash-last")
    text = ada.inner_text().replace("\xa0", " ")
    assert re.search(r"equation of motion for", text) and "(theta)" not in text and "✓ done" in text, text
    box = ada.bounding_box()
    assert box is not None and box["x"] >= 0 and box["x"] + box["width"] <= width, box
    assert page.evaluate("document.documentElement.scrollWidth") <= width
    page.screenshot(path=artifacts / f"teach-who-is-done-{size}.png", full_page=True)
    assert page.errors == []
    context.close()


@pytest.mark.slow
def test_the_dashboard_says_loading_until_its_figures_arrive(browser, live_server, classes, artifacts):  # noqa: F811
    context, page = _teacher(browser, live_server)
    assert page.request.post("/api/classes", data={"title": "first"}).status == 201  # the classroom starts
    code, key = _class_with_answers(classes[0])
    held = []  # the summary's requests, held until the loading state is seen
    page.route("**/api/classes/*/summary", lambda route: route.continue_() if held and held[-1] is None
               else held.append(route))
    page.goto("/teach")
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(json.dumps({'code': code, 'key': key, 'title': 'M'}))})")
    page.reload()
    page.wait_for_function("document.getElementById('class-live') && !document.getElementById('class-live').hidden")
    page.wait_for_timeout(300)
    assert held, "the dashboard asked for no summary"
    # no empty table that reads as "nobody has done anything": every table and list says it is loading
    for where in ("#dash-assignments tbody", "#dash-students tbody", "#dash-steps", "#dash-mistakes",
                  "#now-stuck .now-body", "#now-mistake .now-body", "#dash-counts"):
        assert page.locator(where).inner_text().strip() == "Loading…", where
    waiting = list(held)
    held.append(None)  # the later polls pass
    for route in waiting:
        route.continue_()
    page.wait_for_selector("#dash-assignments tbody tr .dash-done")
    assert page.locator(".dash-loading").count() == 0
    assert page.errors == []
    context.close()


def test_a_whole_teacher_link_pasted_after_a_cut_one_opens_the_class(browser, live_server, classes):  # noqa: F811
    # inst-b 18: after a cut link, the whole link pasted into the same tab changed only the fragment, and the page
    # stayed on "Start a class" with the old message
    context, page = _teacher(browser, live_server)
    made = page.request.post("/api/classes", data={"title": "Mechanics II"}).json()
    page.goto(f"/teach#class={made['code']}&recover={made['recovery_code'][:4]}")
    page.wait_for_function("document.getElementById('start-status').textContent.length > 0")
    assert _status(page, "start-status").startswith("This recovery code is incomplete")
    page.evaluate("(h) => { window.location.hash = h; }", f"class={made['code']}&recover={made['recovery_code']}")
    page.wait_for_selector("#class-live:not([hidden])")
    assert page.locator("#class-code").inner_text() == made["code"]
    assert page.errors == []
    context.close()


def test_a_pseudonym_of_spaces_is_asked_for_in_the_forms_words(browser, live_server, classes):  # noqa: F811
    # inst-b 4: "name: String should have at least 1 character"; student-f 25: an earlier message stayed
    context, page = _teacher(browser, live_server, PHONE)
    made = page.request.post("/api/classes", data={"title": "Mechanics II"}).json()
    page.goto("/join?code=AAAAAA")
    page.fill("#join-name", "ana")
    page.click("#join-form button[type=submit]")
    page.wait_for_function("document.getElementById('join-status').textContent.includes('AAAAAA')")
    page.fill("#join-code", made["code"])
    page.fill("#join-name", "   ")
    page.click("#join-form button[type=submit]")
    said = _status(page, "join-status")
    assert said.startswith("Type a pseudonym") and "String" not in said and "AAAAAA" not in said
    assert page.errors == []
    context.close()
