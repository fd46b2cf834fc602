"""The playground in two stages (issue 35), in Debian's headless Chromium at 1366×768: a typed triple pendulum.

From the click on Derive (the input) to
- the first equations painted: the equations of motion typeset by KaTeX in the first stage's results box;
- the whole document: the step-by-step derivation in place (the page fetched ``stage=whole`` and swapped it in);
and, as the baseline in the same run, the page as it was before the stages: the same kind of system (another
value of g, so no cache holds it) opened at ``stage=whole``, from navigation to its steps painted.  Each figure
is the median of REPEATS systems no cache holds (g differs in its last digit); the ratio first/baseline is the
headline.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_playground_stages
"""

from __future__ import annotations

import statistics
import time
from urllib.parse import urlencode

from benchmarks.bench_browser import ARGS, CHROMIUM, serve

REPEATS = 3
FIRST = '#derived[data-stage="equations"] #results .math .katex'
WHOLE = '#derived[data-stage="whole"] #derivation .step .katex'


def triple(g: str) -> dict[str, list[str] | str]:
    """The triple pendulum as the form sends it (particles and U)."""
    links = "abc"
    return {
        "q": "a, b, c", "form": "particles", "pn": ["m", "l", "g"], "pv": ["1", "1", g],
        "m": ["m"] * 3,
        "x": [" + ".join(f"l*sin({c})" for c in links[: i + 1]) for i in range(3)],
        "y": ["0"] * 3,
        "z": [" ".join(f"- l*cos({c})" for c in links[: i + 1]) for i in range(3)],
        "U": "-m*g*l*(3*cos(a) + 2*cos(b) + cos(c))",
    }  # fmt: skip


def fill(page, query: dict[str, list[str] | str]) -> None:
    """Type the system into the empty form, field by field, as a reader does."""
    page.check('input[name="form"][value="particles"]')
    page.fill("#f-coordinates", str(query["q"]))
    for i, (name, value) in enumerate(zip(query["pn"], query["pv"], strict=True)):
        if i >= page.locator("#parameter-rows tbody tr").count():
            page.click('[data-target="parameter-rows"]')
        page.fill(f"#f-param-{i}-name", name)
        page.fill(f"#f-param-{i}-value", value)
    for i in range(3):
        if i >= page.locator("#particle-rows tbody tr").count():
            page.click('[data-target="particle-rows"]')
        for key in ("m", "x", "z"):
            page.fill(f"#f-particle-{i}-{'mass' if key == 'm' else key}", query[key][i])
    page.fill("#f-U", str(query["U"]))


def staged(browser, base: str, g: str) -> tuple[float, float]:
    """Seconds from the Derive click to the first equations painted, and to the whole document."""
    context = browser.new_context(base_url=base, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    page.set_default_timeout(120_000)
    page.goto("/playground?new")
    fill(page, triple(g))
    started = time.perf_counter()
    page.click('#system-form button[type="submit"]')
    page.wait_for_selector(FIRST)
    first = time.perf_counter() - started
    page.wait_for_selector(WHOLE)
    whole = time.perf_counter() - started
    context.close()
    return first, whole


def baseline(browser, base: str, g: str) -> float:
    """Seconds from navigation to the steps painted, when the page waits for the whole document (stage=whole)."""
    context = browser.new_context(base_url=base, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    page.set_default_timeout(120_000)
    started = time.perf_counter()
    page.goto("/playground?" + urlencode({**triple(g), "stage": "whole"}, doseq=True), wait_until="commit")
    page.wait_for_selector(WHOLE)
    seconds = time.perf_counter() - started
    context.close()
    return seconds


def main() -> None:
    from playwright.sync_api import sync_playwright

    server, base = serve()
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=CHROMIUM, args=ARGS)
            baseline(browser, base, "9.59")  # not counted: the pool's first job starts its workers
            firsts, wholes, olds = [], [], []
            for i in range(REPEATS):
                first, whole = staged(browser, base, f"9.7{i}")
                firsts.append(first)
                wholes.append(whole)
                olds.append(baseline(browser, base, f"9.6{i}"))
            browser.close()
    finally:
        server.should_exit = True
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    first, whole, old = (statistics.median(v) for v in (firsts, wholes, olds))
    print(f"triple pendulum, 1366x768, median of {REPEATS} (load average {load}):")
    print(f"  input -> first equations painted  {first:6.2f} s   {[round(x, 2) for x in firsts]}")
    print(f"  input -> whole document painted   {whole:6.2f} s   {[round(x, 2) for x in wholes]}")
    print(f"  baseline: whole page at once      {old:6.2f} s   {[round(x, 2) for x in olds]}")
    print(f"  first / baseline = {first / old:.2f}; whole / baseline = {whole / old:.2f}")


if __name__ == "__main__":
    main()
