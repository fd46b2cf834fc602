"""Slow clients: per-address caps on connections and unread responses, deadlines on headers and on writes.

uvicorn closes idle keep-alive connections (``--timeout-keep-alive``) and refuses connections beyond
``--limit-concurrency`` with a 503, but it waits for ever for the headers of a request that arrives a
byte at a time, and for a client that never reads its answer; and plain ``uvicorn app.main:app`` has
none of the options scripts/serve.sh gives it.  So a few hundred half-sent requests (slowloris), or a
few hundred requests for plotly.min.js that are never read, held every socket (and the concurrency
cap) from everyone else.  A request never reaches an ASGI middleware before its headers are complete,
and a middleware cannot close a socket, so these limits live on uvicorn's HTTP protocol classes
(``install``, run when the app is imported, whichever way it is served):

* at most ``settings().connections_per_address`` open connections from one address in a process:
  the next one gets a 503 and is closed at once;
* a connection whose request headers are not complete ``header_seconds`` after its first byte (or
  after it opened) is closed;
* an answer the client does not read: uvicorn stops writing when the socket's buffer is full
  ("paused"); a connection paused for more than ``write_seconds`` at a stretch (or for six times that
  in all) is aborted, and at most ``slow_per_address`` connections of one address may be paused at
  once (the one that pauses beyond that is aborted).

A connection from a trusted reverse proxy (app/web/http/address.py) speaks for many clients, so the
per-address caps do not apply to it.  Bodies have their own deadline in app/web/api/limits.py.
``HeaderDeadline`` (``--http app.web.http.slow_clients:HeaderDeadline``) is uvicorn's protocol with all of
this, for the scripts' command line (app/web/http/server_options.py).
"""

from __future__ import annotations

import asyncio
from collections import Counter
from typing import Any

from uvicorn.protocols.http.auto import AutoHTTPProtocol
from uvicorn.protocols.http.h11_impl import H11Protocol

from app.settings import settings


def _httptools() -> Any:
    try:
        from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol
    except ImportError:  # httptools not installed: uvicorn uses h11
        return None
    return HttpToolsProtocol


TOTAL_PAUSE_FACTOR = 6  # a connection paused for this many write deadlines in all is aborted
REFUSAL = (
    b"HTTP/1.1 503 Service Unavailable\r\ncontent-type: text/plain; charset=utf-8\r\ncontent-length: 46\r\n"
    b"retry-after: 5\r\nconnection: close\r\n\r\ntoo many connections from your network address"
)


class Guard:
    """This process's count of open and of paused connections per address, and the limits (tests may change them)."""

    def __init__(self) -> None:
        self.open: Counter[str] = Counter()
        self.paused: Counter[str] = Counter()
        self.per_address: int | None = None
        self.slow_per_address: int | None = None
        self.header_seconds: float | None = None
        self.write_seconds: float | None = None

    def limit(self, name: str) -> Any:
        value = getattr(self, name)
        return (
            value
            if value is not None
            else getattr(settings(), name if name != "per_address" else "connections_per_address")
        )

    def drop(self, counter: Counter[str], address: str) -> None:
        counter[address] -= 1
        if counter[address] <= 0:
            del counter[address]


GUARD = Guard()


def _peer(transport: asyncio.BaseTransport) -> str | None:
    """The address the per-address caps count, or None for a trusted proxy's connection (or no address)."""
    peer = transport.get_extra_info("peername")
    address = peer[0] if isinstance(peer, tuple) and peer else None
    config = settings()
    if address is not None and config.proxy_header.strip():
        if address in {a.strip() for a in config.trusted_proxies.split(",")}:
            return None
    return address


def _arm(protocol: Any) -> None:
    """Start the clock for the headers of the next request (the current cycle is the previous one)."""
    if getattr(protocol, "_lg_header_timer", None) is None:
        protocol._lg_waiting_cycle = protocol.cycle
        seconds = getattr(protocol, "seconds", None) or GUARD.limit("header_seconds")
        protocol._lg_header_timer = protocol.loop.call_later(seconds, _headers_expired, protocol)


def _headers_expired(protocol: Any) -> None:
    protocol._lg_header_timer = None
    if protocol.cycle is protocol._lg_waiting_cycle and not protocol.transport.is_closing():
        protocol.transport.close()  # no new request began: its headers never came


def _write_expired(protocol: Any) -> None:
    protocol._lg_write_timer = None
    protocol.transport.abort()  # close() would wait for the unread buffer to drain: it never would


def _patch(cls: Any) -> None:
    if getattr(cls, "_lg_guarded", False):
        return
    made, received, lost = cls.connection_made, cls.data_received, cls.connection_lost
    paused, resumed = cls.pause_writing, cls.resume_writing

    def connection_made(self: Any, transport: asyncio.Transport) -> None:
        made(self, transport)
        self._lg_header_timer = self._lg_write_timer = None
        self._lg_paused_at = None
        self._lg_paused_total = 0.0
        self._lg_address = _peer(transport)
        if self._lg_address is not None:
            if GUARD.open[self._lg_address] >= GUARD.limit("per_address"):
                # Refused and never counted: the count is of connections served, so it never
                # exceeds the cap even while a refused socket's close is still under way.
                self._lg_address = None
                transport.write(REFUSAL)
                transport.close()
                return
            GUARD.open[self._lg_address] += 1
        _arm(self)

    def data_received(self: Any, data: bytes) -> None:
        if self.cycle is None or self.cycle.response_complete:
            _arm(self)  # bytes of a new request: its headers have header_seconds to arrive
        received(self, data)

    def connection_lost(self: Any, exc: Exception | None) -> None:
        for timer in ("_lg_header_timer", "_lg_write_timer"):
            handle = getattr(self, timer, None)
            if handle is not None:
                handle.cancel()
                setattr(self, timer, None)
        address = getattr(self, "_lg_address", None)
        if address is not None:
            GUARD.drop(GUARD.open, address)
            if getattr(self, "_lg_paused_at", None) is not None:
                GUARD.drop(GUARD.paused, address)
            self._lg_address = None
        lost(self, exc)

    def pause_writing(self: Any) -> None:
        paused(self)
        if getattr(self, "_lg_paused_at", None) is not None or self.transport.is_closing():
            return
        self._lg_paused_at = self.loop.time()
        seconds = GUARD.limit("write_seconds")
        left = max(0.0, min(seconds, TOTAL_PAUSE_FACTOR * seconds - self._lg_paused_total))
        self._lg_write_timer = self.loop.call_later(left, _write_expired, self)
        address = self._lg_address
        if address is not None:
            GUARD.paused[address] += 1
            if GUARD.paused[address] > GUARD.limit("slow_per_address"):
                self.transport.abort()

    def resume_writing(self: Any) -> None:
        resumed(self)
        if getattr(self, "_lg_paused_at", None) is None:
            return
        self._lg_paused_total += self.loop.time() - self._lg_paused_at
        self._lg_paused_at = None
        if self._lg_write_timer is not None:
            self._lg_write_timer.cancel()
            self._lg_write_timer = None
        if self._lg_address is not None:
            GUARD.drop(GUARD.paused, self._lg_address)

    cls.connection_made = connection_made
    cls.data_received = data_received
    cls.connection_lost = connection_lost
    cls.pause_writing = pause_writing
    cls.resume_writing = resume_writing
    cls._lg_guarded = True


def install() -> None:
    """Put the caps and deadlines on uvicorn's HTTP protocols (idempotent)."""
    for cls in (H11Protocol, _httptools()):
        if cls is not None:
            _patch(cls)


install()


class HeaderDeadline(AutoHTTPProtocol):  # type: ignore[misc, valid-type]
    """uvicorn's HTTP protocol with the caps and deadlines above; ``seconds`` overrides the header deadline."""

    seconds: float | None = None  # None: settings().header_seconds
