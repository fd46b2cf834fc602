"""The scene pages' models and rendered bytes are the app's (its lifespan's ``PageCache``), given to the page
routes through ``Depends``: a test gives them a cache of its own."""

import pytest

from app.service.chapter import derivations
from app.settings import Settings
from app.web.api.deps import page_cache
from app.web.rendering.page_cache import PageCache


def _never():
    pytest.fail("built again although the app's cache holds it")


@pytest.mark.slow
def test_a_scene_page_fills_the_cache_the_route_is_given(client, override):
    pages = override(page_cache, PageCache())
    first = client.get("/scenes/simple-pendulum", headers={"Accept-Encoding": "identity"})
    assert first.status_code == 200
    doc = derivations.scene_document("simple-pendulum")  # the model the route was given
    model = pages.model("simple-pendulum", doc, _never)  # the route's model, kept
    plain, compressed = pages.page("simple-pendulum", model, _never, Settings().source_notes)
    assert plain == first.content and len(compressed) < len(plain) / 2
    zipped = client.get("/scenes/simple-pendulum", headers={"Accept-Encoding": "gzip"})
    assert zipped.content == plain  # the client decodes the kept gzip bytes into the same page


@pytest.mark.slow
def test_the_contents_page_keeps_each_cards_diagram(client, override):
    pages = override(page_cache, PageCache())
    assert client.get("/").status_code == 200
    for scene_id in derivations.SCENES:
        assert "<svg" in pages.card(scene_id, _never)


def test_a_new_model_renders_the_page_again():
    pages = PageCache()
    renders = []
    one, two = {"m": 1}, {"m": 2}
    for model in (one, one, two):
        pages.page("s", model, lambda model=model: renders.append(model) or b"page %d" % len(renders))
    assert renders == [one, two]


def test_a_setting_that_changes_the_page_renders_it_again():
    # the source notes shown, then hidden (settings' source_notes), then shown: each render its own
    pages = PageCache()
    renders = []
    model = {"m": 1}
    for notes in (True, True, False, True):
        pages.page("s", model, lambda notes=notes: renders.append(notes) or b"notes %d" % notes, notes)
    assert renders == [True, False, True]
