"""Slow clients: a deadline on request headers, and the server's command-line options.

uvicorn closes idle keep-alive connections (``--timeout-keep-alive``) and
refuses connections beyond ``--limit-concurrency`` with a 503, but it waits for
ever for the headers of a request that arrives a byte at a time, so a few
hundred half-sent requests hold their sockets (and, at the file-descriptor
limit, keep everyone else out).  ``HeaderDeadline`` (``--http
app.web.slow_clients:HeaderDeadline``) closes a connection whose request
headers are not complete ``header_seconds`` after its first byte (or after it
opened).  Bodies have their own deadline in app/web/limits.py.

The uvicorn options that select it (and the keep-alive and connection cap) are
printed by ``python -m app.web.server_options``.
"""

from __future__ import annotations

import asyncio
from typing import Any

from uvicorn.protocols.http.auto import AutoHTTPProtocol

from app.settings import settings


class HeaderDeadline(AutoHTTPProtocol):  # type: ignore[misc, valid-type]
    """uvicorn's HTTP protocol, closing a connection whose request headers arrive too slowly."""

    seconds: float | None = None  # None: settings().header_seconds

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._deadline: asyncio.TimerHandle | None = None
        self._waiting_cycle: Any = None

    def _arm(self) -> None:
        """Start the clock for the headers of the next request (the current cycle is the previous one)."""
        if self._deadline is None:
            self._waiting_cycle = self.cycle
            self._deadline = self.loop.call_later(self.seconds or settings().header_seconds, self._expired)

    def _expired(self) -> None:
        self._deadline = None
        if self.cycle is self._waiting_cycle and not self.transport.is_closing():
            self.transport.close()  # no new request began: its headers never came

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        super().connection_made(transport)
        self._arm()

    def data_received(self, data: bytes) -> None:
        if self.cycle is None or self.cycle.response_complete:
            self._arm()  # bytes of a new request: its headers have header_seconds to arrive
        super().data_received(data)

    def connection_lost(self, exc: Exception | None) -> None:
        if self._deadline is not None:
            self._deadline.cancel()
            self._deadline = None
        super().connection_lost(exc)
