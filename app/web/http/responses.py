"""Lean JSON responses for the documents the service produces (simulations, sections, modes).

``FastJSONResponse`` encodes with orjson (app.service.runtime.encoding) when it is
built: inside a plain ``def`` route that is FastAPI's thread pool, never the
event loop, and there is no ``jsonable_encoder`` pass over thousands of floats.
It compresses there too, in the coding app/web/http/compression.py chose for the
request.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from starlette.background import BackgroundTask
from starlette.responses import Response

from app.service.runtime.encoding import dumps
from app.web.http.compression import CHOSEN, compress, mark


class FastJSONResponse(Response):
    media_type = "application/json"

    def __init__(
        self,
        content: Any,
        status_code: int = 200,
        headers: Mapping[str, str] | None = None,
        background: BackgroundTask | None = None,
    ) -> None:
        super().__init__(content, status_code, headers, background=background)
        coding = CHOSEN.get()
        compressed = compress(self.body, coding)
        if compressed is not None and coding is not None:
            self.body = compressed
            mark(self.headers, coding, len(compressed))

    def render(self, content: Any) -> bytes:
        return dumps(content)
