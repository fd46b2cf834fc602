"""The dashboard says what the grade says (review inst-c 2, 3, 12, 13).

A class of three is scripted into the record: Ada answers T and U on her own (U with its zero at the pivot, twice),
Gus presses "Show this step" on T before typing it, Bo gets T wrong.  The dashboard counts Gus's T as shown, not
done, in the step's figures, in "Who is done" and in the Students table, which carries each student's score as the
gradebook computes it and the steps shown, opens with who is behind first and sorts by score from its header; the
bars count students (Ada's two answers to U are one student), and Ada's U is said apart: right, with another zero.
"""

from __future__ import annotations

import json

import pytest

from app.service.classroom import store
from tests.browser.test_classroom import teacher_page
from tests.browser.test_dashboard import classes  # noqa: F401  (the module's classroom, on its own database)

pytestmark = pytest.mark.browser

TU = [{"item": "simple-pendulum", "system": None, "parameters": {},
       "steps": [{"step": "kinetic", "coordinate": None}, {"step": "potential", "coordinate": None}]}]
T_RIGHT, U_RIGHT, U_OTHER = "m*R**2*theta_dot**2/2", "m*g*R*(1-cos(theta))", "-m*g*R*cos(theta)"


def _scripted(room) -> tuple[str, str]:
    db = room.db
    code, key, _recovery = store.create_class(db, "Mechanics II")
    class_id = store.access(db, code, key).class_id
    store.add_assignment(db, class_id, "Week 3", None, TU)
    first = store.series(db, class_id)[0]["id"]
    ada, bo, gus = (store.join(db, code, name)[1] for name in ("Ada", "Bo", "Gus"))
    for _ in range(2):
        store.record(db, ada, "simple-pendulum", "potential", None, "equivalent", None, U_OTHER, assignment_id=first)
    store.record(db, ada, "simple-pendulum", "kinetic", None, "correct", None, T_RIGHT, assignment_id=first)
    store.record(db, gus, "simple-pendulum", "potential", None, "correct", None, U_RIGHT, assignment_id=first)
    store.record_hint(db, gus, first, "simple-pendulum", "kinetic", None)
    store.record(db, gus, "simple-pendulum", "kinetic", None, "correct", None, T_RIGHT, assignment_id=first)
    store.record(db, bo, "simple-pendulum", "kinetic", None, "incorrect", None, "m*R*theta_dot**2/2",
                 assignment_id=first)
    return code, key


def test_a_step_shown_is_not_done_and_the_table_sorts_by_score(browser, live_server, classes, artifacts):  # noqa: F811
    context, page, errors = teacher_page(browser, live_server)
    code, key = _scripted(classes[0])
    page.goto("/teach")
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(json.dumps({'code': code, 'key': key, 'title': 'M'}))})")
    page.reload()
    page.click("#names-shown")
    page.wait_for_selector("#dash-students tbody tr .dash-score")

    # who is done: Ada alone; Gus went through every step, one of them shown
    done = " ".join(page.locator('#dash-assignments tr[data-assignment="1"] .dash-done').inner_text().split())
    assert done == "1 of 3: Ada · 1 with a step shown: Gus", done

    # the steps: students, not answers; Gus's T shown, not done; Ada's U right with another zero
    steps = {" ".join(t.split()) for t in page.locator(".dash-step").all_inner_texts()}
    kinetic = next(t for t in steps if "2 right, 1 wrong" in t)
    assert "1 of 3 students done, 1 shown, 1 stuck" in kinetic, kinetic
    potential = next(t for t in steps if "1 of 3 wrote U with another zero" in t)
    assert "2 right, 0 wrong" in potential and "2 of 3 students done, 0 stuck" in potential, potential
    observation = page.locator('.dash-observation[data-observation="potential"]')
    assert observation.locator(".dash-count").inner_text() == "1 of 3"
    assert observation.locator("strong").inner_text() == "another zero of U"
    assert "(right, not a mistake) in" in observation.inner_text()

    # the Students table: who is behind first; the score as the gradebook has it; the steps shown
    def table() -> list[tuple[str, str, str, str]]:
        rows = page.locator("#dash-students tbody tr")
        return [(rows.nth(i).get_attribute("data-student"), rows.nth(i).locator("td").nth(0).inner_text(),
                 rows.nth(i).locator(".dash-shown-count").inner_text(), rows.nth(i).locator(".dash-score").inner_text())
                for i in range(rows.count())]

    assert table() == [("Bo", "0 of 2", "0", "0.0"), ("Gus", "1 of 2", "1", "50.0"), ("Ada", "2 of 2", "0", "100.0")]
    grades = page.request.get(f"/api/classes/{code}/grades", headers={"Authorization": f"Bearer {key}"}).json()
    assert {s["name"]: s["grades"][0]["score"] for s in grades["students"]} == {"Ada": 100.0, "Bo": 0.0, "Gus": 50.0}
    gus_last = page.locator('#dash-students tr[data-student="Gus"] .dash-last').inner_text()
    assert gus_last.endswith("· shown"), gus_last
    page.click("#dash-score-sort")
    page.wait_for_function("document.querySelector('#dash-score-sort').parentElement.getAttribute('aria-sort') === 'ascending'")
    assert [r[0] for r in table()] == ["Bo", "Gus", "Ada"]
    page.click("#dash-score-sort")
    page.wait_for_function("document.querySelector('#dash-score-sort').parentElement.getAttribute('aria-sort') === 'descending'")
    assert [r[0] for r in table()] == ["Ada", "Gus", "Bo"]
    page.screenshot(path=artifacts / "teach-shown-1366.png", full_page=True)
    assert errors == []
    context.close()
