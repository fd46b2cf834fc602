"""Compressed ``/api`` responses: zstd for clients that accept it, else gzip, else none.

One content coding is chosen per request from its ``Accept-Encoding`` (our
order of preference among the codings it accepts with q > 0) and kept in a
context variable, which FastAPI's thread pool inherits: ``FastJSONResponse``
(app/web/responses.py) compresses its body right after encoding it, in the
route's thread, so a large simulation is never compressed on the event loop.
``ApiCompression`` compresses every other ``/api`` response that is not
compressed yet (derivations, errors), as starlette's GZipMiddleware would.

zstd at level 1 against gzip at level 1 on the double pendulum's default
simulation (154 kB of JSON, best of 50 on this machine): 0.67 against 2.18 ms
to compress, 46 against 53 kB, 0.14 against 0.48 ms to decompress.  Chromium
and Firefox accept zstd; curl, older browsers and most HTTP libraries get gzip.
"""

from __future__ import annotations

import sys
import zlib
from collections.abc import Callable
from contextvars import ContextVar

import anyio.to_thread
from starlette.datastructures import Headers, MutableHeaders
from starlette.middleware.gzip import GZipResponder, IdentityResponder
from starlette.types import ASGIApp, Receive, Scope, Send

if sys.version_info >= (3, 14):
    from compression import zstd
else:
    from backports import zstd

# Below about a kilobyte compression saves less than a packet.
MINIMUM_BYTES = 1024
# The fastest level of each keeps nearly all the saving: gzip level 5 gave 64 kB in 8-15 ms where
# level 1 gave 69 kB in 2.6 ms (a 184 kB simulation), zstd level 3 50 kB in 1.05 ms against level 1's 46 kB in 0.67 ms.
ZSTD_LEVEL = 1
GZIP_LEVEL = 1
# a streamed body's chunk this large is compressed in a worker thread, not on the event loop (as starlette does)
THREAD_MINIMUM_BYTES = 128 * 1024


def _gzip(body: bytes) -> bytes:
    return zlib.compress(body, GZIP_LEVEL, wbits=16 + zlib.MAX_WBITS)


def _zstd(body: bytes) -> bytes:
    return zstd.compress(body, ZSTD_LEVEL)


# the codings we can send, in our order of preference
CODINGS: dict[str, Callable[[bytes], bytes]] = {"zstd": _zstd, "gzip": _gzip}

# the coding chosen for the request being served (None: send the body as it is)
CHOSEN: ContextVar[str | None] = ContextVar("api_content_coding", default=None)


def negotiate(accept_encoding: str) -> str | None:
    """Our preferred coding among those the header accepts with q > 0 (``*`` accepts every one not named)."""
    weights: dict[str, float] = {}
    for item in accept_encoding.split(","):
        name, _, rest = item.partition(";")
        name = name.strip().lower()
        if not name:
            continue
        weight = 1.0
        for param in rest.split(";"):
            key, _, value = param.partition("=")
            if key.strip().lower() == "q":
                try:
                    weight = float(value)
                except ValueError:
                    weight = 0.0  # a malformed weight accepts nothing
        weights[name] = weight
    for coding in CODINGS:
        if weights.get(coding, weights.get("*", 0.0)) > 0.0:
            return coding
    return None


def compress(body: bytes, coding: str | None) -> bytes | None:
    """``body`` in ``coding``, or None when it stays as it is (no coding, or too small to be worth it)."""
    if coding is None or len(body) < MINIMUM_BYTES:
        return None
    return CODINGS[coding](body)


def mark(headers: MutableHeaders, coding: str, length: int) -> None:
    """The headers of a body sent in ``coding``."""
    headers["content-encoding"] = coding
    headers["content-length"] = str(length)
    headers.add_vary_header("Accept-Encoding")


class ZstdResponder(IdentityResponder):
    """starlette's responder with zstd frames: one per whole body, flushed blocks for a streamed one."""

    content_encoding = "zstd"

    def __init__(self, app: ASGIApp, minimum_size: int) -> None:
        super().__init__(app, minimum_size)
        self._compressor: zstd.ZstdCompressor | None = None

    def _compress(self, body: bytes, more_body: bool) -> bytes:
        if self._compressor is None:
            self._compressor = zstd.ZstdCompressor(level=ZSTD_LEVEL)
        mode = zstd.ZstdCompressor.FLUSH_BLOCK if more_body else zstd.ZstdCompressor.FLUSH_FRAME
        return self._compressor.compress(body, mode)

    async def apply_compression(self, body: bytes, *, more_body: bool) -> bytes:
        if len(body) >= THREAD_MINIMUM_BYTES:
            return await anyio.to_thread.run_sync(self._compress, body, more_body)
        return self._compress(body, more_body)


def _responder(app: ASGIApp, coding: str | None) -> ASGIApp:
    if coding == "zstd":
        return ZstdResponder(app, MINIMUM_BYTES)
    if coding == "gzip":
        return GZipResponder(app, MINIMUM_BYTES, compresslevel=GZIP_LEVEL, thread_minimum_size=THREAD_MINIMUM_BYTES)
    return IdentityResponder(app, MINIMUM_BYTES)  # adds Vary: Accept-Encoding where another coding would compress


class ApiCompression:
    """Chooses the coding of each ``/api`` request and compresses what its route did not (pages' static files
    come precompressed from scripts/assets.sh, pages from app/web/pages.py's cache)."""

    def __init__(self, app: ASGIApp):
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or not scope["path"].startswith("/api/"):
            await self.app(scope, receive, send)
            return
        coding = negotiate(Headers(scope=scope).get("accept-encoding", ""))
        token = CHOSEN.set(coding)
        try:
            # a response already compressed (Content-Encoding set) passes through the responder untouched
            await _responder(self.app, coding)(scope, receive, send)
        finally:
            CHOSEN.reset(token)
