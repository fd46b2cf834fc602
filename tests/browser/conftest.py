"""Fixtures for real-browser tests: the app served by uvicorn in a thread, and Debian's headless Chromium.

``live_server`` (session) yields the base URL of the app on a free loopback
port.  ``page`` is a new Playwright page (``page.console_errors`` collects
console errors and uncaught exceptions) of one browser shared by the package's
tests (``/usr/bin/chromium`` through ``executable_path``; never ``playwright
install``).  Its context is shared too, so the second page on a worker finds
KaTeX and plotly.js in the HTTP cache and compiled in V8's code cache; what a
test could leave for the next (cookies, local storage) is cleared after each
test.  ``fresh_page`` has a context of its own, for tests that watch every
request a first visit makes.  Screenshots go to ``test-artifacts/``.
"""

from __future__ import annotations

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


class SharedContext:
    """One browser context reused by consecutive tests, given back to the next test as if new.

    After a test its cookies (the server's client identity) are cleared; if the test left anything in an
    origin's storage (practice answers in localStorage), the context is closed and the next test gets a new one.
    """

    def __init__(self, browser, **options):
        self.browser, self.options, self.context = browser, options, None

    def new_page(self):
        if self.context is None:
            self.context = self.browser.new_context(**self.options)
        page = self.context.new_page()
        page.set_default_timeout(60_000)
        return page

    def release(self, page) -> None:
        page.close()
        if any(origin.get("localStorage") for origin in self.context.storage_state()["origins"]):
            self.close()
        else:
            self.context.clear_cookies()

    def close(self) -> None:
        if self.context is not None:
            self.context.close()
            self.context = None


def watch_errors(page):
    page.console_errors = []
    page.on("console", lambda msg: page.console_errors.append(msg.text) if msg.type == "error" else None)
    page.on("pageerror", lambda exc: page.console_errors.append(f"uncaught: {exc}"))
    return page


@pytest.fixture(scope="package")
def desktop(browser, live_server) -> Iterator[SharedContext]:
    shared = SharedContext(browser, base_url=live_server, viewport={"width": 1280, "height": 900})
    yield shared
    shared.close()


@pytest.fixture(scope="package")
def handheld(browser, live_server) -> Iterator[SharedContext]:
    shared = SharedContext(
        browser, base_url=live_server, viewport={"width": 390, "height": 844}, has_touch=True, is_mobile=True
    )
    yield shared
    shared.close()


@pytest.fixture
def page(desktop):
    page = watch_errors(desktop.new_page())
    yield page
    desktop.release(page)


@pytest.fixture
def phone(handheld):
    page = handheld.new_page()
    yield page
    handheld.release(page)


@pytest.fixture
def fresh_page(browser, live_server):
    context = browser.new_context(base_url=live_server, viewport={"width": 1280, "height": 900})
    page = watch_errors(context.new_page())
    page.set_default_timeout(60_000)
    yield page
    context.close()


@pytest.fixture(scope="session")
def artifacts() -> Path:
    ARTIFACTS.mkdir(exist_ok=True)
    return ARTIFACTS
