"""Practice mode in headless Chromium: type answers, see verdicts, reload, find them kept."""

from __future__ import annotations

import unicodedata

import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from tests.browser.conftest import busy_once, unfold_panels

pytestmark = pytest.mark.browser

STEP = '.practice-step[data-key="{}"]'


def answer(page, key: str, text: str) -> None:
    box = page.locator(STEP.format(key)).locator("textarea[name]")  # the step's own box (a follow-up's has no name)
    box.fill(text)
    box.press("Enter")  # keyboard only: Enter checks


def words(locator) -> str:
    """What a verdict's words say (NFC), each formula the page typesets read as the text it sets (data-text)."""
    text = locator.evaluate(
        "e => { const c = e.cloneNode(true);"
        " c.querySelectorAll('.prose-math').forEach((m) => m.replaceWith(m.dataset.text)); return c.textContent; }"
    )
    return unicodedata.normalize("NFC", text)


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
    page.locator(STEP.format("kinetic") + " textarea").fill("m*R**2*theta_dot**2")
    page.wait_for_function(
        "document.querySelector('.practice-step[data-key=kinetic] .practice-preview annotation')"
        "?.textContent.includes('\\\\dot{\\\\theta}')"
    )
    answer(page, "kinetic", "m*R**2*theta_dot**2")
    wrong = verdict_of(page, "kinetic")
    wrong.locator(".verdict-head").wait_for()
    assert wrong.get_attribute("data-verdict") == "incorrect" and wrong.get_attribute("aria-live") == "polite"
    assert "½" in words(wrong.locator(".verdict-hint"))
    # the verdict names the mistake and never shows the difference (the API keeps it for the step's reveal)
    assert wrong.locator(".verdict-difference .katex").count() == 0

    answer(page, "potential", "m*g*R*(1 - cos(theta))")
    right = verdict_of(page, "potential")
    right.locator(".verdict-head").wait_for()
    assert right.get_attribute("data-verdict") == "correct"

    # "show this step" reveals the engine's step
    reveal = page.locator(STEP.format("kinetic") + " button[aria-controls]")
    reveal.click()
    assert reveal.get_attribute("aria-expanded") == "true"
    assert page.locator(STEP.format("kinetic") + " .practice-engine .math-display .katex").is_visible()
    # and under it, what the verdict kept back: how the last answer checked differs from the step
    assert page.locator(STEP.format("kinetic") + " .practice-reveal .verdict-difference .katex").is_visible()
    page.set_viewport_size({"width": 1366, "height": 768})
    page.locator("#practice").screenshot(path=artifacts / "practice-1366.png")

    page.reload()
    page.wait_for_selector(STEP.format("potential") + ' .practice-verdict[data-verdict="correct"]')
    assert page.locator("#practice-switch").is_checked() and page.locator("#derivation").is_hidden()
    assert page.locator(STEP.format("kinetic") + " textarea").input_value() == "m*R**2*theta_dot**2"
    assert verdict_of(page, "kinetic").get_attribute("data-verdict") == "incorrect"
    assert page.locator(STEP.format("potential") + " textarea").input_value() == "m*g*R*(1 - cos(theta))"
    assert page.locator("#practice .katex-error").count() == 0
    assert page.console_errors == []


def test_a_refusal_marks_the_offending_part_and_every_box_is_labelled(page):
    page.goto("/scenes/spherical-pendulum?practice")
    page.wait_for_selector(STEP.format("momentum:phi"))
    for box in page.locator(".practice-step textarea").all():
        assert page.locator(f'label[for="{box.get_attribute("id")}"]').count() == 1
    answer(page, "momentum:phi", "m*R**2*phi_dot + v")
    refused = verdict_of(page, "momentum:phi")
    refused.locator("mark").wait_for()
    assert refused.locator("mark").inner_text() == "v" and "v is not a name in this problem" in refused.inner_text()
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
    assert unicodedata.normalize("NFC", "the part of the ball's velocity that comes from φ̇") in words(mistake)
    # what T leaves out is the answer's: never beside the verdict (the API keeps it for the step's reveal)
    assert mistake.locator(".verdict-piece").count() == 0
    # a one-term answer: nothing else in it to call right
    assert verdict.locator(".verdict-partial").count() == 0
    verdict.screenshot(path=artifacts / "practice-mistake-1366.png")

    # the follow-up question, answered with the keyboard
    follow = verdict.locator(".verdict-follow-up")
    assert "speed of the ball" in follow.locator("label").inner_text()
    follow.locator("textarea").fill("R*sin(theta)*phi_dot")
    follow.locator("textarea").press("Enter")
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


def tap_or_record(page, button, shot) -> None:
    """Click the button as a person would; where another element stays over it (seen once on a loaded CI
    machine, a practice row over the export's button on a phone, never here), record what covers it and the
    page as it was, then press the button itself, so the test goes on to check what the button does."""
    try:
        button.click(timeout=15_000)
    except PlaywrightTimeout:
        page.screenshot(path=shot, full_page=True)
        covering = button.evaluate(
            "b => { const r = b.getBoundingClientRect();"
            " const e = document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2);"
            " return [JSON.stringify(r), scrollY, innerWidth, e && e.outerHTML.slice(0, 200)]; }"
        )
        print("covered:", covering)
        button.dispatch_event("click")


def sized_page(browser, live_server, phone: bool):
    """A fresh context at 390×844 with touch (a phone) or at 1366×768, and its page."""
    viewport = {"width": 390, "height": 844} if phone else {"width": 1366, "height": 768}
    context = browser.new_context(base_url=live_server, viewport=viewport, has_touch=phone, is_mobile=phone)
    page = context.new_page()
    page.set_default_timeout(60_000)
    return context, page


@pytest.mark.parametrize("size", ["desktop", "phone"])
@pytest.mark.parametrize(("scene", "step", "slip", "key", "name", "follow"), NAMED_WITH_FOLLOW_UP)
def test_the_named_slip_its_piece_and_follow_up_at_both_sizes(browser, live_server, artifacts, size, scene, step,
                                                              slip, key, name, follow):  # fmt: skip
    phone = size == "phone"
    context, page = sized_page(browser, live_server, phone)
    try:
        page.goto(f"/scenes/{scene}?practice")
        page.wait_for_selector(STEP.format(step))
        box = page.locator(STEP.format(step)).locator("textarea[name]")
        box.fill(slip)
        box.press("Enter")
        verdict = verdict_of(page, step)
        mistake = verdict.locator(".verdict-mistake")
        mistake.wait_for()
        assert verdict.get_attribute("data-verdict") == "incorrect"
        shown = words(mistake)
        assert mistake.get_attribute("data-key") == key and unicodedata.normalize("NFC", name) in shown
        assert mistake.locator(".verdict-piece").count() == 0  # the correct piece is the answer's: kept for the reveal
        # nothing of the verdict is cut off on the phone: it fits the screen's width
        assert verdict.evaluate("e => e.getBoundingClientRect().right") <= page.viewport_size["width"] + 1
        follow_up = verdict.locator(".verdict-follow-up")
        # the names it may use folded to one line (student-k 11): opened, they are the question's
        names = follow_up.locator("details.follow-up-names")
        assert names.locator("summary").inner_text().strip() == "Names you may use" and not names.evaluate("d => d.open")
        assert names.locator("p").is_hidden()
        follow_up.locator("textarea").fill(follow)
        # the reply is typeset as it is typed, as the step's own answer is
        follow_up.locator(".practice-preview .katex").wait_for()
        assert follow_up.locator(".practice-preview-note").inner_text() == ""
        follow_up.locator("textarea").press("Enter")
        page.wait_for_selector(STEP.format(step) + ' .follow-up-verdict[data-verdict="correct"]')
        verdict.screenshot(path=artifacts / f"practice-{scene}-{size}.png")
        assert page.locator("#practice .katex-error").count() == 0
    finally:
        context.close()


def test_the_positions_step_names_the_wedges_x_left_out_on_a_phone(browser, live_server, artifacts):
    # issue 41, item 1: the practice starts with the positions, says the figure's axes, names the slip
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/movable-incline?practice")
        key = "position:x2"
        page.wait_for_selector(STEP.format(key))
        # the wedge's own x is the coordinate X itself, so the block's x is the first position asked (prof-q 3)
        first = page.locator(".practice-step").first
        assert first.get_attribute("data-key") == key
        step = page.locator(STEP.format(key))
        assert step.locator("h3 .practice-title").inner_text() == "Position: x of the block"
        # said in full on the first position box (student-l 8)
        assert "x across" in first.locator(".practice-names").inner_text()
        answer(page, key, "D*cos(alpha)")
        mistake = verdict_of(page, key).locator(".verdict-mistake")
        mistake.wait_for()
        assert mistake.get_attribute("data-key") == "position.x2.carried.1"
        assert "the wedge's x left out" in words(mistake)
        verdict = verdict_of(page, key)
        assert verdict.evaluate("e => e.getBoundingClientRect().right") <= 391
        verdict.screenshot(path=artifacts / "practice-position-phone.png")
        answer(page, key, "X + D*cos(alpha)")
        page.wait_for_selector(STEP.format(key) + ' .practice-verdict[data-verdict="correct"]')
        assert page.locator("#practice .katex-error").count() == 0
    finally:
        context.close()


def test_a_wrong_reply_to_a_follow_up_is_diagnosed(page, artifacts):
    # student-e, 8: the lower bob's T alone typed as if it swung from a fixed pivot
    page.set_viewport_size({"width": 1366, "height": 768})
    page.goto("/scenes/double-pendulum?practice")
    page.wait_for_selector(STEP.format("kinetic"))
    answer(page, "kinetic", "m1*l1**2*theta1_dot**2/2")
    follow_up = verdict_of(page, "kinetic").locator(".verdict-follow-up")
    follow_up.wait_for()
    assert "kinetic energy of the lower bob alone" in follow_up.locator("label").inner_text()
    follow_up.locator("textarea").fill("m2*l2**2*theta2_dot**2/2")
    follow_up.locator("textarea").press("Enter")
    page.wait_for_selector(STEP.format("kinetic") + ' .follow-up-verdict[data-verdict="incorrect"]')
    said = words(follow_up.locator(".follow-up-verdict"))
    assert "the lower bob also moves when θ₁ changes" in said and "carries the lower bob" in said, said
    follow_up.screenshot(path=artifacts / "practice-follow-up-wrong-1366.png")


def test_panels_that_give_away_a_step_are_folded_until_it_is_shown(page, artifacts):
    # student-c, 21: the pendulum's tension and its predicted ω stood in the panels above the practice boxes
    page.set_viewport_size({"width": 390, "height": 844})
    page.goto("/scenes/simple-pendulum?practice")
    page.wait_for_selector(STEP.format("omega_squared"))
    unfold_panels(page)  # a phone folds the plot panels under the animation: opened, they still fold what gives away
    conventions = page.locator("#panel-constraint-force .conventions")
    readout = page.locator("#panel-small-oscillations .readout")
    assert conventions.count() == 1 and conventions.is_hidden() and readout.is_hidden()
    fold = page.locator("#panel-small-oscillations .gives-away")
    steps = page.locator(".practice-step h3 .practice-title").all_inner_texts()
    number = next(
        k
        for k, key in enumerate(page.locator(".practice-step").evaluate_all("s => s.map(x => x.dataset.key)"))
        if key == "omega_squared"
    )
    assert fold.inner_text() == f"Show (gives away step {number + 1}: {steps[number]})"
    page.locator("#panel-small-oscillations").screenshot(path=artifacts / "practice-folded-390.png")
    # shown by the student's choice of the panel's button, or once the step is shown
    page.locator(STEP.format("omega_squared") + " button[aria-controls]").click()
    assert readout.evaluate("el => getComputedStyle(el).display") != "none" and fold.count() == 0
    assert conventions.is_hidden()
    page.locator("#panel-constraint-force .gives-away").click()
    assert conventions.is_visible() and "cos" in conventions.inner_text()
    page.locator("#practice-switch").click()  # practice off: nothing is folded
    assert page.locator("#panel-constraint-force .conventions").is_visible()


def test_an_equation_typed_as_a_textbook_writes_it_is_checked_and_a_refusal_is_said_once(page, artifacts):
    # student-c, 5: θ̈ = −(g/R) sin θ was refused, and every refusal was shown twice in parser words
    page.set_viewport_size({"width": 390, "height": 844})
    page.goto("/scenes/simple-pendulum?practice")
    key = "equation:theta"
    page.wait_for_selector(STEP.format(key))
    names = page.locator(STEP.format(key) + " .practice-names").inner_text()
    assert "lhs = rhs" in names
    # issue 41, item 3: the names printed as a textbook prints them, each typed spelling once, in order
    assert "θ (type theta), θ̇ (type theta_dot), θ̈ (type theta_ddot), pi." in names, names
    how = page.locator('.practice-step[data-key="acceleration:theta"] .practice-names').inner_text()
    assert how.startswith("Type θ̈ = … (θ̈ is typed theta_ddot), or only the right-hand side."), how
    box = page.locator(STEP.format(key) + " textarea[name]")
    box.fill("theta_ddot = -g/R*sin(theta)")
    page.wait_for_function(f"document.querySelector('{STEP.format(key)}').dataset.typeset === 'read'")
    assert page.locator(STEP.format(key) + " .practice-row .practice-lhs").last.is_hidden()  # no "= 0" beside it
    math = page.locator(STEP.format(key) + " .practice-preview-math")
    page.screenshot(path=artifacts / "practice-equation-390.png")
    preview = math.evaluate("el => el.querySelector('annotation')?.textContent ?? el.textContent")
    # once, as typed: no '= 0' after it (set at display size, so that it may break across lines)
    assert preview.removeprefix(r"\displaystyle ") == r"\ddot{\theta} = -\frac{g}{R} \sin \theta"
    box.press("Enter")
    box.press("Enter")  # a second Enter while checking sends nothing more
    verdict = verdict_of(page, key)
    verdict.locator(".verdict-head").wait_for()
    assert verdict.get_attribute("data-verdict") == "correct"

    # ½ typed as students type it, with a space before the mass, is a coefficient: typeset ½ m R² θ̇², checked
    answer(page, "kinetic", "1/2 m R^2 theta_dot^2")
    half = page.locator(STEP.format("kinetic") + " .practice-preview-math")
    page.wait_for_function(f"document.querySelector('{STEP.format('kinetic')}').dataset.typeset === 'read'")
    shown = half.evaluate("el => el.querySelector('annotation')?.textContent ?? el.textContent")
    assert shown.removeprefix(r"\displaystyle ") == r"T = \frac{1}{2} m R^{2} \dot{\theta}^{2}"
    verdict_of(page, "kinetic").locator(".verdict-head").wait_for()
    assert verdict_of(page, "kinetic").get_attribute("data-verdict") == "correct"
    # glued to the mass it reads two ways, and the refusal says the space that decides
    answer(page, "kinetic", "1/2m R^2 theta_dot^2")
    refused = verdict_of(page, "kinetic")
    refused.locator("mark").wait_for()
    said = refused.locator(".verdict-head").inner_text()
    assert said.startswith("Not checked: a factor after a quotient") and said.endswith("put a space after 1/2.")
    assert "column" not in said and "answer:" not in said
    assert page.locator(STEP.format("kinetic") + " .practice-preview-note").inner_text() == ""  # said once
    page.locator(STEP.format("kinetic")).screenshot(path=artifacts / "practice-refused-once-390.png")
    answer(page, "lagrangian", "T - U")
    verdict_of(page, "lagrangian").locator("mark").wait_for()
    assert "write T and U out in the coordinates" in verdict_of(page, "lagrangian").inner_text()
    # a name before a bracket: the fix is said in the student's own characters, with no code quoted after it
    answer(page, "kinetic", "½m(R^2 θ'^2)")
    refused.locator("mark").wait_for()
    said = refused.locator(".verdict-head").inner_text()
    assert said == "Not checked: m is not a function: put a space (or *) between m and the bracket: m (R^2 θ'^2).", said


def test_an_edited_answer_greys_its_old_verdict_and_an_unreadable_one_clears_the_preview(page):
    page.set_viewport_size({"width": 1366, "height": 768})
    page.goto("/scenes/simple-pendulum?practice")
    page.wait_for_selector(STEP.format("kinetic"))
    answer(page, "kinetic", "m*R**2*theta_dot**2/2")
    verdict = verdict_of(page, "kinetic")
    verdict.locator(".verdict-head").wait_for()
    assert verdict.get_attribute("data-verdict") == "correct" and verdict.locator(".verdict-stale-note").count() == 0
    box = page.locator(STEP.format("kinetic")).locator("textarea[name]")
    # edited, not checked: the "Correct" no longer stands for what is in the box
    box.fill("m*R**2*theta_dot**2/3")
    assert "earlier answer" in verdict.locator(".verdict-stale-note").inner_text()
    assert "verdict-stale" in verdict.get_attribute("class")
    box.fill("m*R**2*theta_dot**2/2")  # back to the checked answer: the verdict is its own again
    assert verdict.locator(".verdict-stale-note").count() == 0
    # a text that cannot be read leaves no rendering of an earlier text under the box
    preview = page.locator(STEP.format("kinetic") + " .practice-preview-math")
    page.wait_for_function("document.querySelector('.practice-step[data-key=kinetic] .practice-preview-math .katex')")
    box.fill("m*R**2*(theta_dot**2/2")
    page.wait_for_function(
        "document.querySelector('.practice-step[data-key=kinetic] .practice-preview-note').textContent.includes('Not read yet')"
    )
    assert preview.locator(".katex").count() == 0
    # checked again: the new verdict, without the stale line
    answer(page, "kinetic", "m*R**2*theta_dot**2")
    page.wait_for_function(
        "document.querySelector('.practice-step[data-key=kinetic] .practice-verdict').dataset.verdict === 'incorrect'"
    )
    assert verdict.locator(".verdict-stale-note").count() == 0 and "verdict-stale" not in (
        verdict.get_attribute("class") or ""
    )


@pytest.mark.parametrize("size", ["desktop", "phone"])
def test_what_the_preview_and_the_verdict_say_belongs_to_the_text_in_the_box(browser, live_server, artifacts, size):
    """student-d, 3, 4, 14, 20, 23: a refused text leaves no earlier rendering, its words are a tutor's; the parser's
    note on a half-typed text goes as the text changes; an edited answer's verdict is greyed; the energy readout
    is folded until U is checked."""
    phone = size == "phone"
    context, page = sized_page(browser, live_server, phone)
    try:
        page.goto("/scenes/simple-pendulum?practice")
        page.wait_for_selector(STEP.format("acceleration:theta"))
        # the live energy readout would let U's form be read off at two angles: folded behind its step
        bars = page.locator("[data-panel^=animation] .energy-bars")
        fold = page.locator("[data-panel^=animation] .gives-away")
        assert bars.is_hidden() and "otential energy U" in fold.inner_text()

        def preview(key: str):
            return page.locator(STEP.format(key) + " .practice-preview")

        # an unknown name (l for R): refused, and no rendering of an earlier text stays under the box
        box = page.locator(STEP.format("acceleration:theta")).locator("textarea[name]")
        box.fill("theta_ddot = -g/R*sin(theta)")
        preview("acceleration:theta").locator(".katex").first.wait_for()
        answer(page, "acceleration:theta", "theta_ddot = -g/l*sin(theta)")
        verdict_of(page, "acceleration:theta").locator("mark").wait_for()
        assert "l is not a name in this problem" in verdict_of(page, "acceleration:theta").inner_text()
        page.wait_for_function(
            "document.querySelector('.practice-step[data-key=\"acceleration:theta\"]').dataset.typeset === 'refused'"
        )
        assert preview("acceleration:theta").locator(".katex").count() == 0

        # a derivative typed as a quotient of differentials: said in a tutor's words, nothing of it typeset
        answer(page, "momentum:theta", "dL/dtheta_dot")
        verdict_of(page, "momentum:theta").locator("mark").wait_for()
        said = verdict_of(page, "momentum:theta").inner_text()
        assert "a derivative cannot be typed here" in said and "not a name in this problem" not in said
        assert preview("momentum:theta").locator(".katex").count() == 0

        # the parser's note on a half-typed text goes the moment the text changes, before any check
        box = page.locator(STEP.format("kinetic")).locator("textarea[name]")
        note = preview("kinetic").locator(".practice-preview-note")
        box.fill("m*R**2*(theta_dot**2/2")
        page.wait_for_function(
            "document.querySelector('.practice-step[data-key=kinetic] .practice-preview-note').textContent.includes('Not read yet')"
        )
        box.fill("m*R**2*theta_dot**2/2")
        assert "Not read yet" not in note.inner_text()
        box.press("Enter")
        verdict = verdict_of(page, "kinetic")
        page.wait_for_selector(STEP.format("kinetic") + ' .practice-verdict[data-verdict="correct"]')
        assert "Not read yet" not in note.inner_text()
        # edited after its check: the verdict no longer stands for what is in the box
        box.fill("m*R**2*theta_dot**2/3")
        assert "earlier answer" in verdict.locator(".verdict-stale-note").inner_text()

        # U checked right: the energy readout is shown
        answer(page, "potential", "m*g*R*(1 - cos(theta))")
        page.wait_for_selector(STEP.format("potential") + ' .practice-verdict[data-verdict="correct"]')
        assert bars.evaluate("el => getComputedStyle(el).display") != "none" and fold.count() == 0
        page.locator("#practice").screenshot(path=artifacts / f"practice-own-text-{size}.png")
        assert page.locator("#practice .katex-error").count() == 0
    finally:
        context.close()


def test_a_long_answer_and_its_difference_break_across_lines_on_a_phone(browser, live_server, artifacts):
    """student-d, 19: on a phone the wedge's h (and the double pendulum's L) and a difference were cut at the screen's
    right edge."""
    context = browser.new_context(base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True,
                                  is_mobile=True)  # fmt: skip
    page = context.new_page()
    page.set_default_timeout(60_000)
    fits = "el => el.scrollWidth <= el.clientWidth + 1 && el.getBoundingClientRect().right <= 391"
    try:
        page.goto("/scenes/movable-incline?practice")
        page.wait_for_selector(STEP.format("hamiltonian"))
        box = page.locator(STEP.format("hamiltonian")).locator("textarea[name]")
        # the box takes the whole width of the step on a phone
        assert box.evaluate("el => el.getBoundingClientRect().width") > 300
        # h with U's sign reversed (T − U, which is L): a long answer, and a wrong one with a difference
        box.fill("(M + m)*X_dot**2/2 + m*D_dot**2/2 + m*X_dot*D_dot*cos(alpha) + m*g*D*sin(alpha)")
        preview = page.locator(STEP.format("hamiltonian") + " .practice-preview")
        preview.locator(".katex").first.wait_for()
        assert preview.evaluate(fits)
        verdict = verdict_of(page, "hamiltonian")
        for _ in range(8):
            box.press("Enter")
            verdict.locator(".verdict-head").wait_for()
            page.wait_for_function("!document.querySelector('.practice-step[data-key=hamiltonian]').dataset.checking")
            if verdict.get_attribute("data-verdict") == "incorrect":
                break
            # a server still building the step's catalogue says it is busy, and what to do: press Check again
            assert verdict.inner_text().startswith("Busy: ") and "press Check again" in verdict.inner_text()
        page.locator(STEP.format("hamiltonian")).screenshot(path=artifacts / "practice-long-answer-390.png")
        # the verdict keeps the difference back; "Show this step" shows it under the step, within the screen
        assert verdict.locator(".verdict-difference").count() == 0
        page.locator(STEP.format("hamiltonian") + " button[aria-controls]").click()
        difference = page.locator(STEP.format("hamiltonian") + " .practice-engine .practice-reveal .verdict-difference")
        assert difference.locator(".katex").count() == 1 and difference.evaluate(fits)
        page.locator(STEP.format("hamiltonian")).screenshot(path=artifacts / "practice-long-answer-390.png")
        assert page.locator("#practice .katex-error").count() == 0
    finally:
        context.close()


# the simple pendulum's eight steps, each typed right (as the page's own derivation gives them)
PENDULUM = [
    ("position:x", "R*sin(theta)"),
    ("position:z", "R - R*cos(theta)"),
    ("kinetic", "m*R**2*theta_dot**2/2"),
    ("potential", "m*g*R*(1 - cos(theta))"),
    ("lagrangian", "m*R**2*theta_dot**2/2 - m*g*R*(1 - cos(theta))"),
    ("momentum:theta", "m*R**2*theta_dot"),
    ("equation:theta", "theta_ddot + g/R*sin(theta) = 0"),
    ("acceleration:theta", "-g/R*sin(theta)"),
    ("hamiltonian", "m*R**2*theta_dot**2/2 + m*g*R*(1 - cos(theta))"),
    ("omega_squared", "g/R"),
]


def test_progress_is_counted_and_the_end_is_said(page, artifacts):
    # student-e, 10 and 18: a count of the steps done, an end message; one title per box, no "= 0" under an empty one
    page.set_viewport_size({"width": 1366, "height": 768})
    page.goto("/scenes/simple-pendulum?practice")
    page.wait_for_selector(STEP.format("omega_squared"))
    status = page.locator("#practice-status")
    assert status.inner_text() == "10 steps to derive, in the derivation's order."
    # the heading is the title, once: the label is for a screen reader, and takes no room on the page
    assert page.locator(STEP.format("kinetic") + " label").evaluate("e => e.getBoundingClientRect().width") <= 1
    equation = page.locator(STEP.format("equation:theta"))
    assert equation.locator(".practice-lhs").nth(1).is_hidden()  # "= 0" only beside an expression typed
    equation.locator("textarea[name]").fill("theta_ddot")
    assert equation.locator(".practice-lhs").nth(1).is_visible()
    for n, (key, text) in enumerate(PENDULUM, start=1):
        answer(page, key, text)
        page.wait_for_selector(STEP.format(key) + ' .practice-verdict[data-verdict="correct"], '
                               + STEP.format(key) + ' .practice-verdict[data-verdict="equivalent"]')  # fmt: skip
        if n == 2:
            assert status.inner_text() == "2 of 10 steps correct."
    assert status.inner_text().startswith("All 10 steps correct")
    page.locator("#practice").screenshot(path=artifacts / "practice-all-done-1366.png")
    # kept: after a reload the count is the same
    page.reload()
    page.wait_for_function("document.getElementById('practice-status').dataset.done === '10'")
    # a right answer typed over no longer counts
    box = page.locator(STEP.format("omega_squared")).locator("textarea[name]")
    box.fill("g/R + 1")
    assert status.inner_text() == "9 of 10 steps correct."


@pytest.mark.parametrize("size", ["desktop", "phone"])
def test_practice_mode_hides_its_dead_tabs_and_folds_what_gives_the_answers_away(browser, live_server, artifacts, size):
    # student-e, 12 and 13: the tabs to hidden sections, the export links, the effective potential (U itself)
    phone = size == "phone"
    context, page = sized_page(browser, live_server, phone)
    try:
        page.goto("/scenes/simple-pendulum?practice")
        page.wait_for_selector(STEP.format("kinetic"))
        unfold_panels(page)
        tabs = page.locator(".on-this-page a")
        assert [a.inner_text() for a in tabs.all() if a.is_visible()] == ["Simulation", "Set-up"]
        export = page.locator("#export")
        assert export.locator(".export-links").is_hidden()
        shown = export.locator("button.gives-away")
        assert shown.inner_text() == "Show (gives away the answers)"
        panel = page.locator("#panel-effective-potential")
        assert panel.locator(".plot").is_hidden()
        # step 4: after the two positions (x and z of the bob) and T
        assert "gives away step 4: Potential energy U" in panel.locator("button.gives-away").inner_text()
        # shown on request, and drawn at its full width
        panel.locator("button.gives-away").click()
        assert panel.locator(".plot").is_visible()
        page.wait_for_function(
            "document.querySelector('#panel-effective-potential .plot svg, #panel-effective-potential .plot canvas')"
            "?.getBoundingClientRect().width > 100"
        )
        panel.screenshot(path=artifacts / f"practice-effective-potential-{size}.png")
        tap_or_record(page, shown, artifacts / f"practice-export-{size}.png")
        assert export.locator(".export-links").is_visible()
        # out of practice mode every tab is back
        page.locator("#practice-switch").focus()
        page.keyboard.press("Space")
        assert [a.inner_text() for a in tabs.all() if a.is_visible()][:4] == [
            "Simulation",
            "Set-up",
            "Derivation",
            "Results",
        ]
    finally:
        context.close()


@pytest.mark.parametrize(
    ("step", "text"),
    [
        (
            "kinetic",
            "(1/2)*m1*l1**2*theta1_dot**2 + (1/2)*m2*(l1**2*theta1_dot**2 + l2**2*theta2_dot**2"
            " + 2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2))",
        ),
        (
            "lagrangian",
            "(1/2)*m1*l1**2*theta1_dot**2 + (1/2)*m2*(l1**2*theta1_dot**2 + l2**2*theta2_dot**2"
            " + 2*l1*l2*theta1_dot*theta2_dot*cos(theta1 - theta2))"
            " + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)",
        ),
    ],
)
def test_a_long_preview_with_parentheses_is_read_whole_on_a_phone(browser, live_server, artifacts, step, text):
    """student-f, 24: the double pendulum's T and L, a sum inside parentheses, were cut at the phone's right edge
    ("cos(θ₁ +"), to be read only by swiping inside the preview."""
    context = browser.new_context(base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True,
                                  is_mobile=True)  # fmt: skip
    page = context.new_page()
    page.set_default_timeout(60_000)
    try:
        page.goto("/scenes/double-pendulum?practice")
        page.wait_for_selector(STEP.format(step))
        page.locator(STEP.format(step)).locator("textarea[name]").fill(text)
        preview = page.locator(STEP.format(step) + " .practice-preview")
        # (the page's first typesetting waits its turn behind the step's set-up on a busy machine)
        preview.locator(".katex").first.wait_for(timeout=240_000)
        page.locator(STEP.format(step)).screenshot(path=artifacts / f"practice-double-{step}-390.png")
        # nothing to scroll sideways, nothing past the screen's edge, and the last factor is on the screen
        assert preview.evaluate("el => el.scrollWidth <= el.clientWidth + 1")
        assert preview.evaluate("el => el.getBoundingClientRect().right") <= 391
        assert page.locator("#practice .katex-error").count() == 0
    finally:
        context.close()


def test_a_phones_half_squares_and_dots_are_read_and_every_refused_sign_is_named_at_once(
    browser, live_server, artifacts
):
    # issue 41, 3: ½, ² and θ̇ from a phone's keyboard were refused one at a time
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/simple-pendulum?practice")
        page.wait_for_selector(STEP.format("kinetic"))
        box = page.locator(STEP.format("kinetic")).locator("textarea[name]")
        box.tap()
        page.keyboard.type("½ m R² θ̇²")
        page.wait_for_function(f"document.querySelector('{STEP.format('kinetic')}').dataset.typeset === 'read'")
        math = page.locator(STEP.format("kinetic") + " .practice-preview-math")
        shown = math.evaluate("el => el.querySelector('annotation')?.textContent ?? el.textContent")
        assert shown.removeprefix(r"\displaystyle ") == r"T = \frac{1}{2} m R^{2} \dot{\theta}^{2}"
        box.press("Enter")
        verdict = verdict_of(page, "kinetic")
        verdict.locator(".verdict-head").wait_for()
        assert verdict.get_attribute("data-verdict") == "correct"
        assert box.input_value() == "½ m R² θ̇²"  # nothing typed is lost
        page.locator(STEP.format("kinetic")).screenshot(path=artifacts / "practice-phone-half.png")
        # two signs the parser cannot read are named in one refusal
        potential = page.locator(STEP.format("potential")).locator("textarea[name]")
        potential.tap()
        page.keyboard.type("m g R ≤ cos θ ≥")
        potential.press("Enter")
        refused = verdict_of(page, "potential")
        refused.locator(".verdict-head").wait_for()
        said = refused.inner_text()
        # (the columns are left out: the page marks the part in what was typed)
        assert "2 characters cannot be read: '≤' and '≥' are not allowed" in said, said
        assert potential.input_value() == "m g R ≤ cos θ ≥"
    finally:
        context.close()


def test_a_long_answer_on_a_phone_shows_its_start_in_a_box_that_grows(browser, live_server, artifacts):
    # issue 41, 4: a one-line input scrolled a long answer sideways on a phone and hid its start
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/double-pendulum?practice")
        page.wait_for_selector(STEP.format("kinetic"))
        box = page.locator(STEP.format("kinetic")).locator("textarea[name]")
        one_line = box.evaluate("b => b.getBoundingClientRect().height")
        text = "1/2 (m1 + m2) l1^2 θ1'^2 + 1/2 m2 l2^2 θ2'^2 + m2 l1 l2 θ1' θ2' cos(θ1 - θ2)"
        assert len(text) >= 60
        box.tap()
        page.keyboard.type(text)
        shape = box.evaluate(
            "b => ({height: b.getBoundingClientRect().height, left: b.scrollLeft, top: b.scrollTop,"
            " wide: b.scrollWidth - b.clientWidth, tall: b.scrollHeight - b.clientHeight})"
        )
        # all of it shows, from its start: nothing scrolled away sideways or up, the box grown to its lines
        assert shape["left"] == 0 and shape["top"] == 0 and shape["wide"] <= 1 and shape["tall"] <= 1, shape
        assert shape["height"] > 1.5 * one_line, (shape, one_line)
        page.locator(STEP.format("kinetic")).screenshot(path=artifacts / "practice-long-answer-390.png")
        # Enter still checks, and adds no line to the answer
        box.press("Enter")
        verdict = verdict_of(page, "kinetic")
        verdict.locator(".verdict-head").wait_for()
        assert verdict.get_attribute("data-verdict") == "correct"
        assert box.input_value() == text
    finally:
        context.close()


def test_a_busy_server_is_said_while_the_steps_wait(page):
    """A 429 for the steps (the server busy) is waited out with its Retry-After, and the page says so meanwhile."""
    refused = busy_once(
        page, "**/api/scenes/simple-pendulum/practice", 3, "the server is busy with other users' systems; try again shortly"
    )
    page.goto("/scenes/simple-pendulum?practice")
    page.wait_for_function("/busy/.test(document.getElementById('practice-status').textContent)")
    assert page.locator("#practice-status").inner_text() == "The server is busy; the steps are asked for again in 3 s."
    page.wait_for_selector(STEP.format("lagrangian"), timeout=60_000)
    assert len(refused) == 1
    assert "steps to derive" in page.locator("#practice-status").inner_text()
