"""A typed system's set-up on a student's phone (issue 45): the instructor's words and the system's defining data
typeset stand above its boxes, within the phone's width."""

from __future__ import annotations

import pytest

from tests.browser.test_classroom import (
    PHONE,
    _errors_of,
    classes,  # noqa: F401 - the module's classes in a database of their own
)

pytestmark = pytest.mark.browser

PENDULUM = {"coordinates": ["theta"], "parameters": ["m", "l", "g"],
            "particles": [{"mass": "m", "position": ["l sin θ", "-l cos(theta)"], "label": "bob"}],
            "potential": "-m g l cos θ"}
SETUP = ["θ is the angle of the string from the downward vertical, counterclockwise positive.",
         "U = 0 at the height of the pivot."]


def joined(page, title: str, item: dict) -> None:
    """A class of its own with one assignment of ``item``, which Ada joins on this page."""
    made = page.request.post("/api/classes", data={"title": title}).json()
    teacher = {"Authorization": f"Bearer {made['teacher_key']}"}
    added = page.request.post(f"/api/classes/{made['code']}/assignments", headers=teacher,
                              data={"title": "Week 1", "items": [item]})
    assert added.status == 201, added.text()
    page.goto(f"/join?code={made['code']}")
    page.fill("#join-name", "Ada")
    page.click("#join-form button[type=submit]")


def test_a_student_reads_the_set_up_above_the_boxes_on_a_phone(browser, live_server, classes, artifacts):  # noqa: F811
    context = browser.new_context(base_url=live_server, **PHONE)
    page = context.new_page()
    page.set_default_timeout(60_000)
    errors = _errors_of(page)
    item = {"system": PENDULUM, "name": "pendulum on a string", "setup": "\n".join(SETUP),
            "steps": [{"step": "kinetic"}, {"step": "equation", "coordinate": "theta"}]}
    joined(page, "Set-up", item)
    page.wait_for_selector(".join-item .practice-step textarea")
    setup = page.locator(".join-item .join-setup")
    # the instructor's words, line by line, then the particle and U typeset (T is the step asked: not shown)
    assert setup.locator("p:not(.help)").all_inner_texts() == SETUP
    given = setup.locator(".join-given li")
    given.first.locator(".katex").wait_for()
    assert given.count() == 2 and given.locator(".katex").count() == 2
    assert given.first.inner_text().startswith("Particle 1, bob:")
    annotations = given.locator("annotation").all_text_contents()
    assert annotations == [r"\text{mass } m,\quad (x,\ y) = \left(l \sin \theta,\ -l \cos \theta\right)",
                           r"U = -m g l \cos \theta"]
    # above the boxes, and nothing wider than the phone
    assert setup.bounding_box()["y"] < page.locator(".join-item .practice-step").first.bounding_box()["y"]
    assert page.evaluate("document.documentElement.scrollWidth <= window.innerWidth")
    for li in given.all():
        box = li.bounding_box()
        assert box["x"] >= 0 and box["x"] + box["width"] <= 390
    page.locator(".join-item").first.screenshot(path=artifacts / "join-setup-390.png")
    assert errors == []
    context.close()


def test_values_the_instructor_sets_are_read_with_their_letters_and_units(browser, live_server, classes, artifacts):  # noqa: F811
    """student-g: "Take m1 = 2, l2 = 0.5" named the values as code, without units; they read as the scene's page
    prints them, m₁ = 2 kg, l₂ = 0.5 m."""
    context = browser.new_context(base_url=live_server, **PHONE)
    page = context.new_page()
    page.set_default_timeout(60_000)
    errors = _errors_of(page)
    joined(page, "Values", {"scene": "double-pendulum", "parameters": {"m1": 2, "l2": 0.5}, "steps": [{"step": "kinetic"}]})
    values = page.locator(".join-item .join-values")
    values.locator(".katex").wait_for()
    assert values.locator("annotation").text_content() == r"m_{1} = 2\,\mathrm{kg},\quad l_{2} = 0.5\,\mathrm{m}"
    assert values.inner_text().startswith("Take ")
    values.screenshot(path=artifacts / "join-values-390.png")
    assert errors == []
    context.close()
