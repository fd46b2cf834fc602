"""Every scene page read once at each size, 1366×768 and 390×844 with touch, as a reader meets it and then with
everything open: each check below runs on that one load, in the order that leaves the page as the next expects
(the first screen, the panels, axe, then every step shown, then Play on a phone).  A failing check is named in
the failure with what it found; the others still run.

What each check holds (its name says where it came from):
- ``loads``: the first run is drawn (ready on a desktop; ready, untrusted or warning on a phone) and every
  formula is typeset without a KaTeX error.
- ``panels_drawn`` (desktop): every plot panel draws data, with a text alternative and a data table; the
  animation draws its bodies and the energy bars.
- ``no_overflow`` (phone): nothing in the page goes past the screen's right edge, the page never scrolls sideways.
- ``reads_in_order`` (phone): title, statement, animation, plots, controls, figure, parameters, derivation, in
  that order, the statement on the first screen.
- ``labels_clear`` (phone): each mass's label nearer its mass than any other body or the velocity handle; the
  handle's words over no label, body or wheel.
- ``phase_caption`` (desktop): the phase portrait's sentence agrees with the run (a named turning point is the
  run's extreme, a run stopped by its event is said to end there, nothing is sent to infinity).
- ``action_panel`` (desktop): the action panel opens before the start's first kinetic focus, on a minimum.
- ``axe``: no serious or critical axe-core violation once the panels are drawn; the formulas' glyphs' colour
  contrast measured on each formula (``FORMULAS``), and on a phone only where its colours differ from the
  desktop's (``PHONE_ONLY``).
- ``formula_widths``: with every step shown, no formula wider than its box on a desktop; on a phone what is
  wider scrolls in a box the keyboard reaches and that shows it goes on.
- ``phone_formulas`` (phone): wide formulas broken where they can be, tables fit or scroll with the cue.
- ``joined_formulas`` (desktop): a formula the engine broke by its length is one line where that line fits.
- ``first_step_whole`` (phone): the first step's condition δq(t₀) = δq(t₁) = 0 on one line, no line beginning
  with a bare 0 or ending in a relation.
- ``no_sideways_formula`` (phone; the scenes of ``NO_SIDEWAYS``): no display formula scrolls sideways but the
  named ones.
- ``modes_lines`` (phone; the double pendulum): each matrix and each ω² on a line of its own, the radicand named
  (Δ = …), no value alone at a line's start, nothing past the screen's edge.
- ``rigid_pieces`` (phone; the rolling cylinder and the massive pulley): the centre of mass's vector, H and the
  time as an integral fit, and no line is a relation alone or ends in one.
- ``accelerations_fit`` (the double pendulum): θ̈₁ and θ̈₂ fit their box, their numerators on two lines on a
  desktop and on more on a phone.
- ``fractions_apart`` (desktop; the double pendulum): θ̈₁'s denominator and θ̈₂'s numerator 8 px apart or more.
- ``block_on_slope`` (the two inclines): the block's base on the slope and between its ends, a rectangle (the
  pixel over the middle of its base is the block's colour), and on the wedge no label hides the slope.
- ``wheel_wrap`` (desktop; the pulley): the middle mass's string wraps under its wheel.
- ``labels_off_the_ground`` (the coupled oscillators): at the start, a third of the way and the end, each mass's
  label covers no floor, wall or hatching.
- ``band_under_ceiling`` (the massive pulley): the masses named m₁ and m₂; at the run's end the band saying why
  it ended lies below the ceiling's hatching.
- ``no_code_speak``: no sentence types a subscript as code (U_eff, p_θ, r_i …).
- ``no_noise_after_play`` (phone): after Play no null, NaN, undefined or rounding noise shown as an energy; the
  energy plotted at full precision; the run's status on two lines at most.
- ``no_console_error``: nothing logged as an error, no uncaught exception, over the whole reading.
"""

from __future__ import annotations

import json
import math
import re

import pytest
from playwright.sync_api import Error as PlaywrightError
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from app.scenes import SCENES
from tests.browser.conftest import unfold_panels
from tests.browser.reading import (
    ACCELERATIONS,
    CONTINUATION,
    CONTRAST,
    CUES_SETTLED,
    DONE,
    FRACTION_GAP,
    JOINED,
    LINES,
    NUMBER,
    PHONE,
    SHOW_ALL,
    TYPESET,
    WIDTHS,
    WRITTEN,
    axe_violations,
    code_speak,
    draw_panels,
    extreme,
    joined,
    number,
    phone_problems,
    width_problems,
)

pytestmark = [pytest.mark.browser, pytest.mark.slow]

SIZES = {"desktop": (1366, 768, False), "phone": (390, 844, True)}
ORDER = [
    "h1",
    ".statement",
    "canvas.mechanism",
    ".panels",
    "#controls",
    "figure.setup",
    "table.parameters",
    "#derivation",
]
NOISE = re.compile(r"\b(null|NaN|undefined)\b")
# an energy printed as a number far below any energy of the scene: rounding noise shown as physics
TINY_ENERGY = re.compile(r"[0-9.]+ × 10⁻(1[0-9]|[89]) J")


class Reading:
    """One scene page at one size, its first run (the server's answer) and the console's errors."""

    def __init__(self, page, base: str, scene_id: str, size: str, run: dict, errors: list[str]):
        self.page, self.base, self.scene_id, self.size, self.run, self.errors = page, base, scene_id, size, run, errors
        self.phone = SIZES[size][2]
        self.measured: dict = {"formulas": []}  # the phone's displays and tables (``phone_formulas``)


def loads(r: Reading) -> None:
    state = r.page.get_attribute("#run-status", "data-state")
    allowed = ("ready", "untrusted", "warning") if r.phone else ("ready",)
    assert state in allowed, (state, r.page.inner_text("#run-status .message"))
    assert r.page.locator(".katex-error").count() == 0
    assert r.page.evaluate("document.body.dataset.katexErrors") == "0"
    # every formula typeset (one may hold several KaTeX trees: a stacked display's rows spaced by raised copies)
    assert r.page.locator(".math:has(.katex)").count() == r.page.locator(".math").count() > 0


def panels_drawn(r: Reading) -> None:
    page = r.page
    for section in page.locator("[data-panel]").all():
        kind = section.get_attribute("data-panel")
        if kind in ("work-precision", "poincare", "action", "modes"):
            continue  # drawn when scrolled into view, each tested on its own (test_beyond, test_action, …)
        if kind.startswith("animation"):
            bodies = page.evaluate(
                f"JSON.parse(document.querySelector('[data-panel={kind}] canvas').dataset.bodies || '[]')"
            )
            assert bodies, f"{kind} drew no body"
            assert page.locator(".energy-bars .ebar").count() >= 3
            continue
        plot = section.locator(".plot")
        # panels out of view are drawn when the browser is idle after the server's run
        page.wait_for_function("(el) => el.data && el.data.length > 0", arg=plot.element_handle())
        assert plot.locator(".main-svg").count() > 0, f"{kind} was not drawn"
        assert section.locator(".readout").inner_text().strip(), f"{kind} has no text alternative"
        assert section.locator(".data-summary table").count() == 1, f"{kind} has no data table"


def no_overflow(r: Reading) -> None:
    r.page.wait_for_timeout(300)
    width = r.page.evaluate("document.documentElement.scrollWidth")
    wide = r.page.evaluate(
        """() => [...document.querySelectorAll('main *')].filter((el) => el.getBoundingClientRect().right > 391
             && !el.ownerSVGElement && !el.closest('.table-scroll, .math-display, .data-summary .table, math, .katex-display'))
             .map((el) => el.tagName + '.' + el.className).slice(0, 5)"""
    )
    assert width <= 390 and wide == [], (width, wide)


def reads_in_order(r: Reading) -> None:
    tops = r.page.evaluate(
        "(sels) => sels.map((s) => { const e = document.querySelector('.scene ' + s); return e ? e.getBoundingClientRect().top + scrollY : null; })",
        ORDER,
    )
    present = [(s, t) for s, t in zip(ORDER, tops, strict=True) if t is not None]
    assert [s for s, _ in sorted(present, key=lambda x: x[1])] == [s for s, _ in present], present
    assert r.page.locator(".scene .statement").bounding_box()["y"] < 844  # the statement on the first screen


# the wheels each scene draws (the pulleys' three, the rolling cylinder, the massive pulley's one)
WHEELS = {"pulley": 3, "rolling-cylinder-wedge": 1, "massive-pulley": 1}


def labels_clear(r: Reading) -> None:
    # prof-g 31, prof-h 7, prof-k 12: on a phone each mass's label sits nearer its mass than any other body or the
    # velocity handle; the handle's words ("drag: initial velocity") cover no label, no body and no wheel
    page = r.page
    canvas = page.locator("canvas.mechanism").first
    canvas.scroll_into_view_if_needed()
    page.wait_for_function("document.querySelector('canvas.mechanism').dataset.bodies !== undefined")
    page.wait_for_timeout(300)
    bodies = {b["label"]: (b["x"], b["y"]) for b in json.loads(canvas.get_attribute("data-bodies"))}
    # a scene of several masses labels each (one mass is not labelled)
    labels = {x["label"]: x["box"] for x in json.loads(canvas.get_attribute("data-labels") or "[]")}
    assert labels or len(bodies) < 2, bodies
    wheels = json.loads(canvas.get_attribute("data-wheels") or "[]")
    if r.scene_id in WHEELS:
        assert len(wheels) == WHEELS[r.scene_id], wheels
    handle = canvas.get_attribute("data-handle")
    others = {"the velocity handle": tuple(json.loads(handle).values())} if handle else {}
    if len(bodies) > 1:
        for label, (x0, y0, x1, y1) in labels.items():
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            own = ((bodies[label][0] - cx) ** 2 + (bodies[label][1] - cy) ** 2) ** 0.5
            for name, (x, y) in {**{k: v for k, v in bodies.items() if k != label}, **others}.items():
                assert own <= ((x - cx) ** 2 + (y - cy) ** 2) ** 0.5, (label, name, labels, bodies, handle)
    words = page.locator(".handle-label")
    if not (words.count() and words.first.is_visible()):
        return
    w, c = words.first.bounding_box(), canvas.bounding_box()
    left, top = w["x"] - c["x"], w["y"] - c["y"]
    right, bottom = left + w["width"], top + w["height"]
    for label, (x0, y0, x1, y1) in labels.items():
        assert not (x0 < right and x1 > left and y0 < bottom and y1 > top), ("words over a label", label, labels, w)
    for label, (x, y) in bodies.items():
        assert not (left - 6 < x < right + 6 and top - 6 < y < bottom + 6), ("words over a body", label, bodies, w)
    for x, y, radius in wheels:
        # the nearest point of the words' box to the wheel's centre lies outside its rim
        nx, ny = min(max(x, left), right), min(max(y, top), bottom)
        assert (nx - x) ** 2 + (ny - y) ** 2 > radius**2, ("words over a wheel", wheels, w)


def phase_caption(r: Reading) -> None:
    page = r.page
    if not page.locator("#panel-phase").count():
        return
    page.locator("#panel-phase").scroll_into_view_if_needed()
    page.wait_for_function(WRITTEN)
    text = page.locator("#panel-phase .readout").text_content() or ""
    turning = page.locator("#panel-phase").get_attribute("data-turning")
    coordinate = page.locator("#panel-phase").get_attribute("data-coordinate")
    assert "infinity" not in text, text
    if r.run["stats"]["event"] is not None:
        # a run stopped by its event ends there: the caption says when, and sends nothing off without bound
        assert "the run ends at t = " in text and "without bound" not in text, text
    named = re.search(r"it turns at (\S+) = " + NUMBER, text)
    if named:
        x_t = float(turning or "nan")
        assert abs(number(named.group(2)) - x_t) <= 5e-4 * abs(x_t), (named.group(0), x_t)
        # the turning point is where the run's coordinate has its extreme on that side
        t, x = r.run["t"], r.run["state"][coordinate]
        hi, lo = extreme(t, x, True), extreme(t, x, False)
        assert min(abs(hi - x_t), abs(lo - x_t)) <= 2e-3 * max(abs(x_t), hi - lo), (text, x_t, hi, lo)


def action_panel(r: Reading) -> None:
    # the opening τ is the ordinary case: before the start's first kinetic focus (the server's t* over the whole
    # run), so the true path drawn is a minimum of S
    page, panel = r.page, "#panel-action"
    if not page.locator(panel).count():
        return
    answer = page.request.post(
        f"{r.base}/api/scenes/{r.scene_id}/action", data={"t_end": SCENES[r.scene_id].t_end, "epsilons": [0]}
    ).json()
    page.locator(panel).scroll_into_view_if_needed()
    page.wait_for_function(f"document.querySelector('{panel}')?.dataset.source === 'server'")
    tau = float(page.locator("#action-T").input_value())
    if answer["conjugate_time"] is not None:
        assert tau < answer["conjugate_time"], (tau, answer["conjugate_time"])
    assert page.locator(panel).get_attribute("data-kind") == "minimum", (tau, answer["conjugate_time"])


# What a phone shows that a desktop does not, in colours of its own: the panels' fold buttons and the errata set as
# cards.  No other colour of static/css depends on the screen's size, so the rest of the page's colour contrast is
# the desktop reading's (axe's colour contrast is two thirds of its time on a page of many formulas).
PHONE_ONLY = [".panels > .panel > h3 > button.fold", ".errata td"]
# A formula's glyphs (KaTeX's HTML, hidden from assistive technology, which reads its MathML) take the colour of
# the formula itself, unless coloured inline: their contrast is measured there, not glyph by glyph by axe (a third
# of axe's time on the double pendulum's page).
FORMULAS = [".katex", ".katex-html [style*=color]"]


def axe(r: Reading) -> None:
    r.page.evaluate("window.scrollTo(0, document.body.scrollHeight)")
    draw_panels(r.page)
    if r.phone:
        assert axe_violations(r.page, contrast=False) == []
        assert r.page.evaluate(CONTRAST, PHONE_ONLY) == []
    else:
        assert axe_violations(r.page, exclude=(".katex-html",)) == []
        assert r.page.evaluate(CONTRAST, FORMULAS) == []


def formula_widths(r: Reading) -> None:
    r.page.evaluate(SHOW_ALL)
    try:
        r.page.wait_for_function(CUES_SETTLED, timeout=15_000)
    except PlaywrightTimeout:
        pass  # measured as they are: the assertions say which box disagrees
    assert (problems := width_problems(r.page.evaluate(WIDTHS), r.phone)) == [], problems[:5]


def phone_formulas(r: Reading) -> None:
    r.measured = r.page.evaluate(PHONE)
    assert (problems := phone_problems(r.measured)) == [], problems[:5]


def joined_formulas(r: Reading) -> None:
    texs = r.page.evaluate("() => [...document.querySelectorAll('.math-display')].map((e) => e.dataset.tex || '')")
    found = r.page.evaluate(JOINED, {t: joined(t) for t in texs if joined(t) != t})
    # broken while its one line fits: the continuation still in what KaTeX typeset, or the rows set apart
    assert [f["tex"] for f in found if f["fits"] and (CONTINUATION.search(f["typeset"]) or f["lines"])] == []
    assert [f["tex"] for f in found if f["wide"]] == []


def first_step_whole(r: Reading) -> None:
    # prof-l 7: "δS = 0 / for every δq with δq(t₀) = δq(t₁) = / 0", the 0 alone on a line
    (found,) = r.page.evaluate(LINES, {"selector": "#step-1 .math-display"})
    lines = [line["bare"] for line in found["lines"]]
    assert found["broken"] and not found["wide"], found
    assert not any(line.startswith("0") or line.endswith("=") for line in lines), lines
    assert any(line.endswith("δq(t0)=δq(t1)=0") for line in lines), lines


# the scenes none of whose display formulas scrolls on a phone (prof-c S11: the simple pendulum's steps 14, 15, 28
# and the tabletop's 3, 16, 17 were cut at the right edge), but those that begin as named: the tabletop's velocity
# is one bracket, and the helix's two equations for its multipliers (a linear system in λ₁, λ₂) are not broken yet
NO_SIDEWAYS = {
    "simple-pendulum": (),
    "helix-bead": (r"\begin{aligned}\ddot{\mathcal{C}}_{1} &= 0",),
    "rail-two-body": (),
    "tabletop-spring": (r"\vec v = \left(",),
}


def no_sideways_formula(r: Reading) -> None:
    if r.scene_id not in NO_SIDEWAYS:
        return
    wide = [f["tex"] for f in r.measured["formulas"] if f["wide"]]
    assert [w for w in wide if not w.startswith(NO_SIDEWAYS[r.scene_id])] == [], wide


def modes_lines(r: Reading) -> None:
    # prof-h (issue 40): each matrix and each ω² on its own line, no "K =" left at a line's end, a value on the line
    # of its ≈ ("≈ 5.747 s⁻²"), what is wider than the screen inside a box that scrolls and says so
    if r.scene_id != "double-pendulum":
        return
    (modes,) = r.page.evaluate(LINES, {"step": "Normal modes about", "has": "omega_"})
    texts = [line["text"] for line in modes["lines"]]
    assert modes["broken"] and texts, modes
    # no line ends in a relation with what it relates on the next line (K =, ω₁² =)
    assert not any(t.endswith(("=", "≈")) for t in texts), texts
    # no line begins with a bare value: the frequencies' numbers follow their ≈ (a sum's next term, 4(m₁ + m₂)…
    # after a line ending in its +, may begin with its number)
    assert not any(t[:1].isdigit() and not texts[i - 1].endswith(("+", "−")) for i, t in enumerate(texts)), texts
    assert sum("≈" in t for t in texts) == 2, texts
    assert any(t.startswith(("M=", "ℳ=")) for t in texts) and any(t.startswith("K=") for t in texts), texts
    # issue 40: the long radicand is named on a line of its own (Δ = …), so that each ω² fits the phone: nothing
    # goes past the screen's edge and the box never scrolls sideways
    assert any(t.startswith("Δ=") for t in texts), texts
    assert not modes["wide"] and all(line["right"] <= modes["edge"] + 1 for line in modes["lines"]), modes


def rigid_pieces(r: Reading) -> None:
    # prof-q 5: on a phone the cylinder's r⃗_cm was clipped (now a column), its H's numerator was clipped (now
    # stacked, the term after the fraction kept), and "Time as an integral" left "=" alone on a line above the integral
    if r.scene_id not in ("rolling-cylinder-wedge", "massive-pulley"):
        return
    # the position vector's letter: R where the radius is r (notation.position)
    letter = "R" if r.scene_id == "rolling-cylinder-wedge" else "r"
    starts = [rf"\begin{{aligned}}\vec {letter}_{{\mathrm{{cm}}}}", r"H = \sum_k", r"\begin{aligned}t &= \int"]
    vector, hamiltonian, integral = (r.page.evaluate(LINES, {"start": [s]})[0] for s in starts)
    if r.scene_id == "rolling-cylinder-wedge":
        assert not vector["wide"] and not hamiltonian["wide"], (vector, hamiltonian)
    # the integral is broken after its first row; no line is a relation alone, nor ends with one (the integral's
    # "=" keeps its ∫; H's second "=" begins a line)
    assert len(integral["lines"]) >= 2, integral
    for display in (vector, hamiltonian, integral):
        texts = [line["text"] for line in display["lines"]]
        assert not any(t in ("=", "≈") or t.endswith("=") for t in texts), display


def accelerations_fit(r: Reading) -> None:
    # prof-n 10: on a phone θ̈₁ and θ̈₂, each one fraction wider than the screen, ran off its right edge behind a
    # sideways scroll; their numerators now go on over more lines.  A desktop keeps the engine's two lines.
    if r.scene_id != "double-pendulum":
        return
    found = r.page.evaluate(ACCELERATIONS)
    assert found["wide"] <= 1 and found["errors"] == 0 and found["fractions"] == 2, found
    if r.phone:
        assert all(n > 2 for n in found["rows"]), found
    else:
        assert found["rows"] == [2, 2], found


def fractions_apart(r: Reading) -> None:
    # prof-l 9: on a laptop θ̈₁'s denominator touched θ̈₂'s numerator.  The glyphs' own boxes (taller than their ink)
    # half a line apart: room between the rows, not fractions touching (1 px apart before; the page's 7 px between
    # the lines of a broken display)
    if r.scene_id != "double-pendulum":
        return
    found = r.page.evaluate(FRACTION_GAP)
    assert found["count"] == 2 and found["gap"] >= 8, found


CANVAS = "document.querySelector('[data-panel^=animation] canvas')"
DRAWN = f"JSON.parse({CANVAS}.dataset.drawn)"


def _frame(page, at: str) -> None:
    """The animation scrubbed to frame ``at`` (a JS expression of the scrubber ``s``), drawn."""
    page.evaluate(
        f"() => {{ const s = document.querySelector('input.scrub'); s.value = {at}; s.dispatchEvent(new Event('input')); }}"
    )
    page.wait_for_timeout(100)


def block_on_slope(r: Reading) -> None:
    # at the default start (X = 0: the foot of the ramp; D = 0: the top corner of the wedge); further down the
    # slope: tests/browser/test_pictures.py
    if r.scene_id not in ("incline-block", "movable-incline"):
        return
    canvas = r.page.locator("[data-panel^=animation] canvas")
    drawn, bodies = json.loads(canvas.get_attribute("data-drawn")), json.loads(canvas.get_attribute("data-bodies"))
    block = next(b for b in bodies if b["label"] == "block")
    (solid,) = drawn["solids"]
    # the sloping side: the two corners that are neither vertically nor horizontally aligned
    (ax, ay), (bx, by) = next((p, q) for p in solid for q in solid if abs(p[0] - q[0]) > 2 and abs(p[1] - q[1]) > 2)
    length = math.hypot(bx - ax, by - ay)
    floor = max(y for _, y in solid)
    for x, y in block["base"]:
        # each end of the block's base is on the slope (within rounding) and between its ends
        assert abs((x - ax) * (by - ay) - (y - ay) * (bx - ax)) / length <= 1.5, (x, y, solid)
        assert min(ax, bx) - 1.5 <= x <= max(ax, bx) + 1.5 and y <= floor + 1, (x, y, solid)
    # a rectangle, not a disc: the pixel just above the middle of its base, off the slope's normal, is the block's
    # colour (a disc of radius 10 px would not reach it)
    middle = [(a + b) / 2 for a, b in zip(*block["base"], strict=True)]
    colour = r.page.evaluate(
        """([x, y]) => { const c = document.querySelector('[data-panel^=animation] canvas'), k = c.width / c.clientWidth;
                        return Array.from(c.getContext('2d').getImageData(Math.round(x * k), Math.round(y * k), 1, 1).data); }""",
        [middle[0], middle[1] - 15],
    )
    assert colour[3] == 255 and colour[:3] != [255, 255, 255], colour
    if r.scene_id == "movable-incline":
        wedge = next(b for b in bodies if b["label"] == "wedge")
        assert min(p[0] for p in solid) < wedge["x"] < max(p[0] for p in solid)  # its label's body is inside it
        # prof-h 8: no label (drawn with a white halo) hides the slope, else at D = 0 the slope under the block's
        # far half vanished behind "block" and the block looked perched on the wedge's corner
        steps = math.ceil(length)
        for box in (lb["box"] for lb in json.loads(canvas.get_attribute("data-labels"))):
            hidden = [
                k for k in range(steps + 1)
                if box[0] <= ax + (bx - ax) * k / steps <= box[2] and box[1] <= ay + (by - ay) * k / steps <= box[3]
            ]  # fmt: skip
            assert not hidden, (box, (ax, ay), (bx, by))


def wheel_wrap(r: Reading) -> None:
    if r.scene_id != "pulley":
        return
    spec = r.page.evaluate("JSON.parse(document.getElementById('scene-data').textContent).mechanism")
    assert spec["wheels"][2]["wrap"] == "bottom", spec["wheels"]


def labels_off_the_ground(r: Reading) -> None:
    # prof-m 10: "left mass" sat on the floor's hatching; a label goes where it covers no ground, wall or wire
    if r.scene_id != "coupled-oscillators":
        return
    canvas = r.page.locator("[data-panel^=animation] canvas")
    for frame in ("0", "Math.floor(s.max / 3)", "s.max"):
        _frame(r.page, frame)
        drawn = r.page.evaluate(DRAWN)
        labels = json.loads(canvas.get_attribute("data-labels"))
        curves = {c["label"]: c["box"] for c in drawn["curves"]}
        assert set(curves) == {"floor", "left wall", "right wall"}, curves
        assert curves["floor"][3] - curves["floor"][1] >= 5  # the floor's line and the hatching below it
        assert {lb["label"] for lb in labels} == {"left mass", "right mass"}, labels
        for lb in labels:
            x0, y0, x1, y1 = lb["box"]
            for name, (a0, b0, a1, b1) in curves.items():
                assert x1 < a0 or x0 > a1 or y1 < b0 or y0 > b1, (frame, lb, name, (a0, b0, a1, b1))
    _frame(r.page, "0")


def band_under_ceiling(r: Reading) -> None:
    # prof-q 11: the band saying why the run ended lay over the ceiling's hatching; the bodies named as the
    # statement names them, m₁ and m₂
    if r.scene_id != "massive-pulley":
        return
    canvas = r.page.locator("[data-panel^=animation] canvas")
    assert {lb["label"] for lb in json.loads(canvas.get_attribute("data-labels"))} == {"mass m₁", "mass m₂"}
    _frame(r.page, "s.max")
    drawn = r.page.evaluate(DRAWN)
    assert drawn["event"] == "mass at the pulley", drawn["event"]
    (ceiling,) = [c["box"] for c in drawn["curves"] if c["label"] == "ceiling"]
    # the ceiling's line with its hatching above it starts below the band's bottom edge
    assert ceiling[1] > drawn["band"], (ceiling, drawn["band"])
    _frame(r.page, "0")


def no_code_speak(r: Reading) -> None:
    assert (found := code_speak(r.page)) == [], found[:5]


def no_noise_after_play(r: Reading) -> None:
    page = r.page
    page.evaluate("window.scrollTo(0, 0)")
    page.click("[data-panel^=animation] button[data-action=play]")
    page.wait_for_timeout(1500)
    unfold_panels(page)  # a phone folds the plots under the animation
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
    assert digits > 7 or digits == 0, digits
    lines = page.evaluate(
        """() => { const m = document.querySelector('#run-status .message');
                   return Math.round(m.getBoundingClientRect().height / parseFloat(getComputedStyle(m).lineHeight)); }"""
    )
    assert lines <= 2, lines


def no_console_error(r: Reading) -> None:
    assert r.errors == []


CHECKS = {
    "desktop": [
        loads,
        panels_drawn,
        phase_caption,
        action_panel,
        axe,
        formula_widths,
        joined_formulas,
        accelerations_fit,
        fractions_apart,
        block_on_slope,
        wheel_wrap,
        labels_off_the_ground,
        band_under_ceiling,
        no_code_speak,
        no_console_error,
    ],
    "phone": [
        loads,
        no_overflow,
        reads_in_order,
        labels_clear,
        axe,
        formula_widths,
        phone_formulas,
        first_step_whole,
        no_sideways_formula,
        modes_lines,
        rigid_pieces,
        accelerations_fit,
        block_on_slope,
        labels_off_the_ground,
        band_under_ceiling,
        no_code_speak,
        no_noise_after_play,
        no_console_error,
    ],
}


@pytest.mark.parametrize("size", list(SIZES))
@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_a_scene_page_read_once(browser, live_server, artifacts, scene_id, size):
    width, height, phone = SIZES[size]
    context = browser.new_context(
        base_url=live_server, viewport={"width": width, "height": height}, has_touch=phone, is_mobile=phone
    )
    page = context.new_page()
    page.set_default_timeout(120_000)
    errors: list[str] = []
    page.on("console", lambda msg: errors.append(msg.text) if msg.type == "error" else None)
    page.on("pageerror", lambda exc: errors.append(f"uncaught: {exc}"))
    failed: dict[str, str] = {}
    try:
        with page.expect_response(lambda a: a.url.endswith(f"/api/scenes/{scene_id}/simulate")) as answer:
            page.goto(f"/scenes/{scene_id}")
        page.wait_for_selector(f'{DONE}, #run-status[data-state="error"]', state="attached")
        page.wait_for_selector(TYPESET, state="attached")
        reading = Reading(page, live_server, scene_id, size, json.loads(answer.value.body()), errors)
        for check in CHECKS[size]:
            try:
                check(reading)
            except (AssertionError, PlaywrightError) as exc:
                failed[check.__name__] = f"{type(exc).__name__}: {exc}"[:1500]
        if failed:
            page.screenshot(path=artifacts / f"read-{scene_id}-{size}.png")
    finally:
        context.close()
    assert not failed, "\n".join(f"{name}: {why}" for name, why in failed.items())


def test_every_check_the_module_describes_runs():
    # a check written but left out of CHECKS would pass without running: the docstring's list is the module's
    described = set(re.findall(r"^- ``(\w+)``", __doc__, re.MULTILINE))
    assert described == {check.__name__ for checks in CHECKS.values() for check in checks}
