"""Content-coding negotiation and the compression of /api responses (app/web/http/compression.py)."""

from __future__ import annotations

import gzip
import zlib

import anyio
import pytest
from fastapi.testclient import TestClient
from starlette.responses import Response, StreamingResponse

from app.web.http import compression
from app.web.http.compression import ApiCompression, negotiate, zstd
from app.web.precompress import precompress
from app.web.rendering import templating


@pytest.mark.parametrize(
    ("header", "chosen"),
    [
        ("gzip, deflate, br, zstd", "zstd"),  # Chromium's
        ("gzip, deflate", "gzip"),  # curl --compressed, most libraries
        ("zstd;q=0, gzip", "gzip"),  # refused by weight
        ("ZSTD ; q=0.5", "zstd"),  # any positive weight, any case and spacing
        ("*", "zstd"),
        ("*, zstd;q=0", "gzip"),  # named with q=0 beats the wildcard
        ("gzip;q=nonsense", None),  # a malformed weight accepts nothing
        ("gzip;q=1.5", None),  # so does one outside RFC 9110's 0 to 1 with three decimals
        ("gzip;q=0.0001", None),
        ("gzip;q=0", None),
        ("gzip;q=0.000", None),
        ("gzip; q=0.001", "gzip"),
        ("gzip;q=0.5, zstd;q=0.4", "gzip"),  # the client's higher weight wins
        ("zstd;q=0.5, gzip;q=0.5", "zstd"),  # a tie goes to our preference
        ("gzip;q=0, *", "zstd"),
        ("gzip;q=0, zstd;q=0, *", None),
        ("identity", None),
        ("identity;q=0", None),  # nothing we can send is accepted: the body goes as it is
        ("br", None),
        ("", None),
        (",,;", None),
    ],
)
def test_negotiate_picks_what_the_client_weighs_highest_then_our_preference(header, chosen):
    assert negotiate(header) == chosen


@pytest.mark.parametrize(
    ("header", "chosen"),
    [
        ("gzip", "gzip"),
        ("zstd", None),
        ("gzip;q=0", None),
        ("*", "gzip"),
        ("*;q=0", None),
        ("gzip;q=0.5, zstd", "gzip"),
    ],
)
def test_negotiate_among_what_a_caller_offers(header, chosen):
    assert negotiate(header, offered=("gzip",)) == chosen


def test_small_bodies_stay_as_they_are():
    assert compression.compress(b"x" * (compression.MINIMUM_BYTES - 1), "zstd") is None
    assert compression.compress(b"x" * compression.MINIMUM_BYTES, None) is None
    body = b'{"t": [0.0, 0.1]}' * 200
    assert zstd.decompress(compression.compress(body, "zstd")) == body
    assert gzip.decompress(compression.compress(body, "gzip")) == body


def test_a_simulation_is_compressed_in_its_route_not_by_the_middleware(client, monkeypatch):
    # the route's thread inherits the chosen coding, so the middleware sees a body already compressed
    seen: list[int] = []
    original = compression._Response._encode

    async def spy(self, body, more):
        seen.append(len(body))
        return await original(self, body, more)

    monkeypatch.setattr(compression._Response, "_encode", spy)
    response = client.post(
        "/api/scenes/double-pendulum/simulate", json={"initial": {}}, headers={"Accept-Encoding": "zstd"}
    )
    assert response.status_code == 200 and response.headers["content-encoding"] == "zstd"
    assert seen == [] and len(response.json()["t"]) > 100
    derivation = client.get("/api/scenes/double-pendulum/derivation", headers={"Accept-Encoding": "zstd"})
    assert derivation.headers["content-encoding"] == "zstd" and len(seen) == 1  # a plain route: the middleware
    assert derivation.json()["id"] == "double-pendulum"


def test_pages_are_left_to_their_own_precompressed_copies(client):
    page = client.get("/scenes/simple-pendulum", headers={"Accept-Encoding": "zstd"})
    assert page.status_code == 200 and "content-encoding" not in page.headers


@pytest.mark.parametrize(("header", "coding"), [("zstd, gzip", "zstd"), ("gzip", "gzip"), ("gzip;q=0", None)])
def test_the_playground_page_made_per_request_is_compressed_as_the_api_is(client, header, coding):
    page = client.get("/playground", headers={"Accept-Encoding": header})
    assert page.status_code == 200 and page.headers.get("content-encoding") == coding
    plain = client.get("/playground", headers={"Accept-Encoding": "identity"})
    assert "content-encoding" not in plain.headers and page.text == plain.text


@pytest.mark.parametrize(
    ("header", "page", "static"),
    [
        ("gzip", "gzip", "gzip"),
        ("gzip;q=0.5", "gzip", "gzip"),
        ("*", "gzip", "zstd"),
        ("gzip, deflate, br, zstd", "gzip", "zstd"),  # Chromium's, over plain HTTP too
        ("zstd;q=0.5, gzip", "gzip", "gzip"),  # the client's weight first
        ("gzip;q=0", None, None),
        ("*, gzip;q=0", None, "zstd"),
        ("identity", None, None),
    ],
)
@pytest.mark.parametrize("path", ["/scenes/simple-pendulum", "/static/js/derivation.js"])
def test_pages_and_static_files_come_compressed_in_a_coding_the_client_accepts(client, path, header, page, static):
    expected = page if path.startswith("/scenes") else static
    response = client.get(path, headers={"Accept-Encoding": header})
    assert response.status_code == 200 and response.headers.get("content-encoding") == expected
    assert response.headers.get("vary") == "Accept-Encoding" or not expected
    plain = client.get(path, headers={"Accept-Encoding": "identity"})
    assert response.content == plain.content  # the client decoded the compressed copy to the same bytes


@pytest.mark.parametrize("coding", ["zstd", "gzip"])
def test_a_vendor_library_is_sent_from_its_copy_compressed_at_set_up(client, coding):
    # the copies precompress writes are the ones served: decoded, the library byte for byte
    vendor = templating.STATIC_DIR / "vendor"
    if not (vendor / "katex" / "katex.min.js.zst").is_file():
        pytest.fail("static/vendor has no zstd copies: scripts/setup.sh runs python -m app.web.precompress")
    response = client.get("/static/vendor/katex/katex.min.js", headers={"Accept-Encoding": coding})
    assert response.headers["content-encoding"] == coding
    # the library's own type: a browser runs no script sent as application/zstd
    assert response.headers["content-type"].startswith("text/javascript")
    suffix = compression.STATIC[coding][0]
    copy = (vendor / "katex" / ("katex.min.js" + suffix)).read_bytes()
    assert int(response.headers["content-length"]) == len(copy)
    assert response.content == (vendor / "katex" / "katex.min.js").read_bytes()


def test_precompress_writes_a_fresh_copy_and_leaves_a_fresh_one_alone(tmp_path):
    library = tmp_path / "lib.js"
    library.write_bytes(b"export const x = 1;\n" * 2000)
    assert precompress(tmp_path) == [tmp_path / "lib.js.zst"]
    assert zstd.decompress((tmp_path / "lib.js.zst").read_bytes()) == library.read_bytes()
    assert precompress(tmp_path) == []  # up to date: nothing written again
    assert len((tmp_path / "lib.js.zst").read_bytes()) < len(library.read_bytes()) / 20


async def _streamed(scope, receive, send):
    chunks = [b'{"chunk": %d, "pad": "%s"}\n' % (i, b"ab" * 2000) for i in range(5)]

    async def body():
        for chunk in chunks:
            yield chunk

    await StreamingResponse(body(), media_type="application/x-ndjson")(scope, receive, send)


async def _small(scope, receive, send):
    await Response(b'{"ok": true}', media_type="application/json")(scope, receive, send)


@pytest.mark.parametrize("coding", ["zstd", "gzip"])
def test_streamed_and_small_api_responses(coding):
    # no ``with``: these bare apps have no lifespan
    response = TestClient(ApiCompression(_streamed)).get("/api/stream", headers={"Accept-Encoding": coding})
    assert response.headers["content-encoding"] == coding and "content-length" not in response.headers
    lines = response.content.splitlines()
    assert len(lines) == 5 and lines[4].startswith(b'{"chunk": 4')
    client = TestClient(ApiCompression(_small))
    small = client.get("/api/small", headers={"Accept-Encoding": coding})
    outside = client.get("/elsewhere", headers={"Accept-Encoding": coding})
    assert small.content == b'{"ok": true}' and "content-encoding" not in small.headers
    assert outside.content == small.content and "content-encoding" not in outside.headers


PAD = b"ab" * 2000


def _served(app, headers: dict[str, str], path: str = "/api/x") -> list[dict]:
    """The ASGI messages ``app`` sends through the middleware for a GET of ``path``."""
    scope = {"type": "http", "method": "GET", "path": path, "query_string": b"",
             "headers": [(k.lower().encode(), v.encode()) for k, v in headers.items()]}  # fmt: skip
    sent: list[dict] = []

    requested = []

    async def receive():
        if requested:  # the request was read: wait, like a client that stays connected
            await anyio.sleep_forever()
        requested.append(True)
        return {"type": "http.request", "body": b"", "more_body": False}

    async def send(message):
        sent.append(message)

    anyio.run(ApiCompression(app), scope, receive, send)
    return sent


def _decoder(coding):
    if coding == "gzip":
        d = zlib.decompressobj(16 + zlib.MAX_WBITS)
        return d.decompress
    return zstd.ZstdDecompressor().decompress


@pytest.mark.parametrize("coding", ["zstd", "gzip"])
def test_each_streamed_chunk_reaches_the_client_readable_at_once(coding):
    sent = _served(_streamed, {"Accept-Encoding": coding})
    start, bodies = sent[0], [m for m in sent if m["type"] == "http.response.body"]
    headers = dict(start["headers"])
    assert headers[b"content-encoding"] == coding.encode() and headers[b"vary"] == b"Accept-Encoding"
    decode = _decoder(coding)
    # every chunk decodes, on its own arrival, to the whole line the route sent with it
    lines = [decode(m["body"]) for m in bodies if m["body"]]
    assert [line[:12] for line in lines[:5]] == [b'{"chunk": %d,' % i for i in range(5)]
    assert all(len(m["body"]) < len(PAD) / 10 for m in bodies)


async def _large(scope, receive, send, headers=None, status=200, media="application/json"):
    await Response(b'{"pad": "%s"}' % PAD, status_code=status, media_type=media, headers=headers)(scope, receive, send)


@pytest.mark.parametrize(
    "app",
    [
        lambda s, r, w: _large(s, r, w, headers={"Content-Encoding": "br"}),  # encoded by the route
        lambda s, r, w: _large(s, r, w, status=206),  # a range of the body
        lambda s, r, w: _large(s, r, w, media="image/png"),
        lambda s, r, w: _large(s, r, w, media="text/event-stream"),
    ],
)
def test_what_is_encoded_already_or_streams_events_passes_untouched(app):
    sent = _served(app, {"Accept-Encoding": "gzip, zstd"})
    body = b"".join(m.get("body", b"") for m in sent if m["type"] == "http.response.body")
    assert body == b'{"pad": "%s"}' % PAD and dict(sent[0]["headers"]).get(b"content-encoding") in (None, b"br")


@pytest.mark.parametrize(
    ("header", "coding"), [("gzip;q=0, zstd;q=0", None), ("identity", None), ("gzip;q=0.5", "gzip")]
)
def test_a_large_api_body_honours_the_weights(header, coding):
    sent = _served(_large, {"Accept-Encoding": header})
    headers = dict(sent[0]["headers"])
    assert headers.get(b"content-encoding") == (coding.encode() if coding else None)
    assert headers[b"vary"] == b"Accept-Encoding"  # another client's coding would have compressed it
    body = sent[1]["body"]
    assert int(headers[b"content-length"]) == len(body)
    assert (_decoder(coding)(body) if coding else body) == b'{"pad": "%s"}' % PAD
