"""Two items of an instructor's review (inst-b), on a phone: a class that asks for the students' institution login
(12: the join form asks for it, the dashboard shows it, the grades file keys rows by it), and a typed system's ω²
step (10: it names its equilibrium, and its shown answer says which are stable and where they exist, within the
phone's width)."""

from __future__ import annotations

import csv
import io
import json

import pytest

from app.web.api.examples_user import SPINNING_HOOP
from tests.browser.test_classroom import (
    DESK,
    PHONE,
    _errors_of,
    classes,  # noqa: F401 - the module's classes in a database of their own
)

pytestmark = pytest.mark.browser


def _page(browser, live_server, device):
    context = browser.new_context(base_url=live_server, **device)
    page = context.new_page()
    page.set_default_timeout(60_000)
    return context, page, _errors_of(page)


def test_the_join_form_asks_for_the_login_the_class_asks_for(browser, live_server, classes, artifacts):  # noqa: F811
    teach_context, teach, teach_errors = _page(browser, live_server, DESK)
    teach.goto("/teach")
    teach.fill("#create-title", "Mechanics II")
    teach.select_option("#create-login", "SIS Login ID")
    teach.click("#create-form button[type=submit]")
    teach.wait_for_function("document.getElementById('class-code').textContent.trim().length === 6")
    code = teach.locator("#class-code").inner_text().strip()
    assert teach.locator("#class-login").input_value() == "SIS Login ID"

    context, page, errors = _page(browser, live_server, PHONE)
    page.goto(f"/join?code={code}")
    assert page.locator("#join-login-field").is_hidden()
    page.fill("#join-name", "Ada L.")
    page.click("#join-form button[type=submit]")
    # the class asks: the field appears, says what to type, and has the focus
    page.wait_for_selector("#join-login-field:not([hidden])")
    said = ("This class asks for your institution login (the SIS Login ID Canvas knows you by): type it as you sign "
            "in there.")
    assert page.locator("#join-login-help").inner_text() == said
    assert page.locator("#join-status").inner_text() == "Type your institution login above, then press Join again."
    assert page.evaluate("document.activeElement.id") == "join-login"
    page.screenshot(path=artifacts / "join-login-asked-390.png")
    # pressed again empty: said, nothing sent
    page.click("#join-form button[type=submit]")
    assert page.locator("#join-status").inner_text() == "Type your institution login above first: this class asks for it."
    # a login that is no login: what is wrong, from the server
    page.evaluate("document.getElementById('join-login').value = 'ada' + String.fromCharCode(7) + 'x'")
    page.click("#join-form button[type=submit]")
    page.wait_for_function("document.getElementById('join-status').textContent.includes('without control characters')")
    assert page.locator("#join-login-help").inner_text() == said
    page.fill("#join-login", "alovelace")
    page.click("#join-form button[type=submit]")
    page.wait_for_selector("#join-recovery:not([hidden])")
    assert page.locator("#joined-name").inner_text() == "Ada L."
    assert page.evaluate("document.documentElement.scrollWidth <= window.innerWidth")

    # the dashboard shows it under the pseudonym, once the names are shown (hidden as the page opens); the grades
    # file has it first, under Canvas's header
    teach.click("#names-shown")
    row = teach.locator('#dash-students tr[data-student="Ada L."]')
    row.locator(".dash-login").wait_for()
    assert row.locator(".dash-login").inner_text() == "SIS Login ID: alovelace"
    stored = json.loads(teach.evaluate("localStorage.getItem('lagrange-teach')"))
    grades = teach.request.get(f"/api/classes/{code}/grades?format=csv",
                               headers={"Authorization": f"Bearer {stored['key']}"})
    rows = list(csv.reader(io.StringIO(grades.body().decode("utf-8-sig"))))
    assert rows == [["SIS Login ID", "Student"], ["alovelace", "Ada L."]]
    teach.locator("#dash-students").screenshot(path=artifacts / "teach-login-1366.png")
    # the instructor stops asking: a new student joins with no login field
    teach.select_option("#class-login", "")
    teach.wait_for_function("document.getElementById('data-status').textContent.includes('no longer asked')")
    second_context, second, second_errors = _page(browser, live_server, PHONE)
    second.goto(f"/join?code={code}")
    second.fill("#join-name", "bo")
    second.click("#join-form button[type=submit]")
    second.wait_for_selector("#join-recovery:not([hidden])")
    assert second.locator("#join-login-field").is_hidden()
    # the one refusal asked for (the login, a 422 the browser logs) and nothing else
    assert teach_errors == second_errors == [] and [e for e in errors if "status of 422" not in e] == []
    for each in (teach_context, context, second_context):
        each.close()


def test_the_omega_squared_step_names_its_equilibrium_and_fits_a_phone(browser, live_server, classes, artifacts):  # noqa: F811
    context, page, errors = _page(browser, live_server, PHONE)
    made = page.request.post("/api/classes", data={"title": "Hoop"}).json()
    teacher = {"Authorization": f"Bearer {made['teacher_key']}"}
    item = {"system": SPINNING_HOOP, "name": "Bead on a rotating hoop",
            "setup": "θ is the bead's angle from the hoop's lowest point; the hoop spins at w about its vertical "
                     "diameter; U = 0 at the centre.",
            "steps": [{"step": "omega_squared"}]}
    added = page.request.post(f"/api/classes/{made['code']}/assignments", headers=teacher,
                              data={"title": "Week 5", "items": [item]})
    assert added.status == 201, added.text()
    page.goto(f"/join?code={made['code']}")
    page.fill("#join-name", "cy")
    page.click("#join-form button[type=submit]")
    step = page.locator('.practice-step[data-step="omega_squared"]')
    step.wait_for(timeout=150_000)  # the typed system is derived first, in the worker pool (slow on a busy machine)
    assert step.locator("h3").inner_text() == "ω² of small oscillations about θ = 0"
    step.locator(".join-reveal").click()
    notes = step.locator(".join-step-note")
    notes.first.wait_for()
    said = " ".join(notes.all_inner_texts())
    assert "θ = 0 is stable while g > Rw²" in said and "which exist only when Rw² > g" in said
    assert "unstable" in said and "acos" not in said.replace("arccos", "") and "2π" not in said
    # nothing is cut off: every part of the shown step within its box, and the box within the phone's width
    clipped = step.locator(".practice-engine").evaluate(
        """box => [box, ...box.querySelectorAll('p, .katex-display, .katex')].filter((e) => {
             const r = e.getBoundingClientRect();
             const overflows = e.matches('.katex') ? false : e.scrollWidth > e.clientWidth + 1;
             return overflows || r.right > window.innerWidth || r.left < 0;
           }).map((e) => e.className || e.tagName)""")
    assert clipped == []
    assert page.evaluate("document.documentElement.scrollWidth <= window.innerWidth")
    step.screenshot(path=artifacts / "join-omega-squared-390.png")
    assert errors == []
    context.close()
