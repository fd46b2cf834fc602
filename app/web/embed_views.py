"""The embed page's options, each once (app/web/embed.py serves the page; the scene page offers its frames).

``VIEWS``: what each ``?view=`` of ``/embed/scenes/{id}`` shows, and the height (CSS pixels) of a frame
900 px wide that shows it whole: the tallest scene's embed page, measured in Chromium, rounded up
(tests/browser/test_embed_views.py holds every scene to it).
"""

from __future__ import annotations

from typing import Any

VIEWS: dict[str, dict[str, Any]] = {
    "full": {"says": "the animation, the initial conditions, the parameters and the run's duration", "height": 1760},
    "compact": {"says": "the animation with Play and the time slider alone, no forms", "height": 540},
}
DEFAULT_VIEW = "full"


def embed_src(scene_id: str, view: str = DEFAULT_VIEW) -> str:
    """The address of a scene's embed page in a view (the default view needs no ``?view=``)."""
    return f"/embed/scenes/{scene_id}" + ("" if view == DEFAULT_VIEW else f"?view={view}")


def offers(scene_id: str) -> list[dict[str, Any]]:
    """The frames the scene page offers a lecturer: each view's address, what it shows and its height."""
    return [
        {"view": v, "says": a["says"], "src": embed_src(scene_id, v), "height": a["height"]} for v, a in VIEWS.items()
    ]
