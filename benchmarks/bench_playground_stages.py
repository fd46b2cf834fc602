"""The playground in two stages, in Debian's headless Chromium at 1366×768: a typed triple pendulum.

From the click on Derive (the input) to
- the first equations painted: the equations of motion on screen in the first stage's results box, as the
  server's MathML (Chromium paints it as the page arrives), and typeset by KaTeX over it (which waits for the
  page's load event, that is for Plotly's script too);
- the whole document: the step-by-step derivation in place (the page fetched ``stage=whole`` and swapped it in);
and, as the baseline in the same run, the page as it was before the stages: the same kind of system (another
names for its parameters, so no cache holds it) opened at ``stage=whole``, from navigation to its steps
painted.  Each figure is the median of REPEATS systems no cache holds; the ratio first/baseline is the headline.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_playground_stages
"""

from __future__ import annotations

import json
import statistics
import time
import urllib.request
from concurrent.futures import ThreadPoolExecutor
from urllib.parse import urlencode

from benchmarks.bench_browser import ARGS, CHROMIUM, serve

REPEATS = 3
# the server sends each formula as MathML, which Chromium paints at once; KaTeX typesets over it once loaded
SHOWN = '#derived[data-stage="equations"] #results .math math'
FIRST = '#derived[data-stage="equations"] #results .math .katex'
WHOLE = '#derived[data-stage="whole"] #derivation .step .katex'


def triple(n: int) -> dict[str, list[str] | str]:
    """The triple pendulum as the form sends it (particles and U), its parameters named m{n}, l{n} and g{n}: each
    n is a system no cache holds, not even SymPy's own (a new value of g alone would find its expressions cached
    in a worker that derived the same system before)."""
    links = "abc"
    m, length, g = f"m{n}", f"l{n}", f"g{n}"
    return {
        "q": "a, b, c", "form": "particles", "pn": [m, length, g], "pv": ["1", "1", "9.81"],
        "m": [m] * 3,
        "x": [" + ".join(f"{length}*sin({c})" for c in links[: i + 1]) for i in range(3)],
        "y": ["0"] * 3,
        "z": [" ".join(f"- {length}*cos({c})" for c in links[: i + 1]) for i in range(3)],
        "U": f"-{m}*{g}*{length}*(3*cos(a) + 2*cos(b) + cos(c))",
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


def staged(browser, base: str, n: int) -> tuple[float, float, float]:
    """Seconds from the Derive click to the first equations painted (MathML), typeset (KaTeX), and to the whole
    document."""
    context = browser.new_context(base_url=base, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    page.set_default_timeout(120_000)
    page.goto("/playground?new")
    fill(page, triple(n))
    started = time.perf_counter()
    page.click('#system-form button[type="submit"]')
    page.wait_for_selector(SHOWN)
    shown = time.perf_counter() - started
    page.wait_for_selector(FIRST)
    first = time.perf_counter() - started
    page.wait_for_selector(WHOLE)
    whole = time.perf_counter() - started
    context.close()
    return shown, first, whole


def baseline(browser, base: str, n: int) -> float:
    """Seconds from navigation to the steps painted, when the page waits for the whole document (stage=whole)."""
    context = browser.new_context(base_url=base, viewport={"width": 1366, "height": 768})
    page = context.new_page()
    page.set_default_timeout(120_000)
    started = time.perf_counter()
    page.goto("/playground?" + urlencode({**triple(n), "stage": "whole"}, doseq=True), wait_until="commit")
    page.wait_for_selector(WHOLE)
    seconds = time.perf_counter() - started
    context.close()
    return seconds


def warm_workers(base: str) -> None:
    """Both pool workers' first jobs (a fresh worker's first derivation pays about a second of SymPy's first
    calls): two triple pendulums of other names derived at once through the API, so each worker takes one."""
    from starlette.datastructures import QueryParams

    from app.web.pages.playground_form import read_form, spec_of

    def derive(n: int) -> None:
        spec = spec_of(read_form(QueryParams(urlencode(triple(n), doseq=True))))
        request = urllib.request.Request(base + "/api/derive", json.dumps(spec).encode(),
                                         {"Content-Type": "application/json"})  # fmt: skip
        with urllib.request.urlopen(request, timeout=120) as answer:
            answer.read()

    with ThreadPoolExecutor(2) as both:
        list(both.map(derive, (91, 92)))


def main() -> None:
    from playwright.sync_api import sync_playwright

    server, base = serve()
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=CHROMIUM, args=ARGS)
            warm_workers(base)  # not counted: the figures are a running server's, as students meet it
            shows, firsts, wholes, olds = [], [], [], []
            for i in range(REPEATS):
                shown, first, whole = staged(browser, base, 2 * i + 1)
                shows.append(shown)
                firsts.append(first)
                wholes.append(whole)
                olds.append(baseline(browser, base, 2 * i + 2))
            browser.close()
    finally:
        server.should_exit = True
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    shown, first, whole, old = (statistics.median(v) for v in (shows, firsts, wholes, olds))
    print(f"triple pendulum, 1366x768, median of {REPEATS} (load average {load}):")
    print(f"  input -> first equations painted  {shown:6.2f} s   {[round(x, 2) for x in shows]} (MathML)")
    print(f"  input -> first equations typeset  {first:6.2f} s   {[round(x, 2) for x in firsts]} (KaTeX)")
    print(f"  input -> whole document painted   {whole:6.2f} s   {[round(x, 2) for x in wholes]}")
    print(f"  baseline: whole page at once      {old:6.2f} s   {[round(x, 2) for x in olds]}")
    print(
        f"  painted / baseline = {shown / old:.2f}; typeset / baseline = {first / old:.2f}; "
        f"whole / baseline = {whole / old:.2f}"
    )


if __name__ == "__main__":
    main()
