"""What one running app keeps of its scene pages: built by ``app.main``'s lifespan, given to the page
routes through ``Depends`` (``app.web.api.deps.PagesDep``).

Per scene: its page model (rebuilt when its derivation document is a new object), the diagram of its
card on the contents page, and its rendered page (plain and gzip-compressed), rendered again only when
its model changed.  Building is the caller's (``app.web.pages.chapter``); this object only remembers.
"""

from __future__ import annotations

import gzip
import threading
from collections.abc import Callable
from typing import Any


class PageCache:
    def __init__(self) -> None:
        self._models: dict[str, tuple[int, dict[str, Any]]] = {}
        self._cards: dict[str, str] = {}
        self._pages: dict[str, tuple[dict[str, Any], object, bytes, bytes]] = {}
        self._lock = threading.Lock()

    def model(self, scene_id: str, doc: object, build: Callable[[], dict[str, Any]]) -> dict[str, Any]:
        """The scene's page model for the derivation document ``doc``, built by ``build`` if it changed."""
        with self._lock:
            cached = self._models.get(scene_id)
        if cached and cached[0] == id(doc):
            return cached[1]
        model = build()
        with self._lock:
            self._models[scene_id] = (id(doc), model)
        return model

    def card(self, scene_id: str, build: Callable[[], str]) -> str:
        """The diagram of the scene's card on the contents page (built once)."""
        with self._lock:
            found = self._cards.get(scene_id)
        if found is None:
            found = build()
            with self._lock:
                self._cards[scene_id] = found
        return found

    def page(
        self, scene_id: str, model: dict[str, Any], render: Callable[[], bytes], variant: object = None
    ) -> tuple[bytes, bytes]:
        """The scene's page, plain and gzip-compressed, rendered by ``render`` only when ``model`` is new or the
        page's ``variant`` (a setting that changes what it shows) differs from the last render's."""
        with self._lock:
            cached = self._pages.get(scene_id)
        if cached is None or cached[0] is not model or cached[1] != variant:
            body = render()
            cached = (model, variant, body, gzip.compress(body, 9))
            with self._lock:
                self._pages[scene_id] = cached
        return cached[2], cached[3]
