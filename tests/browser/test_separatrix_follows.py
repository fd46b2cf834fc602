"""The initial rate's separatrix note and marks follow the start and the parameters (issue 40, a professor's
review): after θ(0) = 1.313 rad the note read "from θ(0) = 1 rad" with the old speed."""

from __future__ import annotations

from urllib.parse import urlencode

import pytest

from app.engine.document.model import Document
from app.service.chapter.derivations import scene_document
from app.viz.control_ranges import separatrix_marks
from app.web.pages.playground_form import form_of, query_of
from tests.web.pages.test_playground_hoop import HOOP

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'
NOTE = ".control[data-name=theta_dot] p.ticks"


def expected(doc, theta0: float, parameters: dict[str, float] | None = None) -> str:
    """The note as the server words it, from control_ranges at that start and those parameters."""
    marks = [m for m in separatrix_marks(doc, {"theta": theta0}, parameters)["theta_dot"] if m["value"] > 0]
    return "The slider marks " + "; ".join(f"±{m['value']:.4g} rad/s ({m['label']})" for m in marks) + "."


def note_reads(page, text: str) -> None:
    page.wait_for_function("([s, t]) => document.querySelector(s).textContent.trim() === t", arg=[NOTE, text])


def test_the_pendulums_note_follows_the_start_and_gravity(page):
    doc = scene_document("simple-pendulum")
    page.goto("/scenes/simple-pendulum")
    page.wait_for_selector(READY, state="attached")
    assert page.inner_text(NOTE).strip() == expected(doc, 1.0)
    page.fill("#ctl-theta", "1.313")
    after = expected(doc, 1.313)
    assert "from θ(0) = 1.313 rad" in after
    note_reads(page, after)
    # the marks on the slider moved with it
    values = page.eval_on_selector_all("#ctl-theta_dot-ticks option", "os => os.map((o) => Number(o.dataset.value))")
    (rate,) = {round(abs(v), 9) for v in values}
    assert rate == pytest.approx(separatrix_marks(doc, {"theta": 1.313})["theta_dot"][0]["value"], rel=1e-9)
    page.fill("#ctl-g", "4.9")
    note_reads(page, expected(doc, 1.313, {"g": 4.9}))
    assert page.console_errors == []


def test_the_hoops_note_follows_its_rate(page, artifacts):
    doc = Document.model_validate(page.request.post("/api/derive", data=HOOP).json())
    page.goto("/playground?" + urlencode({**query_of(form_of(HOOP)), "stage": "whole"}, doseq=True))
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    text = page.inner_text(NOTE).strip()
    assert text == expected(doc, 1.0)
    assert "±9.27 rad/s (separatrix from θ(0) = 1 rad, by h (conserved here, not E): just reaches θ = π)" in text
    assert "just reaches θ = 0" in text
    # below w² = g/R the bottom is stable and the pair ±arccos(g/(R w²)) is gone: only the top is left
    page.fill("#ctl-w", "3")
    after = expected(doc, 1.0, {"w": 3.0})
    assert "θ = 0" not in after
    note_reads(page, after)
    page.screenshot(path=artifacts / "playground-hoop-separatrix.png", full_page=False)
    assert page.console_errors == []
