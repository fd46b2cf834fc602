"""ETags on the cacheable GETs, and a 304 for a client that holds the current answer: one ASGI middleware.

The cacheable GETs are the answers that depend on the address alone (the scenes, a scene's derivation,
export, modes, work-precision runs and exercises, and the OpenAPI document); the classroom's answers say
``no-store`` and are never given one.  The ETag is a digest of the answer's bytes (weak, ``W/"…"``, since a
compressed answer carries the same one), so it changes exactly when the answer does; a request whose
``If-None-Match`` names it gets a 304 with no body.
"""

from __future__ import annotations

import hashlib
import re

from starlette.types import ASGIApp, Message, Receive, Scope, Send

# the paths of the cacheable GETs (also as the OpenAPI document writes them, with {scene_id})
_CACHEABLE = re.compile(r"/api/scenes(/[^/]+/(derivation|export|modes|work-precision|practice))?|/openapi\.json")


def cacheable(path: str) -> bool:
    return _CACHEABLE.fullmatch(path) is not None


def etag(body: bytes) -> str:
    return 'W/"' + hashlib.sha256(body).hexdigest()[:32] + '"'


def matches(if_none_match: str, tag: str) -> bool:
    """Whether an If-None-Match header names ``tag`` (weak comparison: W/ is ignored), or is ``*``."""
    if if_none_match.strip() == "*":
        return True
    opaque = tag.removeprefix("W/")
    return any(t.strip().removeprefix("W/") == opaque for t in if_none_match.split(","))


class ETags:
    def __init__(self, app: ASGIApp):
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["method"] not in ("GET", "HEAD") or not cacheable(scope["path"]):
            await self.app(scope, receive, send)
            return
        start: Message | None = None
        chunks: list[bytes] = []

        async def held(message: Message) -> None:
            nonlocal start
            if message["type"] == "http.response.start":
                start = message
                if message["status"] != 200:  # an error or anything else goes out as it is
                    await send(message)
                return
            if start is None or start["status"] != 200:
                await send(message)
                return
            chunks.append(message.get("body", b""))
            if not message.get("more_body", False):
                await self._answer(scope, start, b"".join(chunks), send)

        await self.app(scope, receive, held)

    async def _answer(self, scope: Scope, start: Message, body: bytes, send: Send) -> None:
        headers = list(start.get("headers", []))
        if any(k.lower() == b"cache-control" and b"no-store" in v for k, v in headers):
            await send(start)
            await send({"type": "http.response.body", "body": body})
            return
        tag = etag(body)
        asked = b", ".join(v for k, v in scope["headers"] if k == b"if-none-match").decode("latin-1")
        if asked and matches(asked, tag):
            kept = [(k, v) for k, v in headers if k.lower() in (b"cache-control", b"vary", b"content-location")]
            await send({"type": "http.response.start", "status": 304, "headers": [*kept, (b"etag", tag.encode())]})
            await send({"type": "http.response.body", "body": b""})
            return
        await send({**start, "headers": [*headers, (b"etag", tag.encode())]})
        await send({"type": "http.response.body", "body": body})
