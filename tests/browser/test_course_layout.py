"""Layout faults an instructor found (issue 45, inst-c 19 and 26): the class links in the phone's header on every
page, one step a row in the teacher's checklist, and no handle label across the compact embed's small drawing."""

from __future__ import annotations

import json

import pytest

from tests.browser.test_classroom import PHONE

pytestmark = pytest.mark.browser

DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'


@pytest.fixture
def phone(browser, live_server):
    context = browser.new_context(base_url=live_server, **PHONE)
    page = context.new_page()
    page.set_default_timeout(90_000)
    yield page
    context.close()


@pytest.mark.parametrize("address", ["/", "/scenes/simple-pendulum", "/playground", "/join", "/teach"])
def test_the_phone_header_has_every_link(phone, address, artifacts):
    phone.goto(address)
    boxes = {}
    for name in ("Contents", "Playground", "Join a class", "Teach a class"):
        link = phone.locator(".site-header nav ul a", has_text=name)
        assert link.is_visible(), name
        box = link.bounding_box()
        # within the screen's width, and tall enough to tap
        assert box["x"] >= 0 and box["x"] + box["width"] <= 390 and box["height"] >= 24, (name, box)
        boxes[name] = box
    # no two links overlap
    names = list(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            p, q = boxes[a], boxes[b]
            apart = p["x"] + p["width"] <= q["x"] or q["x"] + q["width"] <= p["x"] or p["y"] + p["height"] <= q["y"] or q["y"] + q["height"] <= p["y"]
            assert apart, (a, b)
    assert phone.evaluate("document.documentElement.scrollWidth <= window.innerWidth")
    if address == "/":
        phone.screenshot(path=artifacts / "header-390.png")
    # the way to the class page works from here
    phone.locator(".site-header nav ul a", has_text="Join a class").click()
    phone.wait_for_url("**/join")


def test_the_compact_embed_leaves_out_the_handle_label_on_a_phone(phone, artifacts):
    phone.goto("/embed/scenes/simple-pendulum?view=compact")
    phone.wait_for_selector(DONE, state="attached")
    phone.wait_for_function("document.querySelector('[data-panel^=animation] canvas.mechanism').dataset.handle !== ''")
    assert phone.locator("[data-panel^=animation] .handle-label").is_hidden()
    phone.screenshot(path=artifacts / "embed-compact-simple-pendulum-390.png")


def test_the_teachers_checklist_has_one_step_a_row(browser, live_server):
    context = browser.new_context(base_url=live_server, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    page.set_default_timeout(60_000)
    made = page.request.post("/api/classes", data={"title": "Rows"}).json()
    page.goto("/teach")
    page.evaluate(f"localStorage.setItem('lagrange-teach', {json.dumps(json.dumps({'code': made['code'], 'key': made['teacher_key'], 'title': 'Rows'}))})")
    page.reload()
    page.locator('#assign-scenes input[data-scene="simple-pendulum"]').check()
    page.wait_for_selector('#assign-scenes input[data-scene="simple-pendulum"] ~ .assign-steps input[data-step="lagrangian"]')
    rows = page.locator('#assign-scenes li:has(> input[data-scene="simple-pendulum"]) .assign-steps > li')
    tops = [b["y"] for b in (r.bounding_box() for r in rows.all())]
    assert len(tops) >= 8 and all(b > a for a, b in zip(tops, tops[1:], strict=False)), tops
    context.close()
