"""The practice box typesets through the checker's parser: texts of the shared corpus (tests/data/expressions.json)
typed into the page are accepted and refused as app/engine/parser/parse.py accepts and refuses them.  The page shows
the server's verdict, so a sample of each kind is typed here; every text of the corpus is read by the engine
(tests/service/tutor/test_typesetting.py) and through the API (tests/web/api/test_api_typeset.py)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

pytestmark = pytest.mark.browser

CORPUS = json.loads((Path(__file__).parents[1] / "data" / "expressions.json").read_text())
BOX = f'.practice-step[data-key="{CORPUS["step"]}"]'
# every fifth text of each kind: the corpus's first (plain products and powers) and its later groups (θ, θ', ^,
# implicit products, names the step does not know)
SAMPLE = 5


def typed(page, text: str) -> str:
    """Type the text into the step's box; the preview's verdict once the server has answered for it."""
    box = page.locator(BOX + " textarea[name]")
    box.fill("")
    page.wait_for_function(f"!document.querySelector('{BOX}').dataset.typeset")
    box.fill(text)
    page.wait_for_function(f"document.querySelector('{BOX}').dataset.typeset")
    return page.locator(BOX).get_attribute("data-typeset")


def test_the_box_accepts_and_refuses_a_sample_of_the_corpus_as_the_parser_does(page, artifacts):
    page.set_viewport_size({"width": 1366, "height": 768})
    page.goto(f"/scenes/{CORPUS['scene']}?practice")
    page.wait_for_selector(BOX)
    preview = page.locator(BOX + " .practice-preview")
    for text in CORPUS["accepted"][::SAMPLE]:
        assert typed(page, text) == "read", text
        assert (
            preview.locator(".practice-preview-math .katex").count() == 1
            and preview.locator(".katex-error").count() == 0
        )
        assert preview.locator(".practice-preview-note").inner_text() == ""
    for case in CORPUS["refused"][::SAMPLE]:
        assert typed(page, case["text"]) == "refused", case
        # the page leaves out the column (the part is marked where it was typed), the API says it
        said = re.sub(r" at column \d+", "", case["says"])
        assert said in preview.locator(".practice-preview-note").inner_text(), case
    assert [e for e in page.console_errors if "status of 422" not in e] == []


def test_a_refused_text_clears_the_last_rendering_and_shows_the_parsers_message(page, artifacts):
    page.goto(f"/scenes/{CORPUS['scene']}?practice")
    page.wait_for_selector(BOX)
    box = page.locator(BOX + " textarea[name]")
    box.fill("m1*l1**2*theta1_dot**2/2")
    page.wait_for_function(f"document.querySelector('{BOX}').dataset.typeset === 'read'")
    # set at display size so that it may break across lines: what is typeset follows \displaystyle
    shown = page.locator(BOX + " .practice-preview-math annotation").text_content().removeprefix("\\displaystyle ")
    assert r"\dot{\theta}_{1}^{2}" in shown and shown.startswith("L =")
    # One input event: typed key by key, a slow machine reads the text on the way
    # ("... + 2^theta1" is read and would become the last good rendering).
    box.fill("m1*l1**2*theta1_dot**2/2 + 2^theta1^2")
    page.wait_for_function(f"document.querySelector('{BOX}').dataset.typeset === 'refused'")
    note = page.locator(BOX + " .practice-preview-note").inner_text()
    # a power of a power is refused with both of its readings
    assert "(2^theta1)^2" in note and "2^(theta1^2)" in note
    # the rendering of the earlier text goes: it would show something that is not what is typed now
    assert page.locator(BOX + " .practice-preview-math annotation").count() == 0
    for width, height in ((1366, 768), (390, 844)):
        page.set_viewport_size({"width": width, "height": height})
        page.locator(BOX).screenshot(path=artifacts / f"typeset-{width}.png")


def test_the_playgrounds_box_reads_the_declared_systems_names(page):
    # what the server answered the page's request for the steps: the page asks for them after its derivation and
    # its simulation (static/js/api.js inTurn), so its own jobs do not make the server refuse it; a busy server's
    # 429s and 503s, each with its Retry-After, are waited out (six tries) with the wait said in the status
    answers: list[tuple[int, str | None]] = []
    page.on(
        "response",
        lambda r: answers.append((r.status, r.headers.get("retry-after"))) if r.url.endswith("/api/practice") else None,
    )
    page.goto("/playground")
    page.locator("#practice-switch").check()
    box = '.practice-step[data-key="acceleration:x"]'
    # the example's practice steps (its derivation, on a busy machine), or the page's word that they could not load
    # (the server's answers are kept to say why)
    page.wait_for_function(
        f"document.querySelector('{box}') || /could not be loaded/.test("
        "document.getElementById('practice-status')?.textContent || '')",
        timeout=400_000,
    )
    assert page.locator(box).count() == 1, (page.locator("#practice-status").text_content(), answers)
    page.locator(box + " textarea[name]").fill("(F*cos(w*t) - b*x_dot - k*x)/m")
    page.wait_for_function(f"document.querySelector('{box}').dataset.typeset === 'read'")
    shown = page.locator(box + " .practice-preview-math annotation").text_content().removeprefix("\\displaystyle ")
    assert shown.startswith(r"\ddot{x} =") and r"\dot{x}" in shown
    page.locator(box + " textarea[name]").fill("k*y")  # y is no name of this system
    page.wait_for_function(f"document.querySelector('{box}').dataset.typeset === 'refused'")
    assert "y is not a name in this problem" in page.locator(box + " .practice-preview-note").inner_text()
