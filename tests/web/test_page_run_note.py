"""What a reader should know about a simulation stands beside it, not in the problem's statement (issue 40,
prof-g 48)."""

from __future__ import annotations

import html
import re


def test_the_double_pendulum_statement_is_physics_and_its_chaos_is_named_beside_the_simulation(client):
    page = html.unescape(client.get("/scenes/double-pendulum").text)
    statement = re.search(r'<p class="statement">(.*?)</p>', page, re.S).group(1)
    for words in ("last digits", "tolerance", "Integration", "three times"):
        assert words not in statement, words
    note = re.search(r'<p class="help run-note" id="run-note">(.*?)</p>', page, re.S)
    assert note, "no note beside the simulation"
    said = re.sub(r"<[^>]+>", "", note.group(1))
    assert "largest Lyapunov exponent is about 1.4 s⁻¹" in said, said
    assert "rescaling the gap every 0.1 s" in said and "The run shown lasts 3 s" in said


def test_a_scene_without_a_note_shows_none(client):
    assert 'id="run-note"' not in client.get("/scenes/simple-pendulum").text
