"""The action panel in Debian's headless Chromium: input → paint after a drag of the varied path, and after a move
of the T slider, against the live page's 100 ms budget; beside it, in the same run, the page's own preview
(an initial-angle slider step, as benchmarks/bench_browser.py measures it) as the peer.

- drag: a pointer pressed on the true path and moved in steps (pointermove every 60 ms), each from the event to
  the first animation frame after the panel's synchronous recomputation (S(ε) of the varied path, its L(t), the
  S(ε) mark) and its Plotly redraw; p50 and p95.
- T: a step of the T slider: a new true path in the browser (RK4), L along it, the S(ε) curve (41 ε), the
  second variation on 8 shapes, and the redraw; p50 and p95.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_action_browser [scene ...]
"""

from __future__ import annotations

import statistics
import sys

from benchmarks.bench_browser import ARGS, CHROMIUM, LATENCY_JS, READY, percentile, serve

INPUTS = 40
BUDGET_MS = 100.0

DRAG_JS = """async ([count, gap]) => {
  const section = document.querySelector('#panel-action'), plot = section.querySelector('.plot');
  const f = plot._fullLayout, d = plot.data[0], i = Math.floor(d.x.length / 2), box = plot.getBoundingClientRect();
  const x = box.left + f.xaxis.d2p(d.x[i]) + f.xaxis._offset, y0 = box.top + f.yaxis.d2p(d.y[i]) + f.yaxis._offset;
  const frame = () => new Promise((r) => requestAnimationFrame(() => r(performance.now())));
  const event = (type, y) => new PointerEvent(type, { clientX: x, clientY: y, bubbles: true, pointerId: 1, pointerType: 'mouse' });
  plot.dispatchEvent(event('pointerdown', y0));
  await frame();
  const out = [], work = [];
  for (let k = 0; k < count; k++) {
    const y = y0 + f.yaxis._length * 0.25 * Math.sin((2 * Math.PI * k) / 20);
    const started = performance.now();
    plot.dispatchEvent(event('pointermove', y));
    work.push(Number(section.dataset.recompute));
    out.push((await frame()) - started);
    await new Promise((r) => setTimeout(r, gap));
  }
  plot.dispatchEvent(event('pointerup', y0));
  return { latency: out, work };
}"""

T_JS = """async ([count, gap]) => {
  const slider = document.querySelector('#action-T'), section = document.querySelector('#panel-action');
  const frame = () => new Promise((r) => requestAnimationFrame(() => r(performance.now())));
  const out = [], work = [];
  const start = Number(slider.value), step = Number(slider.step);
  for (let k = 0; k < count; k++) {
    slider.value = String(start + step * (k % 10));
    const started = performance.now();
    slider.dispatchEvent(new Event('input', { bubbles: true }));
    work.push(Number(section.dataset.recompute));
    out.push((await frame()) - started);
    await new Promise((r) => setTimeout(r, gap));
  }
  return { latency: out, work };
}"""


def measure(browser, base: str, scene: str) -> dict[str, float]:
    context = browser.new_context(base_url=base, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    page.goto(f"/scenes/{scene}")
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    page.locator("#panel-action").scroll_into_view_if_needed()
    page.wait_for_function("document.querySelector('#panel-action').dataset.source === 'server'", timeout=120_000)
    page.wait_for_timeout(1000)
    drag = page.evaluate(DRAG_JS, [INPUTS, 60])
    t_moves = page.evaluate(T_JS, [20, 120])
    page.wait_for_timeout(1000)
    peer = page.evaluate(LATENCY_JS, [20, 60])["latency"]
    context.close()
    return {
        "drag_p50": statistics.median(drag["latency"]), "drag_p95": percentile(drag["latency"], 0.95),
        "drag_work": statistics.median(drag["work"]),
        "T_p50": statistics.median(t_moves["latency"]), "T_p95": percentile(t_moves["latency"], 0.95),
        "T_work": statistics.median(t_moves["work"]),
        "peer_p50": statistics.median(peer), "peer_p95": percentile(peer, 0.95),
    }  # fmt: skip


def main(argv: list[str]) -> None:
    from playwright.sync_api import sync_playwright

    scenes = argv or ["simple-pendulum", "tabletop-spring", "double-pendulum"]
    server, base = serve()
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
            print(
                "scene                 drag p50/p95 (JS)          T step p50/p95 (JS)        page preview p50/p95   drag p95 / peer p95"
            )
            for scene in scenes:
                r = measure(browser, base, scene)
                print(
                    f"{scene:20s}  {r['drag_p50']:5.1f}/{r['drag_p95']:5.1f} ms ({r['drag_work']:4.1f})   "
                    f"{r['T_p50']:5.1f}/{r['T_p95']:5.1f} ms ({r['T_work']:5.1f})   "
                    f"{r['peer_p50']:5.1f}/{r['peer_p95']:5.1f} ms        {r['drag_p95'] / r['peer_p95']:.2f}",
                    flush=True,
                )
            browser.close()
    finally:
        server.should_exit = True
    print(f"target: input → paint p95 < {BUDGET_MS:g} ms after a drag (the live page's budget)")


if __name__ == "__main__":
    main(sys.argv[1:])
