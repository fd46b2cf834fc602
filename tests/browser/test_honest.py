"""Numbers with honest precision: energies within the run's error read "≈ 0", changes are plotted at full
precision (no staircase from display rounding), and no null, NaN or undefined is shown after Play."""

from __future__ import annotations

import re

import pytest

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

