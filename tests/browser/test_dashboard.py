"""The instructor's first screen answers "which step is the class stuck on, and which mistake" (issue 44, item 5).

A class of six is scripted into the record (answers as a check records them): on the double pendulum's U four
students are stuck with the sign of U, on the simple pendulum's U two more make the same slip, and on the double
pendulum's T two are stuck with the cross term forgotten while three are done.  At 1366×768 (and on a projector
at 1024×768), without scrolling, the dashboard names the double pendulum's U as the step most are stuck on and
"The sign of U" (its case kept), totalled over both scenes, as the most common mistake with its count, 6×; one
click shows the students concerned, once the teacher shows the names (hidden as the page opens, and again after
every reload).  Projector mode enlarges the type, the code (in large type) and its QR code (240 px at least), and both cards stay whole on a 1024×768 screen.  An answer recorded later shows without
a reload.  And a student's side of a busy lecture hall: /join brings the session cookie, and a join refused
with 429 is tried again after its Retry-After, the wait shown.
"""

from __future__ import annotations

import json

import pytest

from app.main import app
from app.service.classroom import store
from app.service.classroom.service import Classroom
from app.settings import Settings
from app.web.api.classes import classroom as classroom_dep
from app.web.api.deps import ServicesDep
from tests.browser.conftest import busy_once
from tests.browser.test_classroom import teacher_page

pytestmark = pytest.mark.browser

SIGN = ("potential.sign", "The sign of U")  # (the tutor's key, its words); U is a symbol: the case stays
CROSS = ("kinetic.cross_term.theta1_dot.theta2_dot", "the cross term m₂ l₁ l₂ θ̇₁ θ̇₂ cos(θ₁ − θ₂)")


@pytest.fixture(scope="module")
def classes(tmp_path_factory):
    made: list[Classroom] = []

    async def own(running: ServicesDep) -> Classroom:
        if not made:
            made.append(Classroom(running.checking, Settings(data_dir=tmp_path_factory.mktemp("dashboard"))))
        return made[0]

    app.dependency_overrides[classroom_dep] = own
    yield made
    app.dependency_overrides.pop(classroom_dep, None)
    for room in made:
        room.stop()


def _scripted_class(room: Classroom) -> tuple[str, str, list[store.Access]]:
    db = room.db
    code, key, _recovery = store.create_class(db, "Mechanics II, Tuesday")
    items = [{"item": "double-pendulum", "system": None, "parameters": {},
              "steps": [{"step": "kinetic", "coordinate": None}, {"step": "potential", "coordinate": None}]},
             {"item": "simple-pendulum", "system": None, "parameters": {},
              "steps": [{"step": "potential", "coordinate": None}]}]
    class_id = store.access(db, code, key).class_id
    store.set_first(db, class_id, items)
    first = store.series(db, class_id)[0]["id"]
    people = [store.join(db, code, name)[1] for name in ("Ada", "Bo", "Cy", "Di", "Ed", "Flo")]
    wrong = lambda who, item, step, mistake: store.record(db, who, item, step, None, "incorrect", mistake[0], "x",  # noqa: E731
                                                          mistake[1], assignment_id=first)
    for who in people[:4]:
        wrong(who, "double-pendulum", "potential", SIGN)
    for who in people[4:]:
        wrong(who, "simple-pendulum", "potential", SIGN)
    for who in people[:2]:
        wrong(who, "double-pendulum", "kinetic", CROSS)
    for who in people[2:5]:
        store.record(db, who, "double-pendulum", "kinetic", None, "correct", None, "T", assignment_id=first)
    return code, key, people


def _within_first_screen(page, selector: str, height: int) -> None:
    box = page.locator(selector).bounding_box()
    assert box is not None and box["y"] >= 0 and box["y"] + box["height"] <= height, (selector, box)


def _dashboard_of_scripted_class(page, room):
    """The scripted class's dashboard opened as its lecturer reopens it (the class kept in this browser)."""
    page.goto("/teach")
    code, key, people = _scripted_class(room)
    kept = json.dumps({"code": code, "key": key, "title": "Mechanics II, Tuesday"})
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(kept)})")
    page.reload()
    return code, key, people


def test_the_first_screen_names_the_stuck_step_and_the_mistake(browser, live_server, classes, artifacts):
    context, page, errors = teacher_page(browser, live_server)
    room = classes[0]
    code, key, people = _dashboard_of_scripted_class(page, room)
    page.wait_for_selector("#now-stuck[data-step]")
    page.wait_for_selector("#now-mistake[data-count]")
    assert page.evaluate("window.scrollY") == 0

    stuck, mistake = page.locator("#now-stuck"), page.locator("#now-mistake")
    assert stuck.get_attribute("data-step") == "potential"
    assert "Double pendulum" in stuck.inner_text() and "4 of 6 stuck" in stuck.inner_text()
    # the step by its symbol: U as typeset (KaTeX's italic 𝑈), or as plain text before the fonts arrive
    assert stuck.locator(".now-what").inner_text().split()[0] in ("U", "\N{MATHEMATICAL ITALIC CAPITAL U}")
    assert mistake.get_attribute("data-count") == "6"
    assert "The sign of U" in mistake.inner_text() and "6 students" in mistake.inner_text()  # totalled over two scenes
    for selector in ("#now-stuck .now-what", "#now-stuck .now-figure", "#now-mistake .now-what",
                     "#now-mistake .now-figure"):
        _within_first_screen(page, selector, 768)
    # the short link and its QR code, drawn by this server, beside the code for a slide or a projector
    assert page.locator("#class-short-link").inner_text().endswith(f"/j/{code}")
    page.wait_for_function("() => { const i = document.getElementById('class-qr'); return i.complete && i.naturalWidth > 0; }")
    _within_first_screen(page, "#class-qr", 768)
    page.screenshot(path=artifacts / "teach-first-screen-1366.png")

    # the names are hidden as the page opens (a dashboard projected as it opens names nobody): counts only
    assert page.locator("#now-stuck .now-who").is_hidden() and page.locator("#dash-students").is_hidden()
    assert "names are hidden" in page.locator(".dash-names-note").inner_text()
    page.click("#names-shown")
    assert page.locator("#names-shown").inner_text() == "Hide the students' names"
    assert page.locator("#now-stuck .now-who").is_visible() and page.locator("#dash-students").is_visible()
    page.reload()  # never remembered: a reload (on a laptop mirrored to a projector) opens with the names hidden
    page.wait_for_selector("#now-stuck[data-step]")
    assert page.locator("#now-stuck .now-who").is_hidden() and page.locator("#dash-students").is_hidden()
    assert page.locator("#names-shown").inner_text() == "Show the students' names"
    page.click("#names-shown")
    assert page.locator(".dash-names-note").is_hidden()

    # one click to the students concerned
    page.click("#now-mistake .now-who summary")
    assert page.locator("#now-mistake .now-names").inner_text() == "Ada, Bo, Cy, Di, Ed, Flo"
    page.click("#now-stuck .now-who summary")
    assert page.locator("#now-stuck .now-names").inner_text() == "Ada, Bo, Cy, Di"

    # the steps, most stuck first; mistake names keep their case
    labels = page.locator(".dash-step .dash-numbers").all_inner_texts()
    assert [t.split(" stuck")[0].split(", ")[-1] for t in labels] == ["4", "2", "2"]
    assert page.locator(".dash-mistake").first.locator("strong").inner_text() == "The sign of U"

    # live: an answer recorded now shows without a reload (Ada gets U right: 3 stuck)
    first = store.series(room.db, people[0].class_id)[0]["id"]
    store.record(room.db, people[0], "double-pendulum", "potential", None, "correct", None, "U", assignment_id=first)
    page.wait_for_function("document.querySelector('#now-stuck .now-figure')?.textContent.startsWith('3 of 6 stuck')",
                           timeout=10_000)

    # a projector at 1024×768, in projector mode: larger type, the answer still on the first screen
    page.set_viewport_size({"width": 1024, "height": 768})
    plain = page.eval_on_selector("#now-mistake .now-what", "e => parseFloat(getComputedStyle(e).fontSize)")
    page.click("#projector")
    large = page.eval_on_selector("#now-mistake .now-what", "e => parseFloat(getComputedStyle(e).fontSize)")
    assert large >= 1.4 * plain
    page.evaluate("window.scrollTo(0, 0)")
    # the whole of both cards (the step, its count, the mistake, its count, where) on the first screen
    for selector in ("#now-stuck", "#now-mistake"):
        _within_first_screen(page, selector, 768)
    page.screenshot(path=artifacts / "teach-projector-1024.png")
    # projected, the code stays large enough for the back of the room, and going onto the projector hid the names
    code_px = page.eval_on_selector("#class-code", "e => parseFloat(getComputedStyle(e).fontSize)")
    assert code_px >= 72, code_px
    # and the QR code is large enough to scan from the back rows (240 px at least, not the page's 96)
    qr_px = page.eval_on_selector("#class-qr", "e => e.getBoundingClientRect().width")
    assert qr_px >= 240, qr_px
    assert page.locator("#now-stuck .now-who").is_hidden() and page.locator("#dash-students").is_hidden()
    # scrolled down to a step's row, the code and its QR code stay in a corner for a latecomer; back up, only the banner
    assert page.locator("#code-badge").is_hidden()
    page.locator("#dash-assignments").scroll_into_view_if_needed()
    page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
    page.wait_for_function("document.body.classList.contains('banner-away')", timeout=5_000)
    badge = page.locator("#code-badge").bounding_box()
    assert badge and badge["y"] >= 0 and badge["y"] + badge["height"] <= 768 and badge["x"] + badge["width"] <= 1024
    assert page.locator("#code-badge-code").inner_text() == code
    assert page.eval_on_selector("#code-badge-qr", "e => e.naturalWidth > 0 && e.getBoundingClientRect().width >= 120")
    page.screenshot(path=artifacts / "teach-projector-scrolled-1024.png")
    page.evaluate("window.scrollTo(0, 0)")
    page.wait_for_function("!document.body.classList.contains('banner-away')", timeout=5_000)
    assert page.locator("#code-badge").is_hidden()
    stuck = page.locator('#dash-assignments tr[data-assignment="1"] .dash-stuck')
    assert stuck.locator(".dash-names").is_hidden()
    assert page.evaluate("getComputedStyle(document.querySelector("
                         "'#dash-assignments tr[data-assignment=\"1\"] .dash-stuck'), '::before').content") == '"6 students"'
    # the names' switch is not the twin of "Leave projector mode": apart from it, another size and colour
    leave, names = page.locator("#projector").bounding_box(), page.locator("#names-shown").bounding_box()
    assert leave and names and abs(names["y"] - leave["y"]) > 2 * leave["height"]
    look = "e => { const s = getComputedStyle(e); return [s.backgroundColor, s.fontSize]; }"
    leave_look, names_look = page.eval_on_selector("#projector", look), page.eval_on_selector("#names-shown", look)
    assert leave_look[0] != names_look[0] and leave_look[1] != names_look[1], (leave_look, names_look)
    page.click("#names-shown")
    assert page.locator("#now-stuck .now-who").is_visible() and page.locator("#dash-students").is_visible()
    assert stuck.locator(".dash-names").is_visible()
    page.click("#projector")  # leaving projector mode keeps the teacher's choice
    assert page.locator("#projector").inner_text() == "Projector mode" and page.locator("#dash-students").is_visible()
    assert errors == []
    context.close()


def test_on_a_phone_the_students_table_header_lines_up_with_its_rows(browser, live_server, classes, artifacts):
    """At 390 px each student is a short grid row (name, steps done, shown, score; the last step and last activity
    under them): the header's cells sit over the rows' cells, column by column, whatever each row's numbers."""
    context, page, errors = teacher_page(browser, live_server)
    page.set_viewport_size({"width": 390, "height": 844})
    _dashboard_of_scripted_class(page, classes[0])
    page.wait_for_selector("#dash-students tbody tr:not(.dash-loading)", state="attached")
    page.click("#names-shown")
    page.locator("#dash-students").scroll_into_view_if_needed()
    page.screenshot(path=artifacts / "teach-students-390.png", full_page=True)
    lefts = page.evaluate("""() => [...document.querySelectorAll('#dash-students tr')].map(
        tr => [...tr.children].slice(1, 4).map(c => Math.round(c.getBoundingClientRect().left)))""")
    head, *rows = lefts
    assert len(rows) == 6
    for row in rows:
        assert all(abs(a - b) <= 1 for a, b in zip(head, row, strict=True)), (head, row)
    assert errors == []
    context.close()


def test_the_join_page_brings_a_session_and_waits_out_a_busy_minute(browser, live_server, classes, artifacts):
    """/join sets the session cookie before the student joins; a join answered 429 with Retry-After is tried
    again after that wait, counted down on the page, and then goes through."""
    context = browser.new_context(base_url=live_server, viewport={"width": 390, "height": 844})
    page = context.new_page()
    page.set_default_timeout(60_000)
    code = page.request.post("/api/classes", data={"title": "Busy minute"}).json()["code"]
    # the first try meets a full minute
    refused = busy_once(
        page, "**/api/classes/*/join", 2, "joins from your network address: at most 300 a minute; try again in 2 s"
    )
    page.goto(f"/join?code={code}")
    assert any(c["name"] == "lagrange_session" for c in context.cookies())  # the session, before joining
    page.fill("#join-name", "Ada")
    page.click("#join-form button[type=submit]")
    page.wait_for_function("document.getElementById('join-status').textContent.includes('Trying again in')")
    assert "Many are joining at once" in page.locator("#join-status").inner_text()
    page.wait_for_selector("#join-live:not([hidden])", timeout=15_000)
    assert len(refused) == 1 and page.locator("#joined-name").inner_text() == "Ada"
    context.close()
