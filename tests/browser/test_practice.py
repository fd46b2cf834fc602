"""Practice mode in headless Chromium: type answers, see verdicts, reload, find them kept."""

from __future__ import annotations

import unicodedata

import pytest

pytestmark = pytest.mark.browser

STEP = '.practice-step[data-key="{}"]'


def answer(page, key: str, text: str) -> None:
    box = page.locator(STEP.format(key)).locator("input[name]")  # the step's own box (a follow-up's has no name)
    box.fill(text)
    box.press("Enter")  # keyboard only: Enter checks


def verdict_of(page, key: str):
    return page.locator(STEP.format(key) + " .practice-verdict")


def test_a_wrong_then_a_right_answer_survive_a_reload(page, artifacts):
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector("#practice-switch")
    assert page.locator("#derivation").is_visible()
    page.locator("#practice-switch").focus()
    page.keyboard.press("Space")
    assert page.locator("#derivation").is_hidden() and page.locator("#results").is_hidden()
    page.wait_for_selector(STEP.format("kinetic"))

    # the live preview typesets what is typed
    page.locator(STEP.format("kinetic") + " input").fill("m*R**2*theta_dot**2")
    page.wait_for_function(
        "document.querySelector('.practice-step[data-key=kinetic] .practice-preview annotation')"
        "?.textContent.includes('\\\\dot{\\\\theta}')"
    )
    answer(page, "kinetic", "m*R**2*theta_dot**2")
    wrong = verdict_of(page, "kinetic")
    wrong.locator(".verdict-head").wait_for()
    assert wrong.get_attribute("data-verdict") == "incorrect" and wrong.get_attribute("aria-live") == "polite"
    assert "½" in wrong.locator(".verdict-hint").inner_text()
    assert wrong.locator(".verdict-difference .katex").count() == 1

    answer(page, "potential", "m*g*R*(1 - cos(theta))")
    right = verdict_of(page, "potential")
    right.locator(".verdict-head").wait_for()
    assert right.get_attribute("data-verdict") == "correct"

    # "show this step" reveals the engine's step
    reveal = page.locator(STEP.format("kinetic") + " button[aria-controls]")
    reveal.click()
    assert reveal.get_attribute("aria-expanded") == "true"
    assert page.locator(STEP.format("kinetic") + " .practice-engine .katex").is_visible()
    page.set_viewport_size({"width": 1366, "height": 768})
    page.locator("#practice").screenshot(path=artifacts / "practice-1366.png")

    page.reload()
    page.wait_for_selector(STEP.format("potential") + ' .practice-verdict[data-verdict="correct"]')
    assert page.locator("#practice-switch").is_checked() and page.locator("#derivation").is_hidden()
    assert page.locator(STEP.format("kinetic") + " input").input_value() == "m*R**2*theta_dot**2"
    assert verdict_of(page, "kinetic").get_attribute("data-verdict") == "incorrect"
    assert page.locator(STEP.format("potential") + " input").input_value() == "m*g*R*(1 - cos(theta))"
    assert page.locator("#practice .katex-error").count() == 0
    assert page.console_errors == []


def test_a_refusal_marks_the_offending_part_and_every_box_is_labelled(page):
    page.goto("/scenes/spherical-pendulum?practice")
    page.wait_for_selector(STEP.format("momentum:phi"))
    for box in page.locator(".practice-step input").all():
        assert page.locator(f'label[for="{box.get_attribute("id")}"]').count() == 1
    answer(page, "momentum:phi", "m*R**2*phi_dot + v")
    refused = verdict_of(page, "momentum:phi")
    refused.locator("mark").wait_for()
    assert refused.locator("mark").inner_text() == "v" and "unknown name" in refused.inner_text()
    # the browser logs the refusal's 422 itself (and a 429 when the check met the page's own simulation job,
    # which it retries); nothing else may go wrong
    assert [e for e in page.console_errors if "status of 422" not in e and "status of 429" not in e] == []


def test_a_shared_link_opens_practice_with_its_parameters(page):
    page.goto("/scenes/simple-pendulum?practice&m=2.5&R=0.5")
    page.wait_for_selector(STEP.format("kinetic"))
    assert page.locator("#practice-switch").is_checked()
    assert page.locator("#ctl-m").input_value() == "2.5" and page.locator("#ctl-R").input_value() == "0.5"


def test_the_playground_practises_the_declared_system(page, artifacts):
    page.goto("/playground")
    page.locator("#practice-switch").check()
    page.wait_for_selector(STEP.format("acceleration:x"))
    # the system lives in the address: its practice link opens it in practice mode
    page.locator("#practice-link").click()
    page.wait_for_function("document.getElementById('practice-link-status').textContent !== ''")
    link = page.locator("#practice-link-status").inner_text().removeprefix("Link: ")
    assert link == "Link copied." or ("practice" in link and "system=" in link)
    answer(page, "acceleration:x", "(F*cos(w*t) - b*x_dot - k*x)/m")
    verdict_of(page, "acceleration:x").locator(".verdict-head").wait_for()
    assert verdict_of(page, "acceleration:x").get_attribute("data-verdict") == "correct"
    page.set_viewport_size({"width": 390, "height": 844})
    page.locator("#practice").screenshot(path=artifacts / "practice-390.png")
    # a check that meets the page's own simulation job is told to wait (429) and retries
    assert [e for e in page.console_errors if "status of 429" not in e] == []


def test_a_named_mistake_its_piece_and_its_follow_up(page, artifacts):
    page.set_viewport_size({"width": 1366, "height": 768})
    page.goto("/scenes/spherical-pendulum?practice")
    page.wait_for_selector(STEP.format("kinetic"))
    # T without the φ̇ part of the ball's velocity
    answer(page, "kinetic", "m*R**2*theta_dot**2/2")
    verdict = verdict_of(page, "kinetic")
    verdict.locator(".verdict-mistake").wait_for()
    assert verdict.get_attribute("data-verdict") == "incorrect"
    mistake = verdict.locator(".verdict-mistake")
    assert mistake.get_attribute("data-key") == "kinetic.velocity_part.ball.phi"
    assert "the part of the ball's velocity that comes from φ̇" in mistake.inner_text()
    # what T leaves out, ½ m R² sin²θ φ̇², labelled and typeset (not R sin θ φ̇, the follow-up's answer)
    piece = mistake.locator(".verdict-piece annotation").text_content()
    assert "\\dot{\\phi}" in piece and "\\sin" in piece and mistake.locator(".verdict-piece .katex").is_visible()
    assert "Everything else in your T is right." in verdict.locator(".verdict-partial").inner_text()
    verdict.screenshot(path=artifacts / "practice-mistake-1366.png")

    # the follow-up question, answered with the keyboard
    follow = verdict.locator(".verdict-follow-up")
    assert "speed of the ball" in follow.locator("label").inner_text()
    follow.locator("input").fill("R*sin(theta)*phi_dot")
    follow.locator("input").press("Enter")
    page.wait_for_selector(STEP.format("kinetic") + ' .follow-up-verdict[data-verdict="correct"]')
    assert "Correct" in follow.locator(".follow-up-verdict").inner_text()
    page.set_viewport_size({"width": 390, "height": 844})
    verdict.screenshot(path=artifacts / "practice-mistake-390.png")

    # then the right T
    answer(page, "kinetic", "m*R**2*(theta_dot**2 + sin(theta)**2*phi_dot**2)/2")
    page.wait_for_selector(STEP.format("kinetic") + ' .practice-verdict[data-verdict="correct"]')
    assert verdict.locator(".verdict-mistake").count() == 0
    assert page.locator("#practice .katex-error").count() == 0
    assert [e for e in page.console_errors if "status of 429" not in e] == []


# A slip with a follow-up question on two more scenes, at the desktop size and on a phone with touch:
# (scene, step, the slip, the mistake's key, words of its name, the follow-up's answer)
NAMED_WITH_FOLLOW_UP = [
    ("movable-incline", "kinetic", "M*X_dot**2/2 + m*D_dot**2/2", "kinetic.velocity_part.block.X",
     "the part of the block's velocity that comes from Ẋ", "X_dot"),
    ("rail-two-body", "potential", "k*(x2 - x1)**2/2", "potential.natural_length.k_l0_x1_x2",
     "the spring's natural length l₀", "x2 - x1 - l0"),
]  # fmt: skip


@pytest.mark.parametrize("size", ["desktop", "phone"])
@pytest.mark.parametrize(("scene", "step", "slip", "key", "name", "follow"), NAMED_WITH_FOLLOW_UP)
def test_the_named_slip_its_piece_and_follow_up_at_both_sizes(browser, live_server, artifacts, size, scene, step,
                                                              slip, key, name, follow):  # fmt: skip
    phone = size == "phone"
    viewport = {"width": 390, "height": 844} if phone else {"width": 1366, "height": 768}
    context = browser.new_context(base_url=live_server, viewport=viewport, has_touch=phone, is_mobile=phone)
    page = context.new_page()
    page.set_default_timeout(60_000)
    try:
        page.goto(f"/scenes/{scene}?practice")
        page.wait_for_selector(STEP.format(step))
        box = page.locator(STEP.format(step)).locator("input[name]")
        box.fill(slip)
        box.press("Enter")
        verdict = verdict_of(page, step)
        mistake = verdict.locator(".verdict-mistake")
        mistake.wait_for()
        assert verdict.get_attribute("data-verdict") == "incorrect"
        shown = unicodedata.normalize("NFC", mistake.inner_text())
        assert mistake.get_attribute("data-key") == key and unicodedata.normalize("NFC", name) in shown
        assert mistake.locator(".verdict-piece .katex").is_visible()  # the piece, typeset
        # nothing of the verdict is cut off on the phone: it fits the screen's width
        assert verdict.evaluate("e => e.getBoundingClientRect().right") <= viewport["width"] + 1
        follow_up = verdict.locator(".verdict-follow-up")
        follow_up.locator("input").fill(follow)
        follow_up.locator("input").press("Enter")
        page.wait_for_selector(STEP.format(step) + ' .follow-up-verdict[data-verdict="correct"]')
        verdict.screenshot(path=artifacts / f"practice-{scene}-{size}.png")
        assert page.locator("#practice .katex-error").count() == 0
    finally:
        context.close()
