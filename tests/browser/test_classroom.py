"""The classroom in headless Chromium: an instructor's page and three students' pages (one a phone); a wrong
answer shows on the dashboard with its named mistake within 5 s."""

from __future__ import annotations

import time

import pytest

from app.main import app
from app.service.classroom.service import Classroom
from app.settings import Settings
from app.web.api.classes import classroom as classroom_dep
from app.web.api.deps import ServicesDep

pytestmark = pytest.mark.browser

SCENE = "double-pendulum"
RIGHT_T = "m1*l1**2*theta1_dot**2/2 + m2*(l1**2*theta1_dot**2 + l2**2*theta2_dot**2 + 2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2))/2"
NO_CROSS_T = "m1*l1**2*theta1_dot**2/2 + m2*(l1**2*theta1_dot**2 + l2**2*theta2_dot**2)/2"  # the cross term forgotten
CROSS = "kinetic.cross_term.theta1_dot.theta2_dot"  # the tutor's stable key for that mistake
PHONE = {"viewport": {"width": 390, "height": 844}, "is_mobile": True, "has_touch": True, "device_scale_factor": 2}
DESK = {"viewport": {"width": 1366, "height": 768}}


@pytest.fixture(scope="module")
def classes(tmp_path_factory):
    """The live server's classes in a database of their own."""
    made: list[Classroom] = []

    async def own(running: ServicesDep) -> Classroom:
        if not made:
            made.append(Classroom(running.checking, Settings(data_dir=tmp_path_factory.mktemp("classes"))))
        return made[0]

    app.dependency_overrides[classroom_dep] = own
    yield made
    app.dependency_overrides.pop(classroom_dep, None)
    for room in made:
        room.stop()


def _errors_of(page) -> list[str]:
    page.console_errors = []
    page.on("console", lambda msg: page.console_errors.append(msg.text) if msg.type == "error" else None)
    page.on("pageerror", lambda exc: page.console_errors.append(f"uncaught: {exc}"))
    return page.console_errors


def phone_page(browser, live_server):
    """A fresh phone (its own cookies) on the live server: its context, its page and the page's errors."""
    context = browser.new_context(base_url=live_server, **PHONE)
    page = context.new_page()
    page.set_default_timeout(60_000)
    return context, page, _errors_of(page)


def teacher_page(browser, live_server):
    """A lecturer's laptop at 1366×768 on the live server, the classroom started: its context, page and the page's
    uncaught errors (a refused request's console line is what some of these tests ask for)."""
    context = browser.new_context(base_url=live_server, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    page.set_default_timeout(60_000)
    errors: list[str] = []
    page.on("pageerror", lambda exc: errors.append(str(exc)))
    assert page.request.post("/api/classes", data={"title": "first"}).status == 201  # the classroom starts
    return context, page, errors


def _student(browser, live_server, code: str, name: str, device: dict):
    context = browser.new_context(base_url=live_server, **device)
    page = context.new_page()
    page.set_default_timeout(60_000)
    errors = _errors_of(page)
    page.goto(f"/join?code={code}")
    assert page.locator("#join-code").input_value() == code
    page.fill("#join-name", name)
    page.click("#join-form button[type=submit]")
    page.wait_for_selector('.practice-step[data-step="kinetic"] textarea')
    return context, page, errors


def _answer(page, text: str) -> str:
    step = page.locator('.practice-step[data-step="kinetic"]')
    step.locator("textarea").fill(text)
    step.locator("textarea").press("Enter")
    step.locator(".practice-verdict[data-verdict]").wait_for()
    return step.locator(".practice-verdict").get_attribute("data-verdict")


def test_a_class_live(browser, live_server, classes, artifacts):
    teacher_context = browser.new_context(base_url=live_server, **DESK)
    teacher = teacher_context.new_page()
    teacher.set_default_timeout(60_000)
    teacher_errors = _errors_of(teacher)
    teacher.goto("/teach")
    teacher.fill("#create-title", "Mechanics II")
    teacher.click("#create-form button[type=submit]")
    teacher.wait_for_selector("#class-live:not([hidden])")
    teacher.click("#names-shown")  # the names are hidden as the dashboard opens
    code = teacher.locator("#class-code").inner_text()
    assert len(code) == 6
    # the code is projected large: at least 2.8 rem
    assert float(teacher.eval_on_selector("#class-code", "e => parseFloat(getComputedStyle(e).fontSize)")) >= 44

    # the assignment: the double pendulum's T and U
    teacher.check(f"#assign-{SCENE}")
    teacher.wait_for_selector(f'#assign-{SCENE} ~ .assign-steps input[data-step="kinetic"]')
    teacher.check(f'#assign-{SCENE} ~ .assign-steps input[data-step="kinetic"]')
    teacher.check(f'#assign-{SCENE} ~ .assign-steps input[data-step="potential"]')
    teacher.click("#assign-save")
    teacher.wait_for_function("document.getElementById('assign-status').textContent.startsWith('Added')")

    students = [_student(browser, live_server, code, name, device)
                for name, device in (("Ada", PHONE), ("Bo", DESK), ("Cy", DESK))]
    (_, ada, _), (_, bo, _), (_, cy, _) = students
    assert ada.locator(".practice-step").count() == 2  # the two assigned steps
    # the scene's set-up opens in practice mode in a tab of its own, its derivation hidden (inst-b 24)
    setup = ada.locator(f'a[href="/scenes/{SCENE}#practice=on"]')
    assert setup.count() == 1 and setup.get_attribute("target") == "_blank"

    # the answer typeset as it is typed, by the checker's reading, before it is sent (inst-b 25, student-f 22)
    kinetic = ada.locator('.practice-step[data-step="kinetic"]')
    kinetic.locator("textarea").fill("1/2 m1 l1^2 theta1'^2")
    kinetic.locator(".practice-preview .katex").wait_for()
    assert kinetic.locator(".practice-preview-note").inner_text() == ""
    kinetic.locator("textarea").fill("m1 (")
    ada.wait_for_function(
        "document.querySelector('.practice-step[data-step=\"kinetic\"] .practice-preview-note').textContent"
        ".startsWith('Not read yet: ')")
    assert kinetic.locator(".practice-preview .katex").count() == 0
    # the typesetter's 422 for that unfinished text is the browser's note of a refused request, no page error
    ada_errors = students[0][2]
    ada_errors[:] = [e for e in ada_errors if "status of 422" not in e]

    assert _answer(ada, NO_CROSS_T) == "incorrect"
    answered = time.monotonic()
    teacher.wait_for_selector(f'.dash-mistake[data-mistake="{CROSS}"]', timeout=5000)
    shown_after = time.monotonic() - answered
    mistake = teacher.locator(f'.dash-mistake[data-mistake="{CROSS}"]')
    # the tutor's own words for it (issue 28), as the student read them
    assert "the cross term" in mistake.inner_text() and mistake.locator(".katex").count() == 1  # T typeset

    assert _answer(bo, RIGHT_T) == "correct"
    # the verdict said once ("Correct: this is …", never "Correct Correct: …"); the names as typed and as printed
    step = bo.locator('.practice-step[data-step="kinetic"]')
    said = step.locator(".practice-verdict p").first.inner_text()
    assert said.startswith("Correct: this is") and "Correct Correct" not in said
    names = step.locator(".practice-names")
    # what the box takes first, in the scene page's words (student-f 23)
    assert names.inner_text().startswith("Type only the right-hand side. Names you may use: ")
    assert names.locator(".katex").count() >= 2
    assert _answer(cy, NO_CROSS_T) == "incorrect"
    teacher.wait_for_function(
        f"document.querySelector('.dash-mistake[data-mistake=\"{CROSS}\"] .dash-count')?.textContent === '2 students'",
        timeout=5000)
    teacher.wait_for_function("document.getElementById('dash-counts').textContent.startsWith('3 students · 3 answers')",
                              timeout=5000)
    rows = teacher.locator("#dash-students tbody tr")
    bo_row = teacher.locator('#dash-students tbody tr[data-student="Bo"]')
    assert rows.count() == 3 and "1 of 2" in bo_row.inner_text()  # Bo did one of the two steps
    assert ada.locator("#joined-progress").inner_text() == "0 of 2 steps done"
    assert bo.locator("#joined-progress").inner_text() == "1 of 2 steps done"

    # a reload keeps the student in the class with their progress
    bo.reload()
    bo.wait_for_selector(".practice-step.step-done")
    assert bo.locator("#joined-progress").inner_text() == "1 of 2 steps done"

    # two answers sent at once (T, then U before T's verdict): the second waits for the first on the page, and both
    # get a verdict, never "Busy" (inst-b 9: the second was turned away while the first was being checked)
    for key, text in (("kinetic", NO_CROSS_T), ("potential", "m1*g*l1")):
        step = ada.locator(f'.practice-step[data-step="{key}"]')
        step.locator("textarea").fill(text)
        step.locator("textarea").press("Enter")
    for key in ("kinetic", "potential"):
        verdict = ada.locator(f'.practice-step[data-step="{key}"] .practice-verdict[data-verdict]')
        verdict.wait_for()
        assert verdict.get_attribute("data-verdict") == "incorrect", verdict.inner_text()

    teacher.screenshot(path=artifacts / "teach-1366.png", full_page=True)
    teacher.set_viewport_size({"width": 390, "height": 844})
    teacher.screenshot(path=artifacts / "teach-390.png", full_page=True)
    ada.screenshot(path=artifacts / "join-390.png", full_page=True)
    cy.screenshot(path=artifacts / "join-1366.png", full_page=True)
    print(f"the wrong answer showed on the dashboard after {shown_after:.2f} s")

    for _, _page, errors in students:
        assert errors == []
    assert teacher_errors == []
    for context, _, _ in students:
        context.close()
    teacher_context.close()
