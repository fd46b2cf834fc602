"""The embed page's options, each once (app/web/pages/embed.py serves the page; the scene page offers its frames).

``VIEWS``: what each ``?view=`` of ``/embed/scenes/{id}`` shows, and the height (CSS pixels) of a frame
900 px wide that shows it whole: the tallest scene's embed page, measured in Chromium, rounded up
(tests/browser/test_embed_views.py holds every scene to it).
"""

from __future__ import annotations

from typing import Any
from urllib.parse import urlencode

from app.scenes import SCENES

VIEWS: dict[str, dict[str, Any]] = {
    "full": {"says": "the animation, the initial conditions, the parameters and the run's duration", "height": 1840},
    "compact": {"says": "the animation with Play and the time slider alone, no forms", "height": 540},
}
DEFAULT_VIEW = "full"


def embeddable(model: dict[str, Any]) -> list[str]:
    """The panels an embed page may show beside the animation: the page's plots that are not folded away."""
    return [k for k in model["panels"] if not k.startswith("animation") and k not in model["folded_panels"]]


def embed_src(scene_id: str, view: str = DEFAULT_VIEW, panel: str | None = None) -> str:
    """The address of a scene's embed page in a view (the default view needs no ``?view=``), with one plot."""
    query = {k: v for k, v in (("view", None if view == DEFAULT_VIEW else view), ("panel", panel)) if v}
    return f"/embed/scenes/{scene_id}" + (f"?{urlencode(query)}" if query else "")


def scene_choices() -> list[dict[str, str]]:
    """Every scene's embed page by its title: what an embed address that names no scene offers instead."""
    return [{"title": s.title, "href": embed_src(k)} for k, s in SCENES.items()]


def refusal(model: dict[str, Any], view: str, panel: str | None) -> dict[str, Any] | None:
    """What an embed address asks for that the scene's page cannot show (a view, else a plot), with the
    choices there are by their titles, each a working address; None when it can show it all."""
    scene = model["info"]["id"]
    plots = embeddable(model)
    if view not in VIEWS:
        keep = panel if panel in plots else None
        choices = [{"title": f"{v.capitalize()}: {a['says']}", "href": embed_src(scene, v, keep)} for v, a in VIEWS.items()]
        return {"kind": "view", "missing": view[:40], "choices": choices}
    if panel is not None and panel not in plots:
        alone = {"title": "None: the animation alone", "href": embed_src(scene, view)}
        choices = [{"title": model["panel_text"][k]["title"], "href": embed_src(scene, view, k)} for k in plots]
        return {"kind": "panel", "missing": panel[:40], "choices": [*choices, alone]}
    return None


def offers(scene_id: str) -> list[dict[str, Any]]:
    """The frames the scene page offers a lecturer: each view's address, what it shows and its height."""
    return [
        {"view": v, "says": a["says"], "src": embed_src(scene_id, v), "height": a["height"]} for v, a in VIEWS.items()
    ]
