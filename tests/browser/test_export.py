"""The download buttons in headless Chromium: a scene page's links and the playground's POST."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytestmark = pytest.mark.browser

READY = '#run-status[data-state="ready"]'


def test_a_scene_page_downloads_its_script(page):
    page.goto("/scenes/simple-pendulum")
    with page.expect_download() as info:
        page.click("#export a[href$='format=py']")
    download = info.value
    assert download.suggested_filename == "simple-pendulum.py"
    assert Path(download.path()).read_text().startswith("#!/usr/bin/env python3")
    assert page.console_errors == []


def test_the_playground_exports_the_system_with_the_values_the_controls_hold(page):
    page.goto("/playground")
    page.wait_for_selector(READY, state="attached")
    name = page.get_attribute("#controls .control[data-group=initial]", "data-name")
    page.fill(f"#ctl-{name}", "0.625")
    page.dispatch_event(f"#ctl-{name}", "change")  # re-simulates: the export waits its turn (429, retried)
    with page.expect_download() as info:
        page.click('button[data-export-format="py"]')
    download = info.value
    assert download.suggested_filename == "system.py"
    script = Path(download.path()).read_text()
    assert "y0 = [0.625" in script or f"y0 = [{json.dumps(0.625)}" in script
    assert "Saved system.py" in page.inner_text("#export-status")
    with page.expect_download() as info:
        page.click('button[data-export-format="ipynb"]')
    assert json.loads(Path(info.value.path()).read_text())["nbformat"] == 4
    # the browser logs the 429 the export waited out while the simulation ran; nothing else
    assert [e for e in page.console_errors if "status of 429" not in e] == []
