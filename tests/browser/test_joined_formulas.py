"""Formulas the engine broke by a count of characters (an aligned block whose continuation rows begin ``&\\quad``)
are typeset on one line where that line fits its box, on every scene page at 1366×768, and nothing overflows; on
a phone (390×844) the lines KaTeX wraps keep clear of each other: no fraction touches one on the next line
(prof-o F3 and F4, issue 40)."""

from __future__ import annotations

import pytest

from tests.browser.reading import CONTINUATION, JOINED, SHOW_ALL, joined

pytestmark = [pytest.mark.browser, pytest.mark.slow]

READY = "body[data-katex-errors]"

# Pairs of fractions on different lines of one display (different pieces KaTeX laid out, .katex-base) that
# overlap sideways: the vertical gap between their boxes (the fraction's vlist, as tall as numerator over
# denominator), in pixels, and the font size there.
GAPS = """() => {
  const out = [];
  for (const el of document.querySelectorAll('.math-display')) {
    if (el.offsetParent === null) continue;
    const fr = [...el.querySelectorAll('.mfrac')].filter((f) => !f.parentElement.closest('.mfrac'))
      .map((f) => ({ base: f.closest('.katex-base'), r: f.querySelector(':scope > .vlist-t').getBoundingClientRect(),
        em: parseFloat(getComputedStyle(f).fontSize) }));
    for (let i = 0; i < fr.length; i++) for (let j = i + 1; j < fr.length; j++) {
      const a = fr[i], b = fr[j];
      if (a.base === b.base) continue;
      const across = Math.min(a.r.right, b.r.right) - Math.max(a.r.left, b.r.left);
      if (across <= 0) continue;
      const gap = Math.max(a.r.top, b.r.top) - Math.min(a.r.bottom, b.r.bottom);
      out.push({ tex: (el.dataset.tex || '').slice(0, 70), gap, em: Math.min(a.em, b.em) });
    }
  }
  return out;
}"""


def _open(browser, live_server, path, width, height, phone):
    context = browser.new_context(
        base_url=live_server, viewport={"width": width, "height": height}, has_touch=phone, is_mobile=phone
    )
    page = context.new_page()
    page.set_default_timeout(120_000)
    page.goto(path)
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    page.wait_for_selector("#derivation .math-display .katex", state="attached", timeout=120_000)
    page.evaluate(SHOW_ALL)
    return context, page


def test_the_rotating_parabola_lagrangian_is_one_line_on_a_wide_page(browser, live_server):
    # prof-o F3: "− m g z" stood alone on a second line, half the column empty above it
    context, page = _open(browser, live_server, "/scenes/rotating-parabola", 1366, 768, False)
    try:
        texs = page.evaluate("() => [...document.querySelectorAll('.math-display')].map((e) => e.dataset.tex || '')")
        lagrangian = [t for t in texs if t.startswith(r"\begin{aligned}L' &=") and "m g z" in t]
        assert lagrangian and CONTINUATION.search(lagrangian[0]), "the engine no longer breaks L′: test another"
        found = page.evaluate(JOINED, {lagrangian[0]: joined(lagrangian[0])})
        assert found[0]["fits"]
        assert found[0]["lines"] == 0
        assert "- m g z" in found[0]["typeset"] and not CONTINUATION.search(found[0]["typeset"])
    finally:
        context.close()


@pytest.mark.parametrize("sid", ["pulley", "rotating-parabola"])
def test_fractions_on_wrapped_lines_do_not_touch_on_a_phone(browser, live_server, sid):
    context, page = _open(browser, live_server, f"/scenes/{sid}", 390, 844, True)
    try:
        pairs = page.evaluate(GAPS)
        assert pairs, "no fractions on adjacent lines measured"
        # a clear gap, a tenth of the type's size at least, between a denominator and the numerator below it
        touching = [(p["tex"], round(p["gap"], 2)) for p in pairs if p["gap"] < 0.1 * p["em"]]
        assert touching == [], touching
    finally:
        context.close()
