"""An embed page inside an iframe on a page of another origin: allowed by the ``embed_ancestors`` setting it
plays and answers its slider; by default Chromium refuses to show it in the frame."""

from __future__ import annotations

import threading
from collections.abc import Iterator
from contextlib import contextmanager
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest

from tests.web.api.test_classes_processes import _free_port, server

pytestmark = [pytest.mark.browser, pytest.mark.slow]

READY = '#run-status[data-state="ready"], #run-status[data-state="untrusted"], #run-status[data-state="warning"]'


@contextmanager
def course_page(embed_url: str) -> Iterator[str]:
    """A course site on its own origin (another port of 127.0.0.1) whose page frames ``embed_url``."""
    html = (
        "<!doctype html><html lang=en><title>Week 3</title><h1>Week 3: the pendulum</h1>"
        f'<iframe id="book" src="{embed_url}" width="900" height="640" title="Pendulum"></iframe>'
    ).encode()

    class Page(BaseHTTPRequestHandler):
        def do_GET(self) -> None:  # noqa: N802 - the standard library's name
            self.send_response(200)
            self.send_header("content-type", "text/html; charset=utf-8")
            self.end_headers()
            self.wfile.write(html)

        def log_message(self, *args) -> None:
            pass

    site = ThreadingHTTPServer(("127.0.0.1", _free_port()), Page)
    thread = threading.Thread(target=site.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{site.server_port}/"
    finally:
        site.shutdown()
        site.server_close()


def _book_frame(page):
    page.wait_for_selector("#book")
    return page.frame_locator("#book")


def test_a_listed_site_frames_the_embed_page_and_it_plays(browser, artifacts):
    port = _free_port()
    with course_page(f"http://127.0.0.1:{port}/embed/scenes/simple-pendulum?panel=energy") as site:
        origin = site.rstrip("/")
        with server({"LAGRANGE_EMBED_ANCESTORS": origin}, port=port):
            context = browser.new_context(viewport={"width": 1000, "height": 800})
            page = context.new_page()
            page.set_default_timeout(60_000)
            errors: list[str] = []
            page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
            page.goto(site)
            frame = _book_frame(page)
            frame.locator(READY).wait_for(state="attached")
            play = frame.locator("[data-panel=animation-2d] [data-action=play]")
            time_shown = frame.locator("[data-panel=animation-2d] output.time")
            before = time_shown.inner_text()
            play.click()
            page.wait_for_timeout(900)
            play.click()
            assert time_shown.inner_text() != before  # it played
            # a slider answers: a new run with the new g
            runs = frame.locator("#simulation").get_attribute("data-runs")
            frame.locator("#ctl-g-range").focus()
            for _ in range(20):
                page.keyboard.press("ArrowRight")
            frame.locator(f'#simulation:not([data-runs="{runs}"])').wait_for(state="attached")
            assert float(frame.locator("#ctl-g").input_value()) > 9.81
            assert frame.locator("[data-panel=energy] .plot").count() == 1
            assert frame.locator("#derivation").count() == 0
            frame.locator("h1").scroll_into_view_if_needed()
            page.screenshot(path=artifacts / "embed-framed.png")
            assert errors == []
            context.close()


def test_by_default_the_frame_is_refused(browser, live_server):
    with course_page(f"{live_server}/embed/scenes/simple-pendulum") as site:
        context = browser.new_context()
        page = context.new_page()
        page.set_default_timeout(60_000)
        page.goto(site)
        page.wait_for_selector("#book")
        page.wait_for_timeout(1500)
        frame = next(f for f in page.frames if f is not page.main_frame)
        # Chromium shows its own error page in place of a document whose policy forbids this ancestor
        assert frame.url.startswith("chrome-error://")
        context.close()
