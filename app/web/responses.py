"""Lean JSON responses, and gzip for API clients that accept it.

``FastJSONResponse`` encodes with orjson (app.service.encoding) when it is
built: inside a plain ``def`` route that is FastAPI's thread pool, never the
event loop, and there is no ``jsonable_encoder`` pass over thousands of floats.
"""

from __future__ import annotations

from typing import Any

from starlette.middleware.gzip import GZipMiddleware
from starlette.responses import Response
from starlette.types import ASGIApp, Receive, Scope, Send

from app.service.encoding import dumps

# Below about a kilobyte gzip saves less than a packet.  On a 184 kB simulation document level 1
# gave 69 kB in 2.6 ms against level 5's 64 kB in 8-15 ms: the fastest level keeps nearly all the saving.
GZIP_MINIMUM_BYTES = 1024
GZIP_LEVEL = 1


class FastJSONResponse(Response):
    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return dumps(content)


class ApiGzip:
    """gzip for ``/api`` responses (pages' static files come precompressed from assets.sh)."""

    def __init__(self, app: ASGIApp):
        self.app = app
        self.gzip = GZipMiddleware(app, minimum_size=GZIP_MINIMUM_BYTES, compresslevel=GZIP_LEVEL)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http" and scope["path"].startswith("/api/"):
            await self.gzip(scope, receive, send)
        else:
            await self.app(scope, receive, send)
