"""No typeset formula wider than its box: every scene page with every step shown, and the playground's
double pendulum, at 1366×768 (nothing may overflow) and 390×844 with touch (a formula is broken across lines where it can, and may only
be wider than its box inside a box that scrolls, that the keyboard can reach and that shows it goes on)."""

from __future__ import annotations

from urllib.parse import urlencode

import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from app.scenes import SCENES

pytestmark = [pytest.mark.browser, pytest.mark.slow]

READY = "body[data-katex-errors]"

# Each typeset display formula: its own width, the width of the box it sits in, and whether that box scrolls
# and can be focused (tabindex, label) -- the one place a wide formula may go on a phone.
MEASURE = """async () => {
  for (const d of document.querySelectorAll('details')) d.open = true;
  for (const b of document.querySelectorAll('button.all-steps[aria-expanded=false]')) b.click();
  // the page marks wide boxes as they appear (a ResizeObserver) and once the fonts are in: let it see them
  await document.fonts.ready;
  for (let i = 0; i < 3; i++) await new Promise((r) => requestAnimationFrame(r));
  const out = [];
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

# a user's double pendulum typed as two particles (the playground's shareable address)
PLAYGROUND_DOUBLE_PENDULUM = "/playground?" + urlencode(
    {
        "q": "theta1, theta2",
        "form": "particles",
        "pn": ["m1", "m2", "l1", "l2", "g"],
        "pv": ["1", "1", "1", "1", "9.81"],
        "m": ["m1", "m2"],
        "x": ["l1*sin(theta1)", "l1*sin(theta1) + l2*sin(theta2)"],
        "y": ["0", "0"],
        "z": ["-l1*cos(theta1)", "-l1*cos(theta1) - l2*cos(theta2)"],
        "U": "-(m1 + m2)*g*l1*cos(theta1) - m2*g*l2*cos(theta2)",
    },
    doseq=True,
)

PAGES = [f"/scenes/{sid}" for sid in SCENES] + [PLAYGROUND_DOUBLE_PENDULUM]


def _measure(page, path):
    page.goto(path)
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    page.wait_for_selector("#derivation .math-display .katex", state="attached", timeout=120_000)
    assert page.locator(".katex-error").count() == 0
    # the scroll cues are set at the frame after a box's layout changes (fonts loading, formulas broken):
    # measured once they agree with the boxes, or after 15 s as they are (the assertions then say which)
    try:
        page.wait_for_function(
            "() => [...document.querySelectorAll('.math-display')].every("
            "b => (b.scrollWidth > b.clientWidth + 1) === Boolean(b.dataset.more))",
            timeout=15_000,
        )
    except PlaywrightTimeout:
        pass
    return page.evaluate(MEASURE)


@pytest.mark.parametrize("path", PAGES, ids=[p.split("?")[0].rsplit("/", 1)[-1] or "playground" for p in PAGES])
def test_no_formula_wider_than_its_box(browser, live_server, artifacts, path):
    name = path.split("?")[0].rsplit("/", 1)[-1]
    for width, height, phone in ((1366, 768, False), (390, 844, True)):
        context = browser.new_context(
            base_url=live_server, viewport={"width": width, "height": height}, has_touch=phone, is_mobile=phone
        )
        page = context.new_page()
        page.set_default_timeout(120_000)
        try:
            found = _measure(page, path)
            assert found, "no display formula measured"
            page.screenshot(path=artifacts / f"widths-{name}-{width}.png", full_page=True)
            wide = [f for f in found if f["formula"] > f["box"] + 1]
            if not phone:
                assert wide == [], [(f["tex"][:60], f["formula"], f["box"]) for f in wide]
            else:
                assert all(f["scrolls"] and f["focusable"] for f in wide), [f for f in wide if not f["focusable"]][:5]
                # every one shows that it scrolls, and a formula that fits shows nothing
                assert all(f["cue"] for f in wide), [f["tex"] for f in wide if not f["cue"]][:5]
                assert not any(f["cue"] for f in found if f["formula"] <= f["box"] + 1)
        finally:
            context.close()
