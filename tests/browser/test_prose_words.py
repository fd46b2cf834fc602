"""No sentence on a scene page types a subscript as code (issue 40, prof-e 2 / prof-f 14, 21, 35).

Every scene page, with all derivation steps shown, every "details" open and every panel drawn, is read as
the browser shows it: no text outside the typeset mathematics holds U_eff, p_θ, Q_θ, r_i, p_x₁ or U_eff''.
"""

from __future__ import annotations

import re

import pytest

from app.scenes import SCENES

pytestmark = [pytest.mark.browser, pytest.mark.slow]

CODE_SPEAK = re.compile(r"_eff|\bp_|Q_|r_i\b|_x|''|[A-Za-zΑ-Ωα-ω][\u0300-\u036f]?_[A-Za-z0-9Α-Ωα-ω]")

# every text node a reader sees outside the mathematics (KaTeX, MathML) and the code a student types
TEXTS = """() => {
  const out = [];
  const walk = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walk.nextNode(); n; n = walk.nextNode()) {
    const p = n.parentElement;
    if (!p || p.closest('.katex, math, script, style, code, pre, textarea')) continue;
    const t = n.textContent.trim();
    if (t) out.push(t);
  }
  return out;
}"""


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_no_sentence_types_a_subscript_as_code(page, scene_id):
    page.goto(f"/scenes/{scene_id}")
    page.wait_for_function("document.querySelector('#panel-animation .readout, .readout')")
    page.evaluate(
        "() => { for (const b of document.querySelectorAll('button')) if (/Show all/.test(b.textContent)) b.click();"
        " for (const d of document.querySelectorAll('details')) d.open = true; }"
    )
    # every panel draws when it scrolls into view
    for section in page.locator("section.panel").all():
        section.scroll_into_view_if_needed()
    page.wait_for_timeout(1500)
    found = [t for t in page.evaluate(TEXTS) if CODE_SPEAK.search(t)]
    assert not found, found[:5]
