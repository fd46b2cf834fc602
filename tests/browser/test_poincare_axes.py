"""The Poincaré section's axis titles show whole at both sizes (prof-g 59: "ntum p of θ₁" cut at the left edge)."""

from __future__ import annotations

import pytest

from tests.browser.conftest import unfold_panels

pytestmark = [pytest.mark.browser, pytest.mark.slow]


@pytest.mark.parametrize("size", [(1366, 768), (390, 844)], ids=["desk", "phone"])
def test_every_axis_title_lies_inside_the_chart(page, size):
    page.set_viewport_size({"width": size[0], "height": size[1]})
    page.goto("/scenes/double-pendulum")
    unfold_panels(page)
    page.locator("#panel-poincare").scroll_into_view_if_needed()
    page.wait_for_function("document.querySelector('#panel-poincare')?.dataset.points")
    chart = page.locator("#panel-poincare .main-svg").first.bounding_box()
    assert chart is not None
    for title in ("xtitle", "ytitle"):
        box = page.locator(f"#panel-poincare .{title}").first.bounding_box()
        assert box is not None and box["width"] > 0, title
        assert chart["x"] <= box["x"] and box["x"] + box["width"] <= chart["x"] + chart["width"], (title, box, chart)
        assert chart["y"] <= box["y"] and box["y"] + box["height"] <= chart["y"] + chart["height"], (title, box, chart)
    # the momentum's axis names it as the page prints it, p_θ₁ with θ₁ set as a subscript, and gives its unit
    ytitle = page.locator("#panel-poincare .ytitle").first
    # (Plotly puts a zero-width space around a subscript)
    assert (ytitle.text_content() or "").replace("\u200b", "").strip() == "pθ₁ (kg·m²/s)"
    # θ₁ is the one piece set lower than the line, as <sub> sets it
    lowered = ytitle.evaluate(
        "t => [...t.querySelectorAll('tspan')].filter(s => parseFloat(s.getAttribute('dy') || '0') > 0)"
        ".map(s => s.textContent)"
    )
    assert lowered == ["θ₁"], ytitle.inner_html()
