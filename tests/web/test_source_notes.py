"""A course taught from another book hides the source notes (issue 40, prof-n 8 and 11): settings' source_notes."""

from __future__ import annotations

import html
import re

from app.scenes import SCENES
from app.settings import Settings
from app.viz.chapter import ABOUT
from app.web.api.deps import app_settings


def _text(page: str) -> str:
    """What a screen reader hears of a piece of markup: its text, the tags dropped, the spaces collapsed."""
    return " ".join(html.unescape(re.sub(r"<[^>]+>", "", page)).split())


def test_a_course_from_another_book_sees_no_notes(client, override):
    override(app_settings, Settings(source_notes=False))
    page = client.get("/scenes/simple-pendulum").text
    tag = page.split('class="section-tag">', 1)[1].split("</p>", 1)[0]
    assert "notes" not in tag and "Section" not in tag
    assert _text(tag) == SCENES["simple-pendulum"].summary  # the summary line stays
    assert 'id="errata"' not in page and "Notes on the source" not in page
    assert ABOUT not in html.unescape(client.get("/").text)
    assert 'id="about-chapter"' not in client.get("/").text


def test_by_default_the_notes_are_named_and_the_errata_heading_reads_as_two_phrases(client):
    page = client.get("/scenes/simple-pendulum").text
    assert "of the notes" in page.split('class="section-tag">', 1)[1].split("</p>", 1)[0]
    summary = page.split('class="errata-details">', 1)[1].split("</summary>", 1)[0]
    # prof-n 11: "Notes on the source chapter 3 formulas printed differently there" was heard as one run-on
    assert re.fullmatch(r"Notes on the source chapter · \d+ formulas? printed differently there", _text(summary))
    assert 'id="about-chapter"' in client.get("/").text
