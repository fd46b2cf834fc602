"""A scene page says each thing once (issue 40, prof-f 25, 27 and prof-e 12)."""

from __future__ import annotations

import html
import itertools

import pytest

from app.scenes import SCENES
from app.viz.chapter import ABOUT


@pytest.mark.slow
def test_what_the_chapter_is_is_said_on_the_contents_page_and_pointed_to_from_a_scene(client):
    # prof-f 25: the Errata's paragraph about the chapter was copied onto every scene page
    contents = client.get("/").text
    assert ABOUT in html.unescape(contents) and 'id="about-chapter"' in contents
    with_errata = [s for s in SCENES if client.get(f"/api/scenes/{s}/derivation").json().get("errata")]
    assert with_errata
    for scene_id in with_errata:
        page = client.get(f"/scenes/{scene_id}").text
        assert ABOUT not in html.unescape(page), scene_id
        assert '<a href="/#about-chapter">about the chapter</a>' in page, scene_id


@pytest.mark.slow
@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_the_reason_h_is_conserved_is_given_once(client, scene_id):
    # prof-f 27: "h is conserved. (The reason is given with the conserved quantities above.)" on every page
    page = client.get(f"/scenes/{scene_id}").text
    assert "The reason is given" not in page
    for reason in (
        "no non-conservative force acts, so dh/dt",
        "the generalized forces do no work (Σ Q q̇ = 0), so dh/dt",
    ):
        assert page.count(reason) <= 1, (scene_id, reason)


def test_the_damped_results_say_h_is_not_conserved_once_and_use_one_letter(client):
    # prof-e 12: "h is not conserved. The generalized forces do work at the rate Σ Q q̇, so h is not conserved: …"
    page = client.get("/scenes/damped-pendulum").text
    assert "so h is not conserved" not in page and page.count("<strong>h is not conserved.</strong>") == 1
    assert "<strong>h is not conserved.</strong> The generalized forces do work at the rate Σ Q q̇: dh/dt" in page
    # the statement's answer is dh/dt = … = −bθ̇²; the sentence beneath it speaks of h too, not of dE/dt
    answer = client.get("/api/scenes/damped-pendulum/derivation").json()
    power = next(s for s in answer["steps"] if s["key"] == "power")
    assert power["latex"].startswith(r"\frac{dh}{dt}") and "dE/dt" not in power["explanation"]
    assert power["explanation"].startswith("h, which equals E here, falls")


# prof-g 44, 51: the engine's generic captions, which a chapter scene replaces by reasons about its own system
_GENERIC_CAPTIONS = (
    "Each mass is placed in Cartesian coordinates as a function of the generalized coordinates",
    "The dot product of each velocity with itself",
    "T adds up one half of mass times squared speed",
    "The potential energy depends on positions only",
    "The Lagrangian is kinetic minus potential energy",
    "The two partial derivatives the Euler–Lagrange equation needs",
)
# prof-g 45, 51: how the equilibria were found, said as computer algebra or as a program's search
_SOLVER_TALK = ("polynomial in the coordinates", "solved exactly", "numerical search over a full period")


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_each_derivation_step_has_its_own_caption_about_this_system(client, scene_id):
    steps = client.get(f"/api/scenes/{scene_id}/derivation").json()["steps"]
    for before, after in itertools.pairwise(steps):
        assert before["explanation"] != after["explanation"], (scene_id, before["key"], after["key"])
    page = html.unescape(client.get(f"/scenes/{scene_id}").text)
    for words in _GENERIC_CAPTIONS + _SOLVER_TALK:
        assert words not in page, (scene_id, words)


@pytest.mark.parametrize("scene_id", ["coupled-oscillators", "double-pendulum"])
def test_the_equilibria_step_says_why_the_list_is_complete_in_physical_terms(client, scene_id):
    steps = client.get(f"/api/scenes/{scene_id}/derivation").json()["steps"]
    said = next(s["explanation"] for s in steps if s["key"] == "equilibria")
    assert "These are all the equilibria: " in said, said
