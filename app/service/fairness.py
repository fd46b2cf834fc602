"""Fair shares of the worker pool between clients.

A classroom shares one network address, so the unit of fairness is a session
the server issues (a signed cookie), not an address.  Admission rules for an
expensive job (a derivation or simulation of a user system):

1. one job in flight per client: a client whose job is still running gets a
   429 with ``Retry-After`` (a request without a session cookie is keyed on
   its address, so cookie-less scripts share one slot per address);
2. at most ``per_address`` jobs in flight from one address, so one machine
   that mints many sessions cannot take the whole pool;
3. at most ``capacity`` jobs in flight overall (running plus queued), beyond
   which a 503 with ``Retry-After`` says the server is busy;
4. sessions are minted at most ``mint_per_minute`` per address.

Jobs are time-limited by the worker pool and queued first come, first served;
since each client has at most one job waiting, the queue serves clients in
turn and a few abusive clients hold at most a few slots.  Answers are cached,
and a request identical to one already running waits for that job without a
ticket of its own (app/service/user_systems.py), so a class opening one shared
link costs one job.
"""

from __future__ import annotations

import hashlib
import hmac
import math
import os
import secrets
import threading
import time
from collections import deque
from dataclasses import dataclass, field
from pathlib import Path

from app.errors import OverCapacity
from app.service.cache import cache_dir
from app.settings import settings

COOKIE = "lagrange_session"
COOKIE_MAX_AGE = 30 * 24 * 3600


class Busy(OverCapacity):
    """A job refused for fairness: this client's turn (``whole_server`` false) or a full server, with a ``retry_after``."""


def _secret(configured: str | None) -> bytes:
    """The key that signs sessions: the configured one, else a file shared by the server's processes."""
    if configured:
        return configured.encode()
    path = Path(cache_dir()) / "session-secret"
    try:
        return path.read_bytes()
    except OSError:
        pass
    key = secrets.token_bytes(32)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        descriptor = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
        with os.fdopen(descriptor, "wb") as handle:
            handle.write(key)
    except FileExistsError:
        return path.read_bytes()  # another process won the race
    except OSError:
        pass  # a read-only disk: sessions last as long as this process
    return key


@dataclass
class Ticket:
    """An admitted job; ``release`` frees its slot (idempotent)."""

    owner: Fairness
    client: str
    address: str
    started: float = field(default_factory=time.monotonic)
    released: bool = False

    def release(self) -> None:
        self.owner._release(self)


class Fairness:
    def __init__(
        self,
        capacity: int,
        workers: int = 1,
        per_address: int | None = None,
        mint_per_minute: int = 120,
        secret: str | None = None,
    ):
        self.capacity = capacity
        self.workers = workers
        self.per_address = per_address or max(1, capacity // 2)
        self.mint_per_minute = mint_per_minute
        self._key = _secret(secret or settings().session_secret)
        self._lock = threading.Lock()
        self._running: dict[str, Ticket] = {}
        self._per_address: dict[str, int] = {}
        self._minted: dict[str, deque[float]] = {}
        self._mean_seconds = 2.0  # a running mean of job durations, for Retry-After

    # sessions -------------------------------------------------------------------------------
    def _sign(self, session: str) -> str:
        return hmac.new(self._key, session.encode(), hashlib.sha256).hexdigest()[:24]

    def verify(self, token: str | None) -> str | None:
        """The session id of a valid cookie value, else None (a malformed value is simply not a session)."""
        if not isinstance(token, str) or not token or len(token) > 100 or not token.isascii() or "." not in token:
            return None
        session, _, signature = token.partition(".")
        return session if hmac.compare_digest(self._sign(session), signature) else None

    def mint(self, address: str) -> str | None:
        """A new signed cookie value, or None when this address minted too many this minute."""
        now = time.monotonic()
        with self._lock:
            recent = self._minted.setdefault(address, deque())
            while recent and now - recent[0] > 60:
                recent.popleft()
            if len(recent) >= self.mint_per_minute:
                return None
            recent.append(now)
            if len(self._minted) > 10000:  # forget idle addresses
                for stale in [a for a, q in self._minted.items() if not q or now - q[-1] > 60]:
                    del self._minted[stale]
        session = secrets.token_urlsafe(12)
        return f"{session}.{self._sign(session)}"

    # admission ------------------------------------------------------------------------------
    def _retry_after(self, jobs_ahead: int) -> int:
        """Seconds until a slot is likely free: the mean job time for each job ahead per worker."""
        return max(1, min(30, math.ceil(self._mean_seconds * max(jobs_ahead, 1) / self.workers)))

    def admit(self, client: str, address: str) -> Ticket:
        """Admit one job for ``client`` (a session id or ``address:...``) or raise Busy."""
        with self._lock:
            if client in self._running:
                raise Busy(
                    "you already have a derivation or simulation running; wait for it to finish",
                    self._retry_after(self.workers),
                )
            if self._per_address.get(address, 0) >= self.per_address:
                raise Busy(
                    f"{self.per_address} jobs from your network address are already running; try again shortly",
                    self._retry_after(1),
                )
            if len(self._running) >= self.capacity:
                raise Busy(
                    "the server is busy with other users' systems; try again shortly",
                    self._retry_after(len(self._running) - self.capacity + 1),
                    whole_server=True,
                )
            ticket = Ticket(self, client, address)
            self._running[client] = ticket
            self._per_address[address] = self._per_address.get(address, 0) + 1
            return ticket

    def _release(self, ticket: Ticket) -> None:
        with self._lock:
            if ticket.released:
                return
            ticket.released = True
            if self._running.get(ticket.client) is ticket:
                del self._running[ticket.client]
            left = self._per_address.get(ticket.address, 1) - 1
            if left > 0:
                self._per_address[ticket.address] = left
            else:
                self._per_address.pop(ticket.address, None)
            elapsed = time.monotonic() - ticket.started
            self._mean_seconds = 0.8 * self._mean_seconds + 0.2 * elapsed

    @property
    def in_flight(self) -> int:
        with self._lock:
            return len(self._running)
