"""Numbers with honest precision: energies within the run's error read "≈ 0", changes are plotted at full
precision (no staircase from display rounding), and no null, NaN or undefined is shown after Play."""

from __future__ import annotations

import re

import pytest

from app.scenes import SCENES
from tests.browser.conftest import unfold_panels

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'
NOISE = re.compile(r"\b(null|NaN|undefined)\b")
# an energy printed as a number far below any energy of the scene: rounding noise shown as physics
TINY_ENERGY = re.compile(r"[0-9.]+ × 10⁻(1[0-9]|[89]) J")


def test_the_pulley_energy_stays_where_it_starts(page):
    page.goto("/scenes/pulley")
    page.wait_for_selector(READY, state="attached")
    # E = T + U stays where it starts: −M g c, since the statement puts U = 0 at the end masses' level and M hangs c
    # below it (the page's U keeps −Mgc); along the run T and U change, and E's last digits are the integration's
    shown = page.evaluate(
        """() => { const s = document.querySelector('[data-panel^=animation] input.scrub'); const out = [];
                   for (let k = 1; k <= 20; k++) { s.value = String(Math.round((k * Number(s.max)) / 20));
                     s.dispatchEvent(new Event('input')); out.push(document.querySelector('.energy-bars [data-key=E] .ebar-value').textContent); }
                   return out; }"""
    )
    assert len(set(shown)) == 1 and shown[0] == "−24.53 J", shown  # M g c = 2.5 kg × 9.81 m/s² × 1 m at the defaults


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_no_noise_after_play(browser, live_server, scene_id):
    context = browser.new_context(
        base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    page = context.new_page()
    page.set_default_timeout(60_000)
    page.goto(f"/scenes/{scene_id}")
    page.wait_for_selector(f'{READY}, #run-status[data-state="untrusted"]', state="attached")
    page.click("[data-panel^=animation] button[data-action=play]")
    page.wait_for_timeout(1500)
    # every panel drawn: unfold them (a phone folds them under the animation) and scroll through the page
    unfold_panels(page)
    page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
    page.wait_for_timeout(600)
    text = page.inner_text("main")
    assert not NOISE.search(text), NOISE.search(text).group(0)
    assert not TINY_ENERGY.search(text), TINY_ENERGY.search(text).group(0)
    # the energy change is plotted at full precision: E and h carry more than 7 significant digits
    digits = page.evaluate(
        """() => { const p = document.querySelector('[data-panel=energy] .plot');
                   const y = p && p.data ? p.data.find((t) => t.name === 'E = T + U').y : [];
                   return Math.max(0, ...Array.from(y).map((v) => String(Math.abs(v)).replace(/^0\\.0*|\\.|e.*$/g, '').length)); }"""
    )
    assert digits > 7 or digits == 0
    # the run status is one line, two at most, on a phone
    lines = page.evaluate(
        """() => { const m = document.querySelector('#run-status .message');
                   return Math.round(m.getBoundingClientRect().height / parseFloat(getComputedStyle(m).lineHeight)); }"""
    )
    assert lines <= 2
    context.close()
