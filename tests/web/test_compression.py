"""Content-coding negotiation and the compression of /api responses (app/web/compression.py)."""

from __future__ import annotations

import gzip

import pytest
from fastapi.testclient import TestClient
from starlette.responses import Response, StreamingResponse

from app.web import compression
from app.web.compression import ApiCompression, negotiate, zstd


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
        ("identity", None),
        ("br", None),
        ("", None),
        (",,;", None),
    ],
)
def test_negotiate_picks_our_preference_among_what_the_client_accepts(header, chosen):
    assert negotiate(header) == chosen


def test_small_bodies_stay_as_they_are():
    assert compression.compress(b"x" * (compression.MINIMUM_BYTES - 1), "zstd") is None
    assert compression.compress(b"x" * compression.MINIMUM_BYTES, None) is None
    body = b'{"t": [0.0, 0.1]}' * 200
    assert zstd.decompress(compression.compress(body, "zstd")) == body
    assert gzip.decompress(compression.compress(body, "gzip")) == body


def test_a_simulation_is_compressed_in_its_route_not_by_the_middleware(client, monkeypatch):
    # the route's thread inherits the chosen coding, so the middleware sees a body already compressed
    seen: list[int] = []
    original = compression.ZstdResponder.apply_compression

    async def spy(self, body, *, more_body):
        seen.append(len(body))
        return await original(self, body, more_body=more_body)

    monkeypatch.setattr(compression.ZstdResponder, "apply_compression", spy)
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
