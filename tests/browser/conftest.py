"""Fixtures for real-browser tests: the app served by uvicorn in a thread, and Debian's headless Chromium.

``live_server`` (session) yields the base URL of the app on a free loopback
port.  ``page`` is a Playwright page in a fresh context of one browser shared
by the package's tests (``/usr/bin/chromium`` through ``executable_path``;
never ``playwright install``); ``page.console_errors`` collects console errors
and uncaught exceptions.  Screenshots go to ``test-artifacts/``.
"""

from __future__ import annotations

import json
import socket
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
import uvicorn

from app.main import app

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update"]
ARTIFACTS = Path(__file__).resolve().parents[2] / "test-artifacts"


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="session")
def live_server() -> Iterator[str]:
    config = uvicorn.Config(app, host="127.0.0.1", port=_free_port(), log_level="warning", ws="none", lifespan="on")
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, name="live-server", daemon=True)
    thread.start()
    deadline = time.monotonic() + 30
    while not server.started:
        if time.monotonic() > deadline or not thread.is_alive():
            raise RuntimeError("the app did not start")
        time.sleep(0.05)
    yield f"http://127.0.0.1:{config.port}"
    server.should_exit = True
    thread.join(timeout=10)


@pytest.fixture(scope="package")
def browser():
    # Package scope: Playwright's sync API keeps an event loop running in this thread while it is
    # open, so it must close when the browser tests are done (later tests may call asyncio.run).
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield chromium
        chromium.close()


@pytest.fixture
def page(browser, live_server):
    context = browser.new_context(base_url=live_server, viewport={"width": 1280, "height": 900})
    page = context.new_page()
    page.set_default_timeout(60_000)
    page.console_errors = []
    page.on("console", lambda msg: page.console_errors.append(msg.text) if msg.type == "error" else None)
    page.on("pageerror", lambda exc: page.console_errors.append(f"uncaught: {exc}"))
    yield page
    context.close()


def unfold_panels(page, selector: str = ".panels > section.panel") -> None:
    """Open the plot panels a phone shows folded under the animation (static/js/fold.js); nothing on a wide page."""
    page.evaluate(
        "(sel) => { for (const b of document.querySelectorAll(sel + ' > h3 > button.fold[aria-expanded=false]')) b.click(); }",
        selector,
    )


def busy_once(page, pattern: str, retry_after: int, detail: str) -> list[str]:
    """The first request to ``pattern`` is answered 429 with ``Retry-After`` and ``detail`` (as a busy server
    answers); the later ones go through.  Returns the refused requests' addresses (one, once it happened)."""
    refused: list[str] = []

    def answer(route) -> None:
        if refused:
            route.continue_()
            return
        refused.append(route.request.url)
        route.fulfill(status=429, headers={"Retry-After": str(retry_after), "Content-Type": "application/json"},
                      body=json.dumps({"detail": detail}))  # fmt: skip

    page.route(pattern, answer)
    return refused


@pytest.fixture(scope="session")
def artifacts() -> Path:
    ARTIFACTS.mkdir(exist_ok=True)
    return ARTIFACTS
