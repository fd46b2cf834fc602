"""What the browser tests measure on a page, each written once: the scripts run in the page and the checks on what
they return.  ``test_scene_read.py`` runs them all on one load of each scene page at each size; the playground's
and the single cases' tests read the same scripts."""

from __future__ import annotations

import re
from pathlib import Path

from playwright.sync_api import TimeoutError as PlaywrightTimeout

# the first run has been drawn (or said why it is not trusted)
DONE = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'
# every formula on the page has been typeset (the count of KaTeX errors is written)
TYPESET = "body[data-katex-errors]"

AXE = Path(__file__).resolve().parents[2] / "node_modules" / "axe-core" / "axe.min.js"


def axe_violations(page, contrast: bool = True, exclude: tuple[str, ...] = ()) -> list[str]:
    """axe-core's serious and critical violations on the page as it stands (axe is installed from npm by
    scripts/assets.sh and put into the page here, never served by the app); ``contrast=False`` leaves out colour
    contrast (most of axe's time on a page of many formulas: it lays a grid over every element of the page);
    ``exclude``: elements axe does not read (with what is inside them)."""
    if not AXE.exists():
        raise AssertionError("axe-core is not installed: run scripts/assets.sh (npm ci installs it)")
    page.evaluate(AXE.read_text())
    return page.evaluate(
        """async ([contrast, exclude]) => (await axe.run({ include: [document], exclude: exclude.map((s) => [s]) },
                                                         { resultTypes: ['violations'],
                                                           rules: { 'color-contrast': { enabled: contrast } } }))
             .violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
             .map((v) => `${v.impact} ${v.id}: ${v.nodes.length} × ${v.nodes[0].target.join(' ')} (${v.help})`)""",
        [contrast, list(exclude)],
    )


# WCAG's contrast ratio of the text of each visible element ``selectors`` name against the first opaque background
# behind it (its own or an ancestor's; the page's white where none is): each under 4.5 (3 for large text: 24 px, or
# 18.66 px bold) with its ratio.  For elements drawn on plain backgrounds, as axe's rule finds them there; text of a
# transparent colour (KaTeX's invisible copies that hold a row's room) is not read.
CONTRAST = """(selectors) => {
  const rgb = (c) => (c.match(/[\\d.]+/g) || []).map(Number);
  const lum = ([r, g, b]) => { const f = (v) => { v /= 255; return v <= 0.03928 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4; };
                               return 0.2126 * f(r) + 0.7152 * f(g) + 0.0722 * f(b); };
  const out = [];
  for (const el of document.querySelectorAll(selectors.join(','))) {
    if (!el.textContent.trim() || !el.getClientRects().length) continue;
    const style = getComputedStyle(el);
    const fg = rgb(style.color);
    if (fg.length === 4 && fg[3] === 0) continue;
    let bg = [255, 255, 255];
    for (let a = el; a; a = a.parentElement) {
      const c = rgb(getComputedStyle(a).backgroundColor);
      if (c.length === 3 || (c.length === 4 && c[3] === 1)) { bg = c.slice(0, 3); break; }
    }
    const [hi, lo] = [lum(fg.slice(0, 3)), lum(bg)].sort((x, y) => y - x);
    const ratio = (hi + 0.05) / (lo + 0.05);
    const size = parseFloat(style.fontSize), bold = Number(style.fontWeight) >= 700;
    if (ratio < (size >= 24 || (bold && size >= 18.66) ? 3 : 4.5)) out.push([el.textContent.trim().slice(0, 30), ratio.toFixed(2)]);
  }
  return out;
}"""


# Every step shown and every "details" open, once the fonts are in and the page has laid them out.
OPEN_ALL = """
  for (const d of document.querySelectorAll('details')) d.open = true;
  for (const b of document.querySelectorAll('button.all-steps[aria-expanded=false]')) b.click();
  await document.fonts.ready;
  for (let i = 0; i < 4; i++) await new Promise((r) => requestAnimationFrame(r));
  await new Promise((r) => setTimeout(r, 300));
"""
SHOW_ALL = "async () => {" + OPEN_ALL + "}"

# the page marks a box that scrolls (data-more) at the frame after its layout changes: they agree once it has
CUES_SETTLED = (
    "() => [...document.querySelectorAll('.math-display')].every("
    "b => (b.scrollWidth > b.clientWidth + 1) === Boolean(b.dataset.more))"
)

# Each typeset display formula: its own width, the width of the box it sits in, and whether that box scrolls
# and can be focused (tabindex, label) -- the one place a wide formula may go on a phone.
# (the page marks wide boxes as they appear, a ResizeObserver, and once the fonts are in: OPEN_ALL lets it see them)
WIDTHS = (
    "async () => {"
    + OPEN_ALL
    + """  const out = [];
  for (const el of document.querySelectorAll('.math-display')) {
    if (!el.querySelector('.katex') || el.offsetParent === null) continue;
    const style = getComputedStyle(el);
    out.push({
      tex: (el.dataset.tex || '').slice(0, 80),
      formula: el.scrollWidth,
      box: el.clientWidth,
      scrolls: ['auto', 'scroll'].includes(style.overflowX),
      focusable: el.tabIndex >= 0 && !!el.getAttribute('aria-label'),
      // the visible cue that it goes on: the right edge faded and a round arrow there (data-more, site.css)
      cue: (el.dataset.more || '').includes('right') && (style.maskImage || style.webkitMaskImage || 'none') !== 'none'
        && style.backgroundImage.includes('svg'),
    });
  }
  return out;
}"""
)


def width_problems(found: list[dict], phone: bool) -> list:
    """No formula wider than its box at a desktop size; on a phone what is wider scrolls in a box the keyboard
    reaches and that shows it goes on, and a formula that fits shows no such cue."""
    if not found:
        return ["no display formula measured"]
    wide = [f for f in found if f["formula"] > f["box"] + 1]
    if not phone:
        return [(f["tex"][:60], f["formula"], f["box"]) for f in wide]
    problems: list = [("cannot be reached", f["tex"]) for f in wide if not (f["scrolls"] and f["focusable"])]
    problems += [("scrolls without a cue", f["tex"]) for f in wide if not f["cue"]]
    problems += [("a cue on a formula that fits", f["tex"]) for f in found if f["cue"] and f["formula"] <= f["box"] + 1]
    return problems


# On a phone: each shown display (its step, whether it is wider than its box, broken by the page, showing the cue)
# and each table (wider than its box, the cue, cells clipped, its right edge).
PHONE = (
    "async () => {"
    + OPEN_ALL
    + """  const cue = (el) => {
    const style = getComputedStyle(el);
    return (el.dataset.more || '').includes('right')
      && (style.maskImage || style.webkitMaskImage || 'none') !== 'none' && style.backgroundImage.includes('svg');
  };
  const formulas = [];
  for (const el of document.querySelectorAll('.scene .math-display')) {
    if (!el.querySelector('.katex') || el.offsetParent === null) continue;
    formulas.push({
      step: el.closest('li.step')?.id || '', tex: (el.dataset.tex || '').slice(0, 70),
      wide: el.scrollWidth > el.clientWidth + 1, broken: el.dataset.broken === 'true', cue: cue(el),
    });
  }
  const tables = [];
  for (const t of document.querySelectorAll('.scene table')) {
    if (t.offsetParent === null) continue;
    const box = t.closest('.table-scroll, .data-summary .table, .frequencies') || t.parentElement;
    const clipped = [...t.querySelectorAll('th, td')].filter((c) => c.scrollWidth > c.clientWidth + 1
      && !c.querySelector('.math-display')).length;
    tables.push({ name: t.className || t.closest('section')?.id || '', wide: box.scrollWidth > box.clientWidth + 1,
      cue: cue(box), clipped, right: t.getBoundingClientRect().right });
  }
  return { formulas, tables };
}"""
)


def phone_problems(found: dict) -> list:
    """A phone breaks the first step's two lines rather than scrolling them; what still overflows scrolls with the
    fade and the arrow and what fits shows none; every table fits or scrolls with the cue, the parameters and the
    errata always fit, and no cell is clipped."""
    formulas, tables = found["formulas"], found["tables"]
    if not formulas:
        return ["no display formula measured"]
    wide = [f for f in formulas if f["wide"]]
    problems: list = [("scrolls without a cue", f["tex"]) for f in wide if not f["cue"]]
    problems += [("a cue on a formula that fits", f["tex"]) for f in formulas if f["cue"] and not f["wide"]]
    first = [f for f in formulas if f["step"] == "step-1"]
    if not first or any(f["wide"] for f in first):
        problems.append(("the first step scrolls", first))
    for t in tables:
        if t["clipped"] or (t["wide"] and not t["cue"]):
            problems.append(("table", t))
        if t["name"] in ("parameters", "errata") and (t["wide"] or t["right"] > 390):
            problems.append(("table wider than the phone", t))
    return problems


# code-speak: a subscript or a prime typed as a programmer types it (U_eff, p_θ, Q_θ, r_i, p_x₁, U_eff'')
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


def code_speak(page) -> list[str]:
    """The sentences of the page (outside the mathematics) that type a subscript as code."""
    return [t for t in page.evaluate(TEXTS) if CODE_SPEAK.search(t)]


# every plot shown has its data (the work-precision chart draws once its report is measured: not waited for)
PLOTS_DRAWN = """() => [...document.querySelectorAll('section.panel:not(#panel-work-precision) .plot')]
  .filter((p) => p.offsetParent !== null).every((p) => p.data && p.data.length > 0)"""


def draw_panels(page) -> None:
    """Every plot panel scrolled into view, and drawn: each draws when it first comes into view (or when the browser
    is idle).  After 5 s the page is read as it stands (the checks then say what is missing)."""
    for section in page.locator("section.panel").all():
        section.scroll_into_view_if_needed()
    try:
        page.wait_for_function(PLOTS_DRAWN, timeout=5_000)
    except PlaywrightTimeout:
        pass


# the engine's continuation of a row (app/engine/display/breaking.py, _block): a row separator, then the quad indenting it
CONTINUATION = re.compile(r"\s*\\\\(?:\[[^\]]*\])?\s*&\\quad(?![a-zA-Z])\s*")

# Each shown display the engine broke: the TeX KaTeX typeset (its annotation, or its lines' when broken apart),
# whether its one-line form (given) fits a box of the same width, and whether the display overflows.
JOINED = """async (joined) => {
  const out = [];
  for (const el of document.querySelectorAll('.math-display')) {
    const tex = el.dataset.tex || '';
    if (!(tex in joined) || el.offsetParent === null) continue;
    // the one line's own width (an inline box beside the display, in its type), against the display's room
    const probe = document.createElement('span');
    const style = getComputedStyle(el);
    probe.style.cssText = `position:absolute;left:0;top:0;visibility:hidden;white-space:nowrap;font-size:${style.fontSize}`;
    document.body.append(probe);
    window.katex.render("\\\\displaystyle " + joined[tex], probe, { displayMode: false, throwOnError: false });
    const room = el.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
    const fits = probe.getBoundingClientRect().width <= room + 1;
    probe.remove();
    const typeset = [...el.querySelectorAll('annotation')].map((a) => a.textContent).join(' ');
    // set apart in lines of its own (breaking.js's .math-line), or typeset whole
    const lines = el.querySelectorAll('.math-line').length;
    out.push({ tex: tex.slice(0, 70), fits, typeset, lines, wide: el.scrollWidth > el.clientWidth + 1 });
  }
  return out;
}"""


def joined(tex: str) -> str:
    """The display's own rows joined (at the top level: a numerator stacked inside a fraction keeps its lines)."""
    out, depth, last, i = [], 0, 0, 0
    while i < len(tex):
        c = tex[i]
        m = CONTINUATION.match(tex, i) if depth == 0 else None
        if m:
            out.append(tex[last:i] + " ")
            last = i = m.end()
            continue
        depth += (c == "{") - (c == "}")
        i += 2 if c == "\\" else 1
    return "".join(out) + tex[last:]


# the caption is written (level sets of one coordinate, or the projection of several)
WRITTEN = "document.querySelector('#panel-phase .readout')?.textContent.includes('against its rate')"
NUMBER = r"(−?[\d.]+(?: × 10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)"


def number(text: str) -> float:
    if "×" in text:
        mantissa, power = text.split(" × 10")
        digits = power.replace("⁻", "-").translate(str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789"))
        return float(mantissa.replace("−", "-")) * 10 ** int(digits)
    return float(text.replace("−", "-"))


def extreme(t: list[float], x: list[float], highest: bool) -> float:
    """The run's extreme on one side: the vertex of the parabola through the extreme sample and its neighbours."""
    sign = 1 if highest else -1
    k = max(range(len(x)), key=lambda i: sign * x[i])
    if 0 < k < len(x) - 1:
        a, b, c = x[k - 1], x[k], x[k + 1]
        curve = a - 2 * b + c
        if curve != 0:
            return b - (c - a) ** 2 / (8 * curve)
    return x[k]


# The lines of the displays whose TeX begins with one of ``start`` (or of the first display holding ``has`` in the
# first step whose title begins with ``step``, or of the display ``selector`` names), as they show: KaTeX's pieces (.base) grouped by the height they sit at (``text`` trimmed, ``bare``
# without any space); whether the page broke the display, whether it is wider than its box (it scrolls), where its
# box ends.
LINES = """({ start = [], step, has = '', selector }) => {
  const titled = step && [...document.querySelectorAll('li.step')].find((s) => s.querySelector('.step-title')?.textContent.startsWith(step));
  const boxes = selector ? [document.querySelector(selector)] : step ? [[...titled.querySelectorAll('.math-display')].find((b) => (b.dataset.tex || '').includes(has))]
    : [...document.querySelectorAll('.scene .math-display')].filter((b) => start.some((s) => (b.dataset.tex || '').startsWith(s)));
  return boxes.map((box) => {
    const lines = [];
    for (const row of box.querySelectorAll('.math-line')) {
      let line = null;
      for (const b of row.querySelectorAll('.katex-html > .base, .katex-html > .katex-base')) {
        const r = b.getBoundingClientRect();
        if (!line || r.top >= line.bottom - 2) { line = { text: '', right: 0, bottom: r.bottom }; lines.push(line); }
        line.text += b.textContent;
        line.right = Math.max(line.right, r.right);
        line.bottom = Math.max(line.bottom, r.bottom);
      }
    }
    return { tex: (box.dataset.tex || '').slice(0, 60), broken: box.dataset.broken === 'true',
             wide: box.scrollWidth > box.clientWidth + 1, edge: box.getBoundingClientRect().right,
             lines: lines.map((l) => ({ text: l.text.replace(/\\u200b/g, '').trim(), bare: l.text.replace(/[\\u200b\\s]/g, ''),
                                        right: l.right })) };
  });
}"""

# The double pendulum's "Accelerations" display (``box``) and its outermost fractions (``fracs``: not those inside
# them nor the invisible copies of spacedRows' rows, KaTeX's .rlap).
ACCELERATION_FRACTIONS = """
  const step = [...document.querySelectorAll('li.step')].find((s) => s.querySelector('.step-title')?.textContent === 'Accelerations');
  const box = step.querySelector('.math-display');
  const fracs = [...box.querySelectorAll('.mfrac')].filter((f) => !f.parentElement.closest('.mfrac, .rlap'));
"""

# The double pendulum's accelerations: how wide their display is past its box, and on how many lines each of the
# outermost fractions' numerators is set (not the invisible copies of spacedRows' rows).
ACCELERATIONS = (
    "() => {"
    + ACCELERATION_FRACTIONS
    + """
  return { wide: box.scrollWidth - box.clientWidth, errors: box.querySelectorAll('.katex-error').length,
           fractions: fracs.length, broken: box.dataset.broken === 'true',
           rows: fracs.map((f) => [...f.querySelectorAll('.mtable .col-align-l > .vlist-t > .vlist-r > .vlist > span')]
             .filter((s) => s.textContent.trim()).length) };
}"""
)

# The room between the double pendulum's two stacked accelerations: from the lowest glyph box under θ̈₁'s fraction
# line to the highest over θ̈₂'s (the outermost fractions, not those inside them nor spacedRows' invisible copies).
FRACTION_GAP = (
    "() => {"
    + ACCELERATION_FRACTIONS
    + """
  const lines = fracs.map((f) => f.querySelector('.frac-line').getBoundingClientRect());
  const glyphs = (f) => {
    const out = [], walk = document.createTreeWalker(f, NodeFilter.SHOW_TEXT);
    while (walk.nextNode()) {
      if (!walk.currentNode.textContent.trim()) continue;
      const range = document.createRange(); range.selectNodeContents(walk.currentNode);
      out.push(range.getBoundingClientRect());
    }
    return out;
  };
  const den = glyphs(fracs[0]).filter((r) => r.top >= lines[0].bottom);
  const num = glyphs(fracs[1]).filter((r) => r.bottom <= lines[1].top);
  return { count: fracs.length, gap: Math.min(...num.map((r) => r.top)) - Math.max(...den.map((r) => r.bottom)) };
}"""
)
