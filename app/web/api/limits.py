"""Request bodies bounded before anything reads them: one ASGI middleware for every POST route.

A body larger than ``MAX_BODY_BYTES`` is refused with a 413 as soon as its
``Content-Length`` says so (or, for a chunked body, as soon as the count
passes the cap), before the route or the JSON parser sees a byte of it.  A
JSON text nested deeper than ``MAX_JSON_DEPTH`` is refused with a 400 before
``json.loads`` runs (Python's parser recurses once per level).  A body that
does not arrive within ``settings().body_seconds`` (a client sending a byte at
a time, or one that sent ``Expect: 100-continue`` and then nothing) gets a 408
and its connection is closed, rather than holding a socket for ever.  A body
sent to the API under a media type other than JSON (a form's
``application/x-www-form-urlencoded``, ``text/plain``) gets a 415 before it is
read.  Every refusal is an RFC 9457 problem (app/web/api/errors.py).
"""

from __future__ import annotations

import asyncio
import json
from typing import Any

from starlette.types import ASGIApp, Message, Receive, Scope, Send

from app.settings import settings
from app.web.api.errors import PROBLEM_JSON, problem_body

MAX_BODY_BYTES = 32 * 1024
MAX_JSON_DEPTH = 32  # the deepest request the API documents is 5 levels deep
_BODY_METHODS = frozenset({"POST", "PUT", "PATCH"})
NOT_JSON = "the body must be JSON: send it with Content-Type: application/json"


def _json_media(value: bytes) -> bool:
    """Whether a Content-Type names JSON (application/json, or a +json type such as application/merge-patch+json)."""
    media = value.decode("latin-1").partition(";")[0].strip().lower()
    return media == "application/json" or (media.startswith("application/") and media.endswith("+json"))

class TooDeep(ValueError):
    """A JSON text nested deeper than allowed."""


def _as_utf8(data: bytes) -> bytes:
    """The bytes of a JSON text re-encoded as UTF-8, in the encoding ``json.loads`` would detect for them."""
    encoding = json.detect_encoding(data)
    if encoding == "utf-8":
        return data
    # utf-8-sig, utf-16(-le/-be), utf-32(-le/-be): what the parser would decode; undecodable bytes count
    # for nothing here (the parser refuses them anyway)
    return data.decode(encoding, "replace").encode("utf-8", "surrogatepass")


def check_json_depth(text: str | bytes, limit: int = MAX_JSON_DEPTH) -> None:
    """Refuse a JSON text whose arrays and objects nest deeper than ``limit``, by scanning (not parsing) it.

    Brackets inside strings do not count; raises TooDeep as soon as ``limit`` is passed.  Bytes are scanned
    as the document ``json.loads`` would read: a body in UTF-16 or UTF-32 (which ``json.loads`` detects from
    its first bytes) is decoded first, so its nesting cannot hide between zero bytes.
    """
    data = text.encode("utf-8", "surrogatepass") if isinstance(text, str) else _as_utf8(text)
    if data.count(b"[") + data.count(b"{") <= limit:  # the common case, decided at C speed
        return
    depth = 0
    in_string = escaped = False
    for byte in data:
        if in_string:
            if escaped:
                escaped = False
            elif byte == 0x5C:  # backslash
                escaped = True
            elif byte == 0x22:  # closing quote
                in_string = False
        elif byte == 0x22:
            in_string = True
        elif byte in (0x5B, 0x7B):  # [ {
            depth += 1
            if depth > limit:
                raise TooDeep(f"the JSON is nested deeper than {limit} levels")
        elif byte in (0x5D, 0x7D):  # ] }
            depth -= 1


def too_large_message(size: int | None) -> str:
    told = f"{size} bytes" if size is not None else "larger than that"
    return f"the request body is {told}; at most {MAX_BODY_BYTES} bytes are allowed"


async def _refuse(send: Send, status: int, detail: str, extra: dict[str, str] | None = None) -> None:
    body = json.dumps(problem_body(status, detail)).encode()
    headers = [(b"content-type", PROBLEM_JSON.encode()), (b"content-length", str(len(body)).encode())]
    headers += [(k.lower().encode(), v.encode()) for k, v in (extra or {}).items()]
    if status in (408, 413):
        headers.append((b"connection", b"close"))  # the unread body is not worth reading
    await send({"type": "http.response.start", "status": status, "headers": headers})
    await send({"type": "http.response.body", "body": body})


class BodyLimit:
    """Cap every request body (413) and the nesting of JSON bodies (400), then replay the body to the app."""

    def __init__(
        self,
        app: ASGIApp,
        max_bytes: int = MAX_BODY_BYTES,
        max_depth: int = MAX_JSON_DEPTH,
        seconds: float | None = None,
    ):
        self.app = app
        self.max_bytes = max_bytes
        self.max_depth = max_depth
        self.seconds = seconds or settings().body_seconds

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["method"] not in _BODY_METHODS:
            await self.app(scope, receive, send)
            return
        declared = [v for k, v in scope["headers"] if k == b"content-length"]
        media = [v for k, v in scope["headers"] if k == b"content-type"]
        # every API route with a body reads JSON: a form or text body is the wrong media type, not a bad value
        has_body = any(k == b"transfer-encoding" for k, _ in scope["headers"]) or any(v != b"0" for v in declared)
        if scope["path"].startswith("/api/") and media and has_body and not _json_media(media[0]):
            await _refuse(send, 415, NOT_JSON, {"Accept-Post": "application/json"})
            return
        if declared:
            if len(declared) > 1 or not declared[0].isdigit():
                await _refuse(send, 400, "the Content-Length header is not a number")
                return
            if int(declared[0]) > self.max_bytes:
                await _refuse(send, 413, too_large_message(int(declared[0])))
                return
        chunks: list[bytes] = []
        seen = 0
        deadline = asyncio.get_running_loop().time() + self.seconds
        while True:
            try:
                # a deadline on this task (no task of its own per message, as wait_for would create)
                async with asyncio.timeout_at(deadline):
                    message = await receive()
            except TimeoutError:
                await _refuse(send, 408, f"the request body did not arrive within {self.seconds:g} s")
                return
            if message["type"] != "http.request":  # the client went away
                return
            chunk = message.get("body", b"")
            seen += len(chunk)
            if seen > self.max_bytes:  # a chunked body declares no length: count it as it streams in
                await _refuse(send, 413, too_large_message(None))
                return
            chunks.append(chunk)
            if not message.get("more_body", False):
                break
        body = b"".join(chunks)
        try:
            check_json_depth(body, self.max_depth)
        except TooDeep as exc:
            await _refuse(send, 400, f"{exc}; requests here are at most a few levels deep")
            return
        replayed = False

        async def replay() -> Message:
            nonlocal replayed
            if not replayed:
                replayed = True
                return {"type": "http.request", "body": body, "more_body": False}
            return await receive()

        await self.app(scope, replay, send)


def install(app: Any) -> None:
    app.add_middleware(BodyLimit)
