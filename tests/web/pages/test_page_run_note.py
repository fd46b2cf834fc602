"""What a reader should know about a simulation stands beside it, not in the problem's statement (issue 40,
prof-g 48); the double pendulum's Lyapunov exponent there is measured, not typed."""

from __future__ import annotations

import html
import math
import re

import numpy as np
import pytest

from app.numerics.lyapunov import largest_exponent
from app.service.chapter.derivations import PROCESS_SCENES, scene
from app.service.simulations.simulate_request import parameter_vector


def _note(page: str) -> str:
    note = re.search(r'<p class="help run-note" id="run-note">(.*?)</p>', page, re.S)
    assert note, "no note beside the simulation"
    return re.sub(r"<[^>]+>", "", note.group(1))


def test_the_double_pendulum_statement_is_physics_and_its_chaos_is_named_beside_the_simulation(client):
    page = html.unescape(client.get("/scenes/double-pendulum").text)
    statement = re.search(r'<p class="statement">(.*?)</p>', page, re.S).group(1)
    for words in ("last digits", "tolerance", "Integration", "three times", "Lyapunov"):
        assert words not in statement, words
    said = _note(page)
    assert "largest Lyapunov exponent is about" in said and "The default run lasts 3 s" in said, said
    assert "putting it back at that distance every 0.1 s" in said and "over 100 s" in said, said


@pytest.mark.slow
def test_the_exponent_the_page_prints_is_the_one_a_second_run_beside_the_first_measures(client):
    # measured again here, outside the page's cache, from the scene's default start and parameters
    s = scene("double-pendulum")
    d = PROCESS_SCENES.derivation(s.id)
    system, _ = PROCESS_SCENES.system(s.id)
    q = system.coordinates
    y0 = np.array([s.initial[n] for n in q] + [s.initial[f"{n}_dot"] for n in q])
    value = largest_exponent(system, parameter_vector(d, {}), y0, s.lyapunov_seconds, 60.0).value
    assert value > 0.5  # chaotic: nearby starts part exponentially
    rate = f"{value:.2g}"
    said = _note(html.unescape(client.get("/scenes/double-pendulum").text))
    assert f"exponent is about {rate} s⁻¹" in said, (value, said)
    # the growth per second is e^λ, from the printed λ
    assert f"grows about {math.exp(float(rate)):.2g}-fold each second" in said, said
    assert "θ₁ larger by 10⁻⁹ rad" in said, said


def test_a_scene_without_a_note_shows_none(client):
    assert 'id="run-note"' not in client.get("/scenes/simple-pendulum").text
