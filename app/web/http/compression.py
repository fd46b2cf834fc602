"""Content codings: which one a request gets (``negotiate``, the one decision) and ``/api`` responses sent in it.

``negotiate`` reads ``Accept-Encoding`` with its weights (RFC 9110 §12.5.3): a coding weighted 0
(``gzip;q=0``) is refused, ``*`` stands for every coding the header does not name, and among those
accepted the client's highest weight wins, ties going to our order of preference (zstd, then gzip).
The pages (app/web/pages/chapter.py) ask it too, offering only gzip; the static files (app/web/rendering/templating.py) offer
``STATIC``'s codings, each compressed once at its best level: a vendor library from the copy written beside it
at set-up (``.zst`` by app/web/precompress.py, ``.gz`` by scripts/assets.sh), our own modules in memory.

For ``/api`` the chosen coding is kept in a context variable, which FastAPI's thread pool inherits:
``FastJSONResponse`` (app/web/http/responses.py) compresses its body right after encoding it, in the
route's thread, so a large simulation is never compressed on the event loop.  ``ApiCompression``,
a plain ASGI middleware, compresses every other ``/api`` response that is not compressed yet
(derivations, errors), and a streamed one chunk by chunk, each flushed so that the client can read
it at once.

zstd at level 1 against gzip at level 1 on the double pendulum's default
simulation (154 kB of JSON, best of 50 on this machine): 0.67 against 2.18 ms
to compress, 46 against 53 kB, 0.14 against 0.48 ms to decompress.  Chromium
and Firefox accept zstd; curl, older browsers and most HTTP libraries get gzip.
"""

from __future__ import annotations

import gzip
import re
import sys
import zlib
from collections.abc import Callable, Iterable
from contextvars import ContextVar

import anyio.to_thread
from starlette.datastructures import Headers, MutableHeaders
from starlette.types import ASGIApp, Message, Receive, Scope, Send

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
# a streamed body's chunk this large is compressed in a worker thread, not on the event loop
THREAD_MINIMUM_BYTES = 128 * 1024
# media types sent as they are: compressed already, or an event stream (as starlette's GZipMiddleware leaves them)
UNCOMPRESSED = frozenset(
    {"application/gzip", "application/x-gzip", "application/zip", "application/grpc", "audio/*", "font/woff",
     "font/woff2", "image/avif", "image/gif", "image/jpeg", "image/png", "image/webp", "text/event-stream", "video/*"}
)  # fmt: skip

Encoder = Callable[[bytes, bool], bytes]  # (chunk, more to come) -> its compressed bytes


def _gzip() -> Encoder:
    compressor = zlib.compressobj(GZIP_LEVEL, zlib.DEFLATED, 16 + zlib.MAX_WBITS)
    # a chunk with more to come is flushed to a byte boundary (readable at once); the last one ends the stream
    return lambda body, more: compressor.compress(body) + compressor.flush(zlib.Z_SYNC_FLUSH if more else zlib.Z_FINISH)


def _zstd() -> Encoder:
    compressor = zstd.ZstdCompressor(level=ZSTD_LEVEL)
    flush = {True: zstd.ZstdCompressor.FLUSH_BLOCK, False: zstd.ZstdCompressor.FLUSH_FRAME}
    return lambda body, more: compressor.compress(body, flush[more])


# the codings we can send, in our order of preference: each makes the encoder of one response
CODINGS: dict[str, Callable[[], Encoder]] = {"zstd": _zstd, "gzip": _gzip}

# a file compressed once and sent many times (the static files): each coding's sibling suffix and its best level.
# zstd at 19 sends plotly.js basic in 344 kB where gzip -9 sends 395 kB, KaTeX in 68 kB against 77 kB; Chromium
# asks for zstd over plain HTTP too (a classroom server), as `benchmarks/bench_browser.py`'s encoded sizes show.
STATIC: dict[str, tuple[str, int]] = {"zstd": (".zst", 19), "gzip": (".gz", 9)}

# the coding chosen for the request being served (None: send the body as it is)
CHOSEN: ContextVar[str | None] = ContextVar("api_content_coding", default=None)

# RFC 9110's qvalue: 0 to 1 with at most three decimals
_QVALUE = re.compile(r"(0(\.\d{0,3})?|1(\.0{0,3})?)")


def weights(accept_encoding: str) -> dict[str, float]:
    """Each coding the header names (lower case) with its weight; a malformed weight accepts nothing."""
    found: dict[str, float] = {}
    for item in accept_encoding.split(","):
        name, _, rest = item.partition(";")
        name = name.strip().lower()
        if not name:
            continue
        weight = 1.0
        for param in rest.split(";"):
            key, _, value = param.partition("=")
            if key.strip().lower() == "q":
                weight = float(value.strip()) if _QVALUE.fullmatch(value.strip()) else 0.0
        found[name] = weight
    return found


def negotiate(accept_encoding: str, offered: Iterable[str] = CODINGS) -> str | None:
    """The coding to send, of those ``offered`` (in our order of preference), or None for the body as it is."""
    weighed = weights(accept_encoding)
    chosen, best = None, 0.0
    for coding in offered:
        weight = weighed.get(coding, weighed.get("*", 0.0))
        if weight > best:  # a tie keeps the earlier, our preference
            chosen, best = coding, weight
    return chosen


def compress(body: bytes, coding: str | None) -> bytes | None:
    """``body`` in ``coding``, or None when it stays as it is (no coding, or too small to be worth it)."""
    if coding is None or len(body) < MINIMUM_BYTES:
        return None
    return CODINGS[coding]()(body, False)


def compress_once(body: bytes, coding: str) -> bytes:
    """``body`` in ``coding`` (one of ``STATIC``) at its best level: for a file sent many times."""
    level = STATIC[coding][1]
    return zstd.compress(body, level=level) if coding == "zstd" else gzip.compress(body, level, mtime=0)


def mark(headers: MutableHeaders, coding: str, length: int) -> None:
    """The headers of a body sent in ``coding``."""
    headers["content-encoding"] = coding
    headers["content-length"] = str(length)
    headers.add_vary_header("Accept-Encoding")


def _sent_as_is(start: Message) -> bool:
    """A response to pass through: encoded already, a part of a body (206), or of a type kept uncompressed."""
    headers = Headers(raw=start["headers"])
    media = headers.get("content-type", "").partition(";")[0].strip().lower()
    kinds = {media, media.partition("/")[0] + "/*", media.partition("+")[0]}
    return "content-encoding" in headers or start["status"] == 206 or not kinds.isdisjoint(UNCOMPRESSED)


class _Response:
    """The messages of one ``/api`` response on their way out: the start held until the first body says whether
    (and how) the body is compressed, then every chunk compressed as it comes."""

    def __init__(self, send: Send, coding: str | None) -> None:
        self.send = send
        self.coding = coding
        self.start: Message | None = None  # held until the first body
        self.encoder: Encoder | None = None

    async def __call__(self, message: Message) -> None:
        kind = message["type"]
        if kind == "http.response.start":
            message.setdefault("headers", [])
            if _sent_as_is(message):
                await self.send(message)
            else:
                self.start = message
        elif kind == "http.response.body" and self.encoder is not None:
            message["body"] = await self._encode(message.get("body", b""), message.get("more_body", False))
            await self.send(message)
        elif kind == "http.response.body" and self.start is not None:
            await self._first(self.start, message)
        else:  # passed through, a file sent by path, trailers, early hints
            if self.start is not None:
                start, self.start = self.start, None
                await self.send(start)
            await self.send(message)

    async def _first(self, start: Message, message: Message) -> None:
        self.start = None
        body, more = message.get("body", b""), message.get("more_body", False)
        if more or len(body) >= MINIMUM_BYTES:
            headers = MutableHeaders(raw=start["headers"])
            headers.add_vary_header("Accept-Encoding")  # another coding would have compressed it
            if self.coding is not None:
                self.encoder = CODINGS[self.coding]()
                message["body"] = await self._encode(body, more)
                headers["content-encoding"] = self.coding
                if more or start.get("trailers", False):
                    del headers["content-length"]
                else:
                    headers["content-length"] = str(len(message["body"]))
        await self.send(start)
        await self.send(message)

    async def _encode(self, body: bytes, more: bool) -> bytes:
        assert self.encoder is not None
        if len(body) >= THREAD_MINIMUM_BYTES:
            return await anyio.to_thread.run_sync(self.encoder, body, more)
        return self.encoder(body, more)


# The paths whose responses are made per request and compressed here: the API and the playground's page (a
# derivation rendered for the system in its address: 58 kB of HTML for the default system, 13 kB sent in zstd).
COMPRESSED_PATHS = ("/api/", "/playground")


class ApiCompression:
    """Chooses the coding of each ``/api`` request (and the playground's) and compresses what its route did not
    (pages' static files come precompressed from scripts/assets.sh, scene pages from app/web/pages/chapter.py's cache)."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or not scope["path"].startswith(COMPRESSED_PATHS):
            await self.app(scope, receive, send)
            return
        coding = negotiate(Headers(scope=scope).get("accept-encoding", ""))
        token = CHOSEN.set(coding)
        try:
            await self.app(scope, receive, _Response(send, coding))
        finally:
            CHOSEN.reset(token)
