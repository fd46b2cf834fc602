"""A course's assignment in headless Chromium, at 1366×768 and at 390×844 (touch): the instructor sets three steps
from two scenes and a typed system, three students answer right and wrong (one shown a step), the dashboard and the
grades CSV show their exact scores, and the instructor opens the class in a second browser with the teacher link."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest

from tests.browser.test_classroom import (
    DESK,
    PHONE,
    RIGHT_T,
    _errors_of,
    classes,  # noqa: F401 - the module's classes in a database of their own
)
from tests.browser.test_classroom import NO_CROSS_T as DOUBLE_WRONG

pytestmark = pytest.mark.browser

SIMPLE_RIGHT, SIMPLE_WRONG = "m*R**2*theta_dot**2/2", "m*R**2*theta_dot**2"
SPRING = {"coordinates": ["x"], "parameters": ["m", "k"], "kinetic": "m*x_dot**2/2", "potential": "k*x**2/2"}
SIZES = {"1366": DESK, "390": PHONE}


def _step(page, heading: str):
    return page.locator(".join-item", has=page.locator("h3", has_text=heading)).locator(".practice-step")


def _answer(page, heading: str, text: str) -> str:
    step = _step(page, heading)
    step.locator("textarea").fill(text)
    step.locator(".practice-verdict").evaluate("e => e.removeAttribute('data-verdict')")
    step.locator("textarea").press("Enter")
    step.locator(".practice-verdict[data-verdict]").wait_for()
    return step.locator(".practice-verdict").get_attribute("data-verdict")


@pytest.mark.slow
@pytest.mark.parametrize("size", list(SIZES))
def test_an_assignment_graded_and_the_class_opened_elsewhere(browser, live_server, classes, artifacts, size):  # noqa: F811
    device = SIZES[size]
    teacher_context = browser.new_context(base_url=live_server, **device)
    teacher = teacher_context.new_page()
    teacher.set_default_timeout(60_000)
    teacher_errors = _errors_of(teacher)
    teacher.goto("/teach")
    teacher.fill("#create-title", f"Mechanics II ({size})")
    teacher.click("#create-form button[type=submit]")
    teacher.wait_for_selector("#class-recovery:not([hidden])")
    code = teacher.locator("#class-code").inner_text()
    link = teacher.locator("#recovery-link").inner_text()
    recovery = teacher.locator("#recovery-code").inner_text()
    assert link == f"{live_server}/teach#class={code}&recover={recovery}"
    teacher.screenshot(path=artifacts / f"teach-recovery-{size}.png")
    teacher.click("#recovery-done")
    assert teacher.locator("#recovery-code").inner_text() == ""  # shown once
    teacher.click("#names-shown")  # the names are hidden as the dashboard opens

    # one assignment of three steps: two scenes' T and a typed system's acceleration
    teacher.fill("#assign-title-input", "Week 3: T and the spring")
    for scene in ("simple-pendulum", "double-pendulum"):
        teacher.check(f"#assign-{scene}")
        kinetic = f'#assign-{scene} ~ .assign-steps input[data-step="kinetic"]'
        teacher.wait_for_selector(kinetic)
        teacher.check(kinetic)
    teacher.click("#assign-system-box summary")
    teacher.fill("#assign-system-name", "spring")
    teacher.fill("#assign-system", json.dumps(SPRING))
    teacher.fill("#assign-system-setup", "x is the stretch of the spring from its natural length; U = 0 at x = 0.")
    teacher.click("#assign-system-load")
    teacher.check('#assign-system-steps input[data-step="acceleration"]')
    teacher.click("#assign-save")
    teacher.wait_for_function("document.getElementById('assign-status').textContent.startsWith('Added: 1.')")
    assert "Week 3: T and the spring" in teacher.locator("#assign-series").inner_text()

    students = {}
    for name in ("Ada", "Bo", "Cy"):
        context = browser.new_context(base_url=live_server, **device)
        page = context.new_page()
        page.set_default_timeout(60_000)
        errors = _errors_of(page)
        page.goto(f"/join?code={code}")
        page.fill("#join-name", name)
        page.click("#join-form button[type=submit]")
        page.wait_for_selector(".join-assignment .practice-step textarea")
        assert page.locator(".join-assignment-title").inner_text() == "1. Week 3: T and the spring"
        assert page.locator(".practice-step").count() == 3
        students[name] = (context, page, errors)
    ada, bo, cy = (students[n][1] for n in ("Ada", "Bo", "Cy"))

    # Ada: all three right at once
    assert _answer(ada, "Simple pendulum", SIMPLE_RIGHT) == "correct"
    assert _answer(ada, "Double pendulum", RIGHT_T) == "correct"
    assert _answer(ada, "spring", "-k*x/m") == "correct"
    # Bo: the simple pendulum's T wrong then right, the double pendulum's without its cross term, the spring right
    assert _answer(bo, "Simple pendulum", SIMPLE_WRONG) == "incorrect"
    assert _answer(bo, "Simple pendulum", SIMPLE_RIGHT) == "correct"
    assert _answer(bo, "Double pendulum", DOUBLE_WRONG) == "incorrect"
    assert _answer(bo, "spring", "-k*x/m") == "correct"
    # Cy: shown the spring's step, then answers it; the simple pendulum right
    _step(cy, "spring").locator(".join-reveal").click()
    _step(cy, "spring").locator(".practice-engine:not([hidden]) .katex").wait_for()
    assert _answer(cy, "spring", "-k*x/m") == "correct"
    assert _answer(cy, "Simple pendulum", SIMPLE_RIGHT) == "correct"
    assert ada.locator(".join-assignment-progress").inner_text() == "3 of 3 steps done"
    assert bo.locator(".join-assignment-progress").inner_text() == "2 of 3 steps done"

    row = teacher.locator('#dash-assignments tr[data-assignment="1"]')
    teacher.wait_for_function(
        "document.querySelector('#dash-assignments tr[data-assignment=\"1\"] .dash-stuck')?.textContent === 'Bo'",
        timeout=10_000)
    assert row.locator(".dash-done").inner_text() == "1 of 3: Ada"
    teacher.screenshot(path=artifacts / f"teach-series-{size}.png", full_page=True)
    with teacher.expect_download() as got:
        teacher.click("#grades-csv")
    assert Path(got.value.path()).read_bytes().startswith(b"\xef\xbb\xbf")  # Excel reads it as UTF-8
    rows = list(csv.reader(io.StringIO(Path(got.value.path()).read_text(encoding="utf-8-sig"))))
    week = "1. Week 3: T and the spring"
    assert rows == [["Student", f"{week} (100 points)"], ["Ada", "100.0"], ["Bo", "66.7"], ["Cy", "33.3"]]
    with teacher.expect_download() as got:
        teacher.click("#grades-details-csv")
    rows = list(csv.reader(io.StringIO(Path(got.value.path()).read_text(encoding="utf-8-sig"))))
    assert rows[0] == ["Student", f"{week} (100 points)", f"{week}: right first try", f"{week}: right",
                       f"{week}: shown", f"{week}: steps"]
    assert rows[1:] == [["Ada", "100.0", "3", "3", "0", "3"],
                        ["Bo", "66.7", "1", "2", "0", "3"],
                        ["Cy", "33.3", "1", "2", "1", "3"]]  # the spring was shown before it was answered
    for _context, page, _errors in students.values():
        page.screenshot(path=artifacts / f"join-series-{size}.png", full_page=True)
        break

    # the teacher link in another browser: the class opens there, with the same key; the fragment is wiped
    elsewhere_context = browser.new_context(base_url=live_server, **device)
    elsewhere = elsewhere_context.new_page()
    elsewhere.set_default_timeout(60_000)
    elsewhere_errors = _errors_of(elsewhere)
    elsewhere.goto(link)
    elsewhere.wait_for_selector("#class-live:not([hidden])")
    assert elsewhere.locator("#class-code").inner_text() == code
    assert elsewhere.evaluate("window.location.hash") == ""
    key = "JSON.parse(localStorage.getItem('lagrange-teach')).key"
    assert elsewhere.evaluate(key) == teacher.evaluate(key)
    elsewhere.wait_for_function(
        "document.querySelector('#dash-assignments tr[data-assignment=\"1\"] .dash-done')?.textContent === '1 of 3: Ada'",
        timeout=10_000)
    elsewhere.screenshot(path=artifacts / f"teach-elsewhere-{size}.png", full_page=True)

    for _context, _page, errors in students.values():
        assert errors == []
    assert teacher_errors == [] and elsewhere_errors == []
    for context, _page, _errors in students.values():
        context.close()
    teacher_context.close()
    elsewhere_context.close()
