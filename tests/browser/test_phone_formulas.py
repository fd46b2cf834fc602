"""On a phone (390×844) a display formula too wide for its box is broken across lines, after its = and + signs,
and tables fit: the cases a professor found (every scene: test_scene_read.py, phone_formulas).  What cannot break (a matrix, one bracket wider than the
screen) scrolls inside its box, which then shows so: its edge fades and a round arrow points the way it goes on."""

from __future__ import annotations

import pytest

from tests.browser.reading import PHONE

pytestmark = [pytest.mark.browser, pytest.mark.slow]

MEASURE = PHONE  # each display and table as a phone shows them (tests/browser/reading.py)


# the tabletop's equilibria block fits since the words about r = 0 (the coordinates fail there) have a row of their own
@pytest.mark.parametrize("scene_id", ["simple-pendulum", "helix-bead", "rail-two-body", "tabletop-spring"])
def test_these_scenes_need_no_sideways_scrolling_on_a_phone(browser, live_server, scene_id):
    # prof-c S11: the simple pendulum's steps 14, 15, 28 and the tabletop's 3, 16, 17 were cut at the right edge
    context = browser.new_context(
        base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    page.set_default_timeout(120_000)
    try:
        page.goto(f"/scenes/{scene_id}")
        page.wait_for_selector("body[data-katex-errors]", state="attached")
        found = page.evaluate(MEASURE)
        wide = [f["tex"] for f in found["formulas"] if f["wide"]]
        # the velocity vector of the tabletop is one bracket: it may scroll; and the helix's two equations for its
        # multipliers (a linear system in λ₁, λ₂) still scroll, with their cue: breaking them is still to do
        allowed = (r"\vec v = \left(", r"\begin{aligned}\ddot{\mathcal{C}}_{1} &= 0")
        assert [w for w in wide if not w.startswith(allowed)] == [], wide
    finally:
        context.close()


MODES_LINES = """() => {
  const step = [...document.querySelectorAll('li.step')].find((s) => s.textContent.includes('Normal modes about'));
  const box = [...step.querySelectorAll('.math-display')].find((el) => (el.dataset.tex || '').includes('omega_'));
  const edge = box.getBoundingClientRect().right;
  const lines = [];
  // the lines as they show: KaTeX's pieces (.base) grouped by the height they sit at
  for (const row of box.querySelectorAll('.math-line')) {
    const bases = [...row.querySelectorAll('.katex-html > .base, .katex-html > .katex-base')];
    let line = null;
    for (const b of bases) {
      const r = b.getBoundingClientRect();
      if (!line || r.top >= line.bottom - 2) { line = { text: '', right: 0, bottom: r.bottom }; lines.push(line); }
      line.text += b.textContent;
      line.right = Math.max(line.right, r.right);
      line.bottom = Math.max(line.bottom, r.bottom);
    }
  }
  return { broken: box.dataset.broken === 'true', more: box.dataset.more || '', edge,
           wide: box.scrollWidth > box.clientWidth + 1, lines: lines.map((l) => ({ text: l.text.replace(/\u200b/g, '').trim(), right: l.right })) };
}"""


def test_the_double_pendulums_normal_modes_read_on_a_phone(browser, live_server, artifacts):
    """prof-h (issue 40): each matrix and each ω² on its own line, no "K =" left at a line's end, a value on the
    line of its ≈ ("≈ 5.747 s⁻²"), and what is wider than the screen inside a box that scrolls and says so."""
    context = browser.new_context(
        base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    page.set_default_timeout(120_000)
    try:
        page.goto("/scenes/double-pendulum")
        page.wait_for_selector("body[data-katex-errors]", state="attached")
        found = page.evaluate(MEASURE)
        assert found["formulas"]
        modes = page.evaluate(MODES_LINES)
        lines = modes["lines"]
        assert modes["broken"] and lines, modes
        texts = [line["text"] for line in lines]
        # no line ends in a relation with what it relates on the next line (K =, ω₁² =)
        assert not any(t.endswith(("=", "≈")) for t in texts), texts
        # no line begins with a bare value: the frequencies' numbers follow their ≈ (a sum's next term, 4(m₁ + m₂)…
        # after a line ending in its +, may begin with its number)
        assert not any(t[:1].isdigit() and not texts[i - 1].endswith(("+", "−")) for i, t in enumerate(texts)), texts
        assert sum("≈" in t for t in texts) == 2, texts
        # the matrices on lines of their own
        assert any(t.startswith("M=") or t.startswith("ℳ=") for t in texts) and any(
            t.startswith("K=") for t in texts
        ), texts
        # issue 40: the long radicand is named on a line of its own (Δ = …), so that each ω² fits the phone:
        # nothing goes past the screen's edge and the box never scrolls sideways
        assert any(t.startswith("Δ=") for t in texts), texts
        assert not modes["wide"] and all(line["right"] <= modes["edge"] + 1 for line in lines), modes
        page.screenshot(path=artifacts / "phone-double-pendulum-modes.png", full_page=True)
    finally:
        context.close()


PIECES = """(start) => {
  // each display whose TeX begins with one of ``start``: whether it is wider than its box, and its lines as they show
  // (KaTeX's pieces grouped by the height they sit at)
  const out = [];
  for (const box of document.querySelectorAll('.scene .math-display')) {
    if (!start.some((s) => (box.dataset.tex || '').startsWith(s))) continue;
    const lines = [];
    for (const row of box.querySelectorAll('.math-line')) {
      let line = null;
      for (const b of row.querySelectorAll('.katex-html > .base, .katex-html > .katex-base')) {
        const r = b.getBoundingClientRect();
        if (!line || r.top >= line.bottom - 2) { line = { text: '', bottom: r.bottom }; lines.push(line); }
        line.text += b.textContent;
        line.bottom = Math.max(line.bottom, r.bottom);
      }
    }
    out.push({ tex: box.dataset.tex.slice(0, 40), wide: box.scrollWidth > box.clientWidth + 1,
               lines: lines.map((l) => l.text.replace(/\\u200b/g, '').trim()) });
  }
  return out;
}"""


@pytest.mark.parametrize("scene_id", ["rolling-cylinder-wedge", "massive-pulley"])
def test_the_rigid_bodies_vectors_and_hamiltonians_fit_a_phone_and_no_line_is_a_bare_relation(
    browser, live_server, artifacts, scene_id
):
    # prof-q 5: on a phone the cylinder's r⃗_cm was clipped (now a column), its H's numerator was clipped (now
    # stacked, the term after the fraction kept), and "Time as an integral" left "=" alone on a line above the integral
    context = browser.new_context(
        base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    page.set_default_timeout(120_000)
    try:
        page.goto(f"/scenes/{scene_id}")
        page.wait_for_selector("body[data-katex-errors]", state="attached")
        page.evaluate(MEASURE)
        # the position vector's letter: R where the radius is r (notation.position)
        letter = "R" if scene_id == "rolling-cylinder-wedge" else "r"
        starts = [rf"\begin{{aligned}}\vec {letter}_{{\mathrm{{cm}}}}", r"H = \sum_k", r"\begin{aligned}t &= \int"]
        vector, hamiltonian, integral = page.evaluate(PIECES, starts)
        if scene_id == "rolling-cylinder-wedge":
            assert not vector["wide"] and not hamiltonian["wide"], (vector, hamiltonian)
        # the integral is broken after its first row; no line is a relation alone, nor ends with one (the integral's
        # "=" keeps its ∫; H's second "=" begins a line)
        assert len(integral["lines"]) >= 2, integral
        for display in (vector, hamiltonian, integral):
            assert not any(line in ("=", "≈") or line.endswith("=") for line in display["lines"]), display
        page.screenshot(path=artifacts / f"phone-rigid-{scene_id}.png", full_page=True)
    finally:
        context.close()
