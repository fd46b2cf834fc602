"""A verdict's quoted formulas typeset on a phone (issue 41, student-l 6, 7): the student's own term and
U_eff″/m_eff set by KaTeX in math italic where the words quote them, never as linear text or with underscores;
a position's note in full once and folded under the later position boxes."""

from __future__ import annotations

import pytest

from tests.browser.test_practice import STEP, answer, sized_page, verdict_of

pytestmark = pytest.mark.browser


def test_a_verdicts_quoted_term_is_typeset_on_a_phone(browser, live_server, artifacts):
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/movable-incline?practice")
        key = "acceleration:X"
        page.wait_for_selector(STEP.format(key))
        answer(page, key, "-m*g*sin(alpha)*cos(alpha)/(M + m*cos(alpha)**2)")
        verdict = verdict_of(page, key)
        name = verdict.locator(".verdict-mistake p").first
        name.wait_for()
        # the quoted term is one KaTeX formula, its letters in math italic; no linear "cos²(α)" left in the words
        math = name.locator(".prose-math .katex")
        assert math.count() == 1
        assert "\\cos^{2}" in math.locator("annotation").text_content()
        assert "cos²(α)" not in name.evaluate(
            "e => [...e.childNodes].map((n) => n.querySelector?.('.katex') ? '' : n.textContent).join('')"
        )
        font = math.locator(".mathnormal").first.evaluate("e => getComputedStyle(e).fontFamily")
        assert "KaTeX_Math" in font
        name.scroll_into_view_if_needed()
        page.screenshot(path=artifacts / "practice-quoted-term-390.png")
    finally:
        context.close()


def test_the_frequencys_rule_reads_with_subscripts_on_a_phone(browser, live_server, artifacts):
    context, page = sized_page(browser, live_server, phone=True)
    try:
        page.goto("/scenes/simple-pendulum?practice")
        key = "omega_squared"
        page.wait_for_selector(STEP.format(key))
        answer(page, key, "sqrt(g/R)")
        hint = verdict_of(page, key).locator(".verdict-hint")
        hint.wait_for()
        # ω² = U_eff″/I_eff typeset (θ an angle: its inertia is I), "eff" an upright subscript: no underscore
        # is shown anywhere in the verdict
        rule = [a for a in hint.locator("annotation").all_text_contents() if "eff" in a]
        # (with the parenthesis the words open against it: no line ends on "(")
        assert rule == ["(\\omega ^{2} = U_{\\text{eff}}'' /I_{\\text{eff}}"]
        shown = verdict_of(page, key).evaluate(
            "e => { const c = e.cloneNode(true); c.querySelectorAll('.katex-mathml').forEach((m) => m.remove());"
            " return c.textContent; }"
        )
        assert "_" not in shown
        # a later position box folds the note said in full on the first
        first, later = (
            page.locator(".practice-step[data-step='position']").first,
            page.locator(".practice-step[data-step='position']").nth(1),
        )
        assert "another origin" in first.locator(".practice-names").inner_text()
        assert "another origin" not in later.locator(".practice-names").inner_text()
        how = later.locator("details.practice-how")
        assert how.locator("summary").inner_text() == "How to write a position" and how.get_attribute("open") is None
        hint.scroll_into_view_if_needed()
        page.screenshot(path=artifacts / "practice-omega-rule-390.png")
    finally:
        context.close()
