"""Embed pages (/embed/scenes/{id}): the simulation alone for a course page's frame, framed only by the sites
the ``embed_ancestors`` setting lists."""

from __future__ import annotations

import re

import pytest
from pydantic import ValidationError
from starlette.applications import Starlette
from starlette.responses import PlainTextResponse
from starlette.routing import Route
from starlette.testclient import TestClient

from app.settings import Settings
from app.web.http.headers import CSP, SecurityHeaders

PANEL = re.compile(r'data-panel="([^"]+)"')


def test_an_embed_page_holds_the_mechanism_and_its_controls_and_nothing_else(client):
    page = client.get("/embed/scenes/simple-pendulum")
    assert page.status_code == 200
    html = page.text
    assert PANEL.findall(html) == ["animation-2d"]
    assert 'canvas class="mechanism' in html and 'id="controls"' in html and 'id="scene-data"' in html
    # no derivation, no site chrome, no link to the view; a link to the whole page
    for absent in (
        'id="derivation"',
        'class="site-header"',
        'class="site-footer"',
        'id="view-link"',
        'id="embed-offer"',
    ):
        assert absent not in html
    assert 'href="/scenes/simple-pendulum"' in html and "/static/js/embed.js" in html
    # the run's duration and tolerance are there to change: why the run is as long as it is, and how to make it finer
    assert 'name="t_end"' in html and 'name="rtol"' in html
    assert '<form id="controls" class="controls" aria-label="Simulation settings" novalidate>' in html


@pytest.mark.slow
def test_the_compact_view_keeps_the_animation_and_one_panel_and_hides_the_form(client):
    page = client.get("/embed/scenes/pulley?view=compact&panel=energy")
    assert page.status_code == 200
    html = page.text
    assert PANEL.findall(html) == ["animation-2d", "energy"]
    assert 'class="embed embed-compact embed-with-panel"' in html
    # the form stays for the run's defaults, out of sight
    assert '<form id="controls" class="controls" aria-label="Simulation settings" novalidate hidden>' in html


def _words(html: str) -> str:
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", "", html))


def _fits_a_frame(html: str) -> None:
    """An embed error page (inst-c 25): no site header or footer, no code words, and a link that opens the book
    in the whole window."""
    assert 'class="site-header"' not in html and 'class="site-footer"' not in html
    assert "?panel=" not in _words(html) and "?view=" not in _words(html) and "<code>" not in html
    assert '<a class="embed-full" href="/" target="_top">Open this book</a>' in html


def test_an_unknown_view_is_refused_with_the_views_there_are(client):
    page = client.get("/embed/scenes/pulley?view=tiny&panel=energy")
    assert page.status_code == 422
    _fits_a_frame(page.text)
    text = _words(page.text)
    assert "This frame asks for a view of the three masses on pulleys that the book does not have" in text
    assert "The frame's address names the view “tiny”. Change it to one of these:" in text
    # each view by what it shows, its address keeping the plot asked for
    choices = re.findall(r'<li><a href="([^"]+)">([^<]+)</a></li>', page.text)
    assert [(h.replace("&amp;", "&"), t.split(":")[0]) for h, t in choices] == [
        ("/embed/scenes/pulley?panel=energy", "Full"), ("/embed/scenes/pulley?view=compact&panel=energy", "Compact")]  # fmt: skip
    for href, _ in choices:
        assert client.get(href.replace("&amp;", "&")).status_code == 200


def test_the_scene_page_offers_each_view_as_a_frame_with_its_height(client):
    from app.web.rendering.embed_views import VIEWS

    html = client.get("/scenes/pulley").text
    offer = re.search(r'<details class="embed-offer" id="embed-offer">(.*?)</details>', html, re.S)
    assert offer is not None
    frames = re.findall(r'data-src="([^"]+)" data-height="(\d+)"', offer[1])
    assert frames == [("/embed/scenes/pulley", str(VIEWS["full"]["height"])),
                      ("/embed/scenes/pulley?view=compact", str(VIEWS["compact"]["height"]))]  # fmt: skip
    # in a lecturer's words (inst-c 22): no setting's name, no address code; the plots chosen by their titles
    words = _words(offer[1])
    assert "ask whoever set up this book for your course to allow your course site" in words
    assert "LAGRANGE_" not in offer[1] and "panel=" not in words
    plots = re.findall(r'<option value="([^"]*)"[^>]*>([^<]+)</option>', offer[1])
    assert plots[0] == ("", "None: the animation alone") and ("energy", "Energy against time") in plots
    for kind, _ in plots[1:]:
        assert client.get(f"/embed/scenes/pulley?panel={kind}").status_code == 200
    # each offered address is a page that answers
    for src, _ in frames:
        assert client.get(src.replace("&amp;", "&")).status_code == 200


def test_one_panel_may_be_asked_for(client):
    html = client.get("/embed/scenes/simple-pendulum?panel=phase").text
    assert PANEL.findall(html) == ["animation-2d", "phase"]


def test_an_unknown_panel_is_refused_with_the_panels_there_are_by_their_titles(client):
    page = client.get("/embed/scenes/simple-pendulum?panel=energ")
    assert page.status_code == 422
    _fits_a_frame(page.text)
    text = _words(page.text)
    assert "This frame asks for a plot that the simple pendulum does not have" in text
    assert "The frame's address names the plot “energ”. Change it to one of the plots" in text
    choices = re.findall(r'<li><a href="([^"]+)">([^<]+)</a></li>', page.text)
    assert choices[0] == ("/embed/scenes/simple-pendulum?panel=energy", "Energy against time")
    assert choices[-1] == ("/embed/scenes/simple-pendulum", "None: the animation alone")
    for href, _ in choices:
        assert client.get(href).status_code == 200


@pytest.mark.parametrize("address", ["/embed/scenes/simple-pend", "/embed/simple-pendulum"])
def test_an_unknown_scene_is_a_404_listing_the_scenes_by_title(client, address):
    page = client.get(address)
    assert page.status_code == 404
    _fits_a_frame(page.text)
    assert "This frame's address names no scene of the book" in _words(page.text)
    choices = re.findall(r'<li><a href="([^"]+)">([^<]+)</a></li>', page.text)
    assert ("/embed/scenes/simple-pendulum", "Simple pendulum") in choices
    assert ("/embed/scenes/incline-block", "Block on a fixed incline") in choices
    # titles only: no raw id beside a title
    assert "incline-block" not in _words(page.text)


def test_by_default_no_site_may_frame_an_embed_page(client):
    headers = client.get("/embed/scenes/simple-pendulum").headers
    assert headers["content-security-policy"] == CSP and headers["x-frame-options"] == "DENY"


def _framed(ancestors: str) -> TestClient:
    async def ok(request):
        return PlainTextResponse("ok")

    app = Starlette(routes=[Route("/embed/scenes/x", ok), Route("/scenes/x", ok)])
    return TestClient(SecurityHeaders(app, embed_ancestors=ancestors))


def test_the_listed_sites_may_frame_embed_pages_and_no_other_page():
    client = _framed("https://lms.example.edu,https://*.course.example.org:8443")
    embed = client.get("/embed/scenes/x").headers
    rules = dict(rule.split(" ", 1) for rule in embed["content-security-policy"].split("; "))
    assert rules["frame-ancestors"] == "https://lms.example.edu https://*.course.example.org:8443"
    assert "x-frame-options" not in embed  # it cannot name a site; the CSP rule governs
    assert rules["script-src"] == "'self' 'unsafe-eval'"  # the rest of the policy is unchanged
    other = client.get("/scenes/x").headers
    assert other["content-security-policy"] == CSP and other["x-frame-options"] == "DENY"


@pytest.mark.parametrize(
    "bad", ["lms.example.edu", "https://lms.example.edu/course", "*", "'self'", "https://a.edu https://b.edu"]
)
def test_the_setting_takes_origins_only(bad):
    with pytest.raises(ValidationError, match="is not a site's origin: write scheme://host"):
        Settings(embed_ancestors=bad)


def test_the_setting_tidies_its_list():
    assert Settings(embed_ancestors=" https://a.edu , http://127.0.0.1:8001,").embed_ancestors == (
        "https://a.edu,http://127.0.0.1:8001"
    )
