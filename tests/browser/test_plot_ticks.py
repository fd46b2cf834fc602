"""A plot's tick labels stand outside its plotting area, so no curve runs through them (prof-k 13: the energy
plot's 0, 1, 2, 3, 4 sat against the area's edge and the curves that start at t = 0 ran through them)."""

from __future__ import annotations

import pytest

from tests.browser.conftest import unfold_panels

pytestmark = pytest.mark.browser

# each plotting area (Plotly's drag rectangle) and each tick label of a panel, in page pixels
BOXES = """(sel) => {
  const p = document.querySelector(sel);
  const box = (e) => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
  return {
    areas: [...p.querySelectorAll('.nsewdrag')].map(box),
    y: [...p.querySelectorAll('.yaxislayer-above text, .ytick text')].map((t) => [t.textContent, ...box(t)]),
    x: [...p.querySelectorAll('.xaxislayer-above text, .xtick text')].map((t) => [t.textContent, ...box(t)]),
  };
}"""


@pytest.mark.parametrize("size", [(1366, 768), (390, 844)], ids=["desk", "phone"])
@pytest.mark.parametrize("panel", ["#panel-energy", "#panel-phase"])
def test_tick_labels_stand_clear_of_the_plotting_area(page, size, panel):
    page.set_viewport_size({"width": size[0], "height": size[1]})
    page.goto("/scenes/simple-pendulum")
    unfold_panels(page)
    page.locator(panel).scroll_into_view_if_needed()
    page.wait_for_selector(f"{panel} .ytick text")
    page.wait_for_timeout(500)
    found = page.evaluate(BOXES, panel)
    assert found["areas"] and found["y"] and found["x"], found
    left = min(a[0] for a in found["areas"])
    bottom = max(a[3] for a in found["areas"])
    # a y label ends, and an x label begins, past a tick mark's length from the area's edge
    for text, _, _, right, _ in found["y"]:
        assert right <= left - 4, (text, right, left)
    for text, _, top, _, _ in found["x"]:
        assert top >= bottom + 4, (text, top, bottom)
