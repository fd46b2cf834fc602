"""The dashboard's figures compare and add up (review instr-j 2, 4, 5; issue 44, items 1–3).

A class of twelve is scripted into the record.  On the simple pendulum's T six students answer (four right, two
wrong with the ½ left out, one of them twice) and a seventh presses "Show this step" without answering; on its U six
answer (three right, two of them with another zero of U; three wrong with the sign of U); on the double pendulum's T
two answer wrong, with nine slips between them.  At 1366×768 every step's bar has the same track, the class, and
fills in proportion to the students who answered, whatever the length of its words; the eleven named mistakes are
all there, eight listed and "and 3 more" opening the rest; a mistake's figure counts students ("2 students, 3
answers"), as its button does; the T step's line says the student shown it without answering apart; and the
students table says when each last answered ("just now", "no answer yet").
"""

from __future__ import annotations

import json

import pytest

from app.service.classroom import store
from tests.browser.test_classroom import teacher_page
from tests.browser.test_dashboard import classes  # noqa: F401  (the module's classroom, on its own database)

pytestmark = pytest.mark.browser

HALF = ("kinetic.half", "the ½ of ½ m v² left out")
SIGN = ("potential.sign", "The sign of U")
SLIPS = [(f"kinetic.slip{k}", f"slip number {k}") for k in range(1, 10)]
STEPS = [{"step": "kinetic", "coordinate": None}, {"step": "potential", "coordinate": None}]
ITEMS = [{"item": "simple-pendulum", "system": None, "parameters": {}, "steps": STEPS},
         {"item": "double-pendulum", "system": None, "parameters": {}, "steps": STEPS[:1]}]


def _scripted(room) -> tuple[str, str]:
    db = room.db
    code, key, _recovery = store.create_class(db, "Mechanics II, Tuesday practice")
    class_id = store.access(db, code, key).class_id
    store.add_assignment(db, class_id, "Week 3", None, ITEMS)
    first = store.series(db, class_id)[0]["id"]
    people = [store.join(db, code, f"S{k:02d}")[1] for k in range(12)]

    def answer(who, item, step, verdict, mistake=(None, None)):
        store.record(db, who, item, step, None, verdict, mistake[0], "x", mistake[1], assignment_id=first)

    for who in people[:4]:
        answer(who, "simple-pendulum", "kinetic", "correct")
    for who in (people[4], people[4], people[5]):  # S04 leaves the ½ out twice
        answer(who, "simple-pendulum", "kinetic", "incorrect", HALF)
    store.record_hint(db, people[6], first, "simple-pendulum", "kinetic", None)  # shown, never answered
    for who in people[:2]:
        answer(who, "simple-pendulum", "potential", "equivalent")
    answer(people[2], "simple-pendulum", "potential", "correct")
    for who in people[3:6]:
        answer(who, "simple-pendulum", "potential", "incorrect", SIGN)
    for k, slip in enumerate(SLIPS):
        answer(people[k % 2], "double-pendulum", "kinetic", "incorrect", slip)
    return code, key


def test_the_bars_share_one_scale_and_every_mistake_counts_students(browser, live_server, classes, artifacts):  # noqa: F811
    context, page, errors = teacher_page(browser, live_server)
    page.goto("/teach")
    code, key = _scripted(classes[0])
    kept = json.dumps({"code": code, "key": key, "title": "Mechanics II, Tuesday practice"})
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(kept)})")
    page.reload()
    page.wait_for_selector('.dash-step[data-step="double-pendulum|kinetic"]')
    page.click("#names-shown")

    # 1. one track for every step, the class; each filled in proportion to the students who answered it
    widths = page.evaluate("""() => Object.fromEntries([...document.querySelectorAll('.dash-step')].map((li) => {
        const px = (s) => li.querySelector(s).getBoundingClientRect().width;
        return [li.dataset.step, [px('.dash-bar'), px('.dash-good') + px('.dash-bad')]];
    }))""")
    tracks = {track for track, _filled in widths.values()}
    assert len(tracks) == 1, widths
    [track] = tracks
    expected = {"simple-pendulum|kinetic": 6, "simple-pendulum|potential": 6, "double-pendulum|kinetic": 2}
    for step, students in expected.items():
        assert abs(widths[step][1] - track * students / 12) < 1.5, (step, widths)
    words = page.locator('.dash-step[data-step="simple-pendulum|potential"] .dash-bar-words').inner_text()
    assert words == "3 right, 3 wrong · 2 of 12 wrote U with another zero"
    page.screenshot(path=artifacts / "teach-bars-1366.png", full_page=True)

    # 2. every named mistake: eight listed, the other three one click away
    mistakes = page.locator("#dash-mistakes > li.dash-mistake:not(.dash-observation)")
    assert mistakes.count() == 8
    more = page.locator("#dash-mistakes .dash-more-mistakes > summary")
    assert more.inner_text() == "and 3 more mistakes (each made by 1 student)"
    assert page.locator(".dash-more li.dash-mistake").first.is_hidden()
    more.click()
    keys = page.eval_on_selector_all("#dash-mistakes [data-mistake]", "all => all.map((e) => e.dataset.mistake)")
    assert sorted(keys) == sorted([HALF[0], SIGN[0], *(slip for slip, _ in SLIPS)])
    assert page.locator(".dash-more li.dash-mistake").last.is_visible()

    # 3. a mistake counts students, its answers apart, as its button does; the step's line adds up with its bar
    half = page.locator(f'#dash-mistakes [data-mistake="{HALF[0]}"]')
    assert half.locator(".dash-count").inner_text() == "2 students, 3 answers"
    assert half.locator(".now-who summary").inner_text() == "Show the students (2)"
    sign = page.locator(f'#dash-mistakes [data-mistake="{SIGN[0]}"]')
    assert sign.locator(".dash-count").inner_text() == "3 students"
    assert [m.split(", ")[0] for m in mistakes.locator(".dash-count").all_inner_texts()[:2]] == ["3 students", "2 students"]
    kinetic = page.locator('.dash-step[data-step="simple-pendulum|kinetic"]')
    assert kinetic.locator(".dash-bar-words").inner_text() == "4 right, 2 wrong"
    assert kinetic.locator(".dash-numbers").inner_text().startswith(
        "4 of 12 students done, 1 shown (without answering: not in the bar), 2 stuck")

    # the students table says how long ago each answered last: who stopped, told from who works
    assert page.locator('#dash-students tr[data-student="S00"] .dash-active').inner_text() == "just now"
    assert page.locator('#dash-students tr[data-student="S07"] .dash-active').inner_text() == "no answer yet"
    assert page.locator("#dash-students thead th").nth(5).inner_text() == "Last active"

    page.set_viewport_size({"width": 1024, "height": 768})
    page.screenshot(path=artifacts / "teach-bars-1024.png", full_page=True)
    assert errors == []
    context.close()


def test_the_lecturer_closes_joining_and_stops_answers_from_the_dashboard(browser, live_server, classes, artifacts):  # noqa: F811
    """Issue 44, item 7: two buttons end the session without deleting the class; a student trying to join reads
    the server's reason on /join; both reopen."""
    context, page, errors = teacher_page(browser, live_server)
    page.goto("/teach")
    room = classes[0]
    code, key = _scripted(room)
    class_id = store.access(room.db, code, key).class_id
    kept = json.dumps({"code": code, "key": key, "title": "Mechanics II, Tuesday practice"})
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(kept)})")
    page.reload()
    page.wait_for_selector("#now-mistake[data-count]")
    assert page.locator("#session-status").inner_text() == "Open: students may join and answer."

    page.click("#session-joining")
    page.wait_for_function("document.getElementById('session-joining').textContent === 'Reopen joining'")
    assert store.class_session(room.db, class_id)["joining_open"] is False
    assert "new students are refused; those who joined keep working" in page.locator("#session-status").inner_text()
    page.click("#session-answers")
    page.wait_for_function("document.getElementById('session-answers').textContent === 'Take answers again'")
    assert store.class_session(room.db, class_id)["answers_open"] is False
    assert "what they answered before is kept" in page.locator("#session-status").inner_text()
    page.screenshot(path=artifacts / "teach-session-ended-1366.png")

    # a student trying to join now reads why, in the server's words
    phone = browser.new_context(base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True)
    student = phone.new_page()
    student.goto("/join")
    student.fill("#join-code", code)
    student.fill("#join-name", "Quentin")
    student.click("#join-form button[type=submit]")
    student.wait_for_function("document.getElementById('join-status').textContent.includes('closed joining')")
    assert student.locator("#join-status").inner_text() == store.JOINING_CLOSED
    student.screenshot(path=artifacts / "join-closed-390.png")
    phone.close()

    # reopened, both: the record is as it was (12 students), and the line says so
    page.click("#session-joining")
    page.click("#session-answers")
    page.wait_for_function("document.getElementById('session-status').textContent.startsWith('Open')")
    assert store.class_session(room.db, class_id)["answers_open"] is True
    assert page.locator("#dash-counts").inner_text().startswith("12 students")
    assert errors == []
    context.close()
