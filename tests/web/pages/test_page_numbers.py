"""Numbers the page needs come from the server, not from copies in the JavaScript."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from app.viz.page_model import SLIDER_STEPS

JS = Path(__file__).resolve().parents[3] / "static" / "js"


@pytest.mark.slow
def test_every_slider_has_the_servers_resolution(client):
    html = client.get("/scenes/double-pendulum").text
    maxima = set(re.findall(r'<input type="range" id="ctl-[^"]+-range" min="0" max="(\d+)"', html))
    assert maxima == {str(SLIDER_STEPS)}


def test_the_scripts_copy_neither_the_slider_resolution_nor_the_collapsed_step_length():
    for path in JS.glob("*.js"):
        text = path.read_text()
        assert not re.search(r"\bSTEPS\s*=\s*1000\b|\bLONG_STEP\b|max=\"1000\"", text), path.name
