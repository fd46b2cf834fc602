"""The scene page in Debian's headless Chromium: input→paint latency, playback, scrubbing, bytes sent.

The app runs in a thread (uvicorn on a free loopback port); Playwright drives
/usr/bin/chromium (never a downloaded browser).  Measured, per page:

- input → paint: an arrow key on the initial-angle slider, every 60 ms (a slider being dragged),
  from the key's ``input`` event to the first animation frame after the page's
  ``lagrange:painted`` event (the browser's preview); p50 and p95.  Once at 1366×768 (the first
  screen: the animation, its energy bars) and once at 1366×2400 (every plot in view too).
- settle → server: from the last input to ``lagrange:painted`` with source 'server'.
- playback: distinct animation frames shown per second over 3 s of play, and the display's
  requestAnimationFrame rate in the same interval (the ceiling).
- scrub: the cost of one time-slider step (its ``input`` handler: canvas, bars, cursor overlays).
- bytes: everything transferred to load the page and its first run (Chromium's encoded sizes,
  no cache), against the 700 kB target for a 2-D page.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_browser [scene ...]
"""

from __future__ import annotations

import socket
import statistics
import sys
import threading
import time

import uvicorn

from app.main import app
from app.scenes import SCENES

CHROMIUM = "/usr/bin/chromium"
ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update"]
READY = '#run-status[data-state="ready"]'
INPUTS = 40

LATENCY_JS = """async ([count, gap]) => {
  const slider = document.querySelector('#controls .controls-initial input[type=range]');
  const out = [];
  let started = 0;
  const frame = () => new Promise((r) => requestAnimationFrame(() => r(performance.now())));
  for (let i = 0; i < count; i++) {
    // a preview that never paints counts as 5 s (and the run goes on)
    const painted = Promise.race([new Promise((resolve) => {
      const seen = (e) => { if (e.detail.source === 'preview') { document.removeEventListener('lagrange:painted', seen); resolve(); } };
      document.addEventListener('lagrange:painted', seen);
    }), new Promise((resolve) => setTimeout(resolve, 5000))]);
    const step = i % 20 < 10 ? 1 : -1;
    slider.value = String(Number(slider.value) + 8 * step);
    started = performance.now();
    slider.dispatchEvent(new Event('input', { bubbles: true }));
    await painted;
    out.push((await frame()) - started);
    await new Promise((r) => setTimeout(r, gap));
  }
  const last = performance.now();
  await Promise.race([new Promise((resolve) => document.addEventListener('lagrange:painted',
    (e) => { if (e.detail.source === 'server') resolve(); })), new Promise((resolve) => setTimeout(resolve, 30000))]);
  return { latency: out, settle: performance.now() - last };
}"""

PLAYBACK_JS = """async (seconds) => {
  const section = document.querySelector('[data-panel^=animation]');
  section.querySelector('[data-action=play]').click();
  let frames = 0, shown = 0, last = section.dataset.frame;
  const start = performance.now();
  await new Promise((resolve) => {
    const tick = () => {
      frames++;
      if (section.dataset.frame !== last) { shown++; last = section.dataset.frame; }
      if (performance.now() - start < seconds * 1000) requestAnimationFrame(tick); else resolve();
    };
    requestAnimationFrame(tick);
  });
  const elapsed = (performance.now() - start) / 1000;
  section.querySelector('[data-action=play]').click();
  return { fps: shown / elapsed, raf: frames / elapsed };
}"""

SCRUB_JS = """(count) => {
  const scrub = document.querySelector('[data-panel^=animation] input.scrub');
  const n = Number(scrub.max) + 1, out = [];
  for (let i = 0; i < count; i++) {
    scrub.value = String(Math.floor((i * 7919) % n));
    const t0 = performance.now();
    scrub.dispatchEvent(new Event('input', { bubbles: true }));
    out.push(performance.now() - t0);
  }
  return out;
}"""


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def serve() -> tuple[uvicorn.Server, str]:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning", ws="none"))
    threading.Thread(target=server.run, daemon=True).start()
    while not server.started:
        time.sleep(0.05)
    # the server's start-up work (its warm-up threads, the scenes' worker process loading the chapter)
    # ends before the measuring starts: the figures are a running server's, as students meet it
    started = time.perf_counter()
    while any(t.name.startswith(("warm-", "freeze-")) for t in threading.enumerate()):
        time.sleep(0.1)
    print(f"the server's warm-up ended {time.perf_counter() - started:.1f} s after it started answering")
    return server, f"http://127.0.0.1:{port}"


def transferred(browser, base: str, path: str) -> int:
    context = browser.new_context(base_url=base, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    cdp = context.new_cdp_session(page)
    cdp.send("Network.enable")
    cdp.send("Network.setCacheDisabled", {"cacheDisabled": True})
    sizes: dict[str, float] = {}
    cdp.on("Network.loadingFinished", lambda e: sizes.__setitem__(e["requestId"], e["encodedDataLength"]))
    page.goto(path)
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    page.wait_for_timeout(1500)  # fonts, and panels drawn while the browser is idle
    context.close()
    return int(sum(sizes.values()))


def interactive(browser, base: str, path: str, height: int) -> dict[str, float]:
    context = browser.new_context(base_url=base, viewport={"width": 1366, "height": height})
    page = context.new_page()
    page.goto(path)
    page.wait_for_selector(READY, state="attached", timeout=120_000)
    # every plot drawn (those out of view are drawn while the browser is idle; the error report, the
    # Poincaré section and the action only when scrolled into view), then a quiet second
    page.wait_for_function(
        """[...document.querySelectorAll('[data-panel] .plot')]
             .every((p) => p.closest('[data-panel=work-precision], [data-panel=poincare], [data-panel=action]')
                           || (p.data && p.data.length))""",
        timeout=120_000,
    )
    page.wait_for_timeout(1000)
    result = page.evaluate(LATENCY_JS, [INPUTS, 60])
    page.wait_for_selector(READY, state="attached")
    scrub = page.evaluate(SCRUB_JS, 200)
    play = page.evaluate(PLAYBACK_JS, 3)
    context.close()
    lat = result["latency"]
    return {
        "p50": statistics.median(lat), "p95": percentile(lat, 0.95), "settle": result["settle"],
        "scrub_p50": statistics.median(scrub), "scrub_p95": percentile(scrub, 0.95),
        "fps": play["fps"], "raf": play["raf"],
    }  # fmt: skip


def main(argv: list[str]) -> None:
    from playwright.sync_api import sync_playwright

    scenes = argv or sorted(SCENES)
    server, base = serve()
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
            print(flush=True)
            print("page                          kB sent   input→paint p50/p95 (768 | all plots)   settle→server  scrub p50/p95  fps (rAF)")
            for path in [*(f"/scenes/{s}" for s in scenes), "/playground"]:
                kb = transferred(browser, base, path) / 1000
                first = interactive(browser, base, path, 768)
                tall = interactive(browser, base, path, 2400)
                print(
                    f"{path:28s} {kb:7.0f}   {first['p50']:5.1f}/{first['p95']:5.1f} ms | {tall['p50']:5.1f}/{tall['p95']:5.1f} ms"
                    f"   {first['settle']:7.0f} ms   {first['scrub_p50']:4.1f}/{first['scrub_p95']:4.1f} ms"
                    f"   {first['fps']:4.0f} ({first['raf']:.0f})",
                    flush=True,
                )
            browser.close()
    finally:
        server.should_exit = True
    print("targets: input→paint p95 < 100 ms, playback ≥ 50 fps, scrub within one frame (16.7 ms), a 2-D page ≤ 700 kB")


if __name__ == "__main__":
    main(sys.argv[1:])
