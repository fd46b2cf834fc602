"""What a professor read on a phone and on a laptop (issue 40, prof-l 7 and 9): the playground's positions wide
enough to read, the handle's words clear of the drawing.  (The first step's condition kept whole on a phone, the
double pendulum's accelerations and the room between them are checks of tests/browser/test_scene_read.py.)"""

from __future__ import annotations

import json
from urllib.parse import urlencode

import pytest

from app.web.pages.playground_form import form_of, query_of

pytestmark = pytest.mark.browser

PHONE = {"viewport": {"width": 390, "height": 844}, "has_touch": True, "is_mobile": True}
LAPTOP = {"viewport": {"width": 1366, "height": 768}}
READY = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'

# the lines of a broken display as they show: KaTeX's pieces grouped by the height they sit at
LINES = """(sel) => {
  const box = document.querySelector(sel);
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
  return { broken: box.dataset.broken === 'true', wide: box.scrollWidth > box.clientWidth + 1,
           lines: lines.map((l) => l.text.replace(/[\\u200b\\s]/g, '')) };
}"""


HOOP = {
    "coordinates": ["theta"],
    "parameters": [{"name": "m", "value": 0.1, "unit": "kg"}, {"name": "R", "value": 0.5, "unit": "m"},
                   {"name": "g", "value": 9.81, "unit": "m/s^2"}, {"name": "w", "value": 6.0, "unit": "1/s"}],
    "particles": [{"mass": "m", "position": ["R*sin(theta)*cos(w*t)", "R*sin(theta)*sin(w*t)", "-R*cos(theta)"]}],
    "potential": "-m*g*R*cos(theta)",
}  # fmt: skip

FIELDS = """() => {
  const row = document.querySelector('#particle-rows tr.row');
  const width = row.getBoundingClientRect().width;
  const inputs = [...row.querySelectorAll('input')].map((i) => ({
    name: i.name, value: i.value, width: i.getBoundingClientRect().width, fits: i.scrollWidth <= i.clientWidth + 1 }));
  return { width, inputs, page: document.documentElement.scrollWidth };
}"""


def test_the_playgrounds_positions_have_the_width_on_a_phone(browser, live_server, artifacts):
    # prof-l 7: the positions showed "R*sin(the" while the mass column was wide
    context = browser.new_context(base_url=live_server, **PHONE)
    page = context.new_page()
    page.set_default_timeout(120_000)
    try:
        page.goto("/playground?" + urlencode(query_of(form_of(HOOP)), doseq=True))
        page.wait_for_selector("#particle-rows")
        found = page.evaluate(FIELDS)
        page.locator("#particle-rows").screenshot(path=artifacts / "phone-playground-particles.png")
        mass, *positions = found["inputs"]
        assert mass["name"] == "m" and [p["name"] for p in positions] == ["x", "y", "z"], found
        # each position takes most of the row and shows all that was typed; the mass column is the narrow one
        for p in positions:
            assert p["width"] >= 0.6 * found["width"] and p["fits"], found
        assert mass["width"] < 0.3 * found["width"] and found["page"] <= 390, found
    finally:
        context.close()


def _crosses_segment(box, a, b, margin=1.0) -> bool:
    """Whether the segment a–b passes through the box (x0, y0, x1, y1), sampled every half pixel."""
    x0, y0, x1, y1 = box
    n = max(1, int(2 * ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2) ** 0.5))
    for k in range(n + 1):
        x, y = a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n
        if x0 - margin <= x <= x1 + margin and y0 - margin <= y <= y1 + margin:
            return True
    return False


def _inside_polygon(x, y, corners) -> bool:
    inside = False
    for k, (ax, ay) in enumerate(corners):
        bx, by = corners[(k + 1) % len(corners)]
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
    return inside


@pytest.mark.parametrize(
    ("scene_id", "size"), [("pulley", "phone"), ("movable-incline", "phone"), ("movable-incline", "laptop")]
)
def test_the_handle_words_cross_nothing_drawn_on_a_phone(browser, live_server, artifacts, scene_id, size):
    # prof-l 7: on a phone "drag: initial velocity (now 0)" ran across the pulley's strings and sat over the wedge;
    # on a laptop the wedge's slope is further from the handle inside it, and the words sat over the wedge there too
    context = browser.new_context(base_url=live_server, **(PHONE if size == "phone" else LAPTOP))
    page = context.new_page()
    page.set_default_timeout(120_000)
    try:
        page.goto(f"/scenes/{scene_id}")
        page.wait_for_selector(READY, state="attached")
        canvas = page.locator("canvas.mechanism").first
        canvas.scroll_into_view_if_needed()
        page.wait_for_function("document.querySelector('canvas.mechanism').dataset.links !== undefined")
        words = page.locator(".handle-label").first
        words.wait_for(state="visible")
        page.wait_for_timeout(300)
        canvas.screenshot(path=artifacts / f"handle-words-drawing-{size}-{scene_id}.png")
        assert words.text_content() == "drag: initial velocity (now 0)"
        w, c = words.bounding_box(), canvas.bounding_box()
        box = (w["x"] - c["x"], w["y"] - c["y"], w["x"] - c["x"] + w["width"], w["y"] - c["y"] + w["height"])
        assert box[0] >= -1 and box[1] >= -1 and box[2] <= c["width"] + 1 and box[3] <= c["height"] + 1, (box, c)
        links = json.loads(canvas.get_attribute("data-links"))
        assert links or scene_id == "movable-incline", links
        assert not [link for link in links if _crosses_segment(box, *link)], (box, links)
        for x, y, r in json.loads(canvas.get_attribute("data-wheels") or "[]"):
            nx, ny = min(max(x, box[0]), box[2]), min(max(y, box[1]), box[3])
            assert (nx - x) ** 2 + (ny - y) ** 2 > r**2, (box, x, y, r)
        solids = json.loads(canvas.get_attribute("data-drawn"))["solids"]
        assert (scene_id == "movable-incline") == bool(solids), solids
        for corners in solids:
            # no edge of the wedge through the words, and the words not inside it
            assert not any(_crosses_segment(box, a, corners[(k + 1) % len(corners)]) for k, a in enumerate(corners))
            assert not _inside_polygon((box[0] + box[2]) / 2, (box[1] + box[3]) / 2, corners), (box, corners)
        # still beside the handle (test_embed_views: within 52 px of it where there is room that near; the laptop's
        # wedge leaves none nearer than the slope, within twice arrows.js's reach of 40 px)
        handle = json.loads(canvas.get_attribute("data-handle"))
        dx = max(box[0] - handle["x"], 0, handle["x"] - box[2])
        dy = max(box[1] - handle["y"], 0, handle["y"] - box[3])
        assert (dx * dx + dy * dy) ** 0.5 < (52 if size == "phone" else 80), (box, handle)
    finally:
        context.close()
