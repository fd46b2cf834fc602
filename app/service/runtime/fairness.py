"""Fair shares of the worker pool between clients.

A classroom shares one network address, so the unit of fairness is a session
the server issues (a signed cookie), not an address.  Sessions are free to
issue: every request without a valid cookie gets one.  Who a request counts as
(``Fairness.key``):

* a request that presents a session's cookie counts as that session, for the
  first ``mint_per_minute`` sessions an address presents each minute (after
  that, further sessions of the address share one key, ``many:<address>``, so
  an address that hoards cookies gains nothing by it);
* a request without one (a first visit, or a script that drops cookies and so
  floods with a fresh session per request) counts as the address's newcomers,
  ``new:<address>``: one shared weight for all of them.

Admission rules for an expensive job (a derivation or simulation of a user
system, a student's check):

1. one job in flight per session: a session whose job is still running gets a
   429 with ``Retry-After``;
2. at most ``per_address`` jobs in flight from one address (the shared keys
   included), so one machine cannot take the whole pool; but a session that
   has used less worker time lately than the key
   of some job the address has in flight is admitted beyond it (up to twice
   the cap), after taking the place of the heaviest waiting job when there is
   one: a well-behaved student behind a flooding neighbour's address is not
   refused for the neighbour's share;
   a class's checks come with the "address" ``class:<id>`` and each student's
   own key: the class has ``class_check_slots`` (a setting) in flight in place
   of a network's share, so a lecture hall behind one address is not refused
   for sharing it; those slots come beside ``capacity`` (the classes' checks
   in flight are not counted against the other users' capacity, and all
   together stop at ``capacity + class_check_slots``);
3. at most ``capacity`` jobs in flight overall (running plus queued), beyond
   which a newcomer that has used less takes the place of the heaviest job
   still waiting, or else a 503 with ``Retry-After`` says the server is busy;
4. a key whose jobs keep running out of time or memory backs off: after two
   such failures in a row it gets a 429 for 5 s, doubling with each further one
   (at most 5 minutes); an address backs off, for its shared keys only, once
   ``per_address`` + 1 of its jobs failed so in a row (a student's own session
   is held back only by its own failures).

Admitted jobs wait for one of ``workers`` run slots in this queue, never in the
pool's.  A free slot goes to the waiting job whose address, then whose key, has
used the least worker time lately (decayed with a half-life of ``HALF_LIFE`` s,
the running jobs' time included): weighted fair queueing across addresses and,
within an address, across sessions, the newcomers counting as one.  A session
that has to wait while a heavier shared key's job runs takes that job's slot:
the job is stopped (``GAVE_WAY``), so a student never waits behind a flood of
cookie-less requests for more than their own job.  So a flood
from one address raises the wait of the others by at most the jobs already
running.  A job waits at most ``queue_seconds`` (its deadline; then a 503 with
``Retry-After``), and a job whose clients all went away leaves the queue
(app/service/users/user_systems.py).

Answers are cached, and a request identical to one already running waits for
that job without a ticket of its own (app/service/users/user_systems.py), so a class
opening one shared link costs one job.
"""

from __future__ import annotations

import asyncio
import hashlib
import hmac
import math
import os
import secrets
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from app.errors import OverCapacity
from app.limits import BACKOFF_SECONDS, HOLD_SECONDS
from app.limits import RATE_WINDOW_SECONDS as NEW_SESSION_SECONDS
from app.service.runtime.cache import cache_dir
from app.settings import settings

COOKIE = "lagrange_session"
COOKIE_MAX_AGE = 30 * 24 * 3600
HALF_LIFE = 120.0  # seconds over which a client's used worker time halves
CLIENT_STRIKES = 2  # failures in a row before a client backs off
BACKOFF_MAX = 300.0
STRIKES = ("timeout", "memory", "crashed")  # outcomes that count against a client
SHARED = ("new:", "many:", "address:")  # keys that many requests share (no one-at-a-time rule for them)
CLASS = "class:"  # the "address" of a class's checks: its students share the class's budget, not a network's
GAVE_WAY = (
    "your job gave way to a student's session: requests without the session cookie run only while no session "
    "waits; send the cookie this answer sets (a browser does) and try again"
)


def shared(key: str) -> bool:
    """Whether ``key`` stands for many requests at once (an address's newcomers), not one session."""
    return key.startswith(SHARED)


class Busy(OverCapacity):
    """A job refused for fairness: this client's turn (``whole_server`` false) or a full server, with a ``retry_after``.

    ``hold`` is how long the answer should wait before it is sent (see ``HOLD_SECONDS``)."""

    hold: float = 0.0


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


@dataclass(eq=False)
class Ticket:
    """An admitted job; ``release`` frees its place (idempotent), saying how the job ended."""

    owner: Fairness
    client: str
    address: str
    started: float = field(default_factory=time.monotonic)
    ran_at: float | None = None  # when it got a run slot
    released: bool = False
    wake: tuple[asyncio.AbstractEventLoop, asyncio.Future] | None = None
    job: Any = None  # the running job's future (set by the service), which a shared key's job may have to give up

    @property
    def running(self) -> bool:
        return self.ran_at is not None

    def release(self, outcome: str = "done") -> None:
        self.owner._release(self, outcome)


class _Usage:
    """Worker seconds per key, decaying with a half-life."""

    def __init__(self) -> None:
        self._values: dict[str, tuple[float, float]] = {}

    def get(self, key: str, now: float) -> float:
        value, stamp = self._values.get(key, (0.0, now))
        return value * 0.5 ** ((now - stamp) / HALF_LIFE)

    def add(self, key: str, seconds: float, now: float) -> None:
        self._values[key] = (self.get(key, now) + seconds, now)
        if len(self._values) > 20000:  # forget the ones that decayed to nothing
            for stale in [k for k in self._values if self.get(k, now) < 0.01]:
                del self._values[stale]


class Fairness:
    def __init__(
        self,
        capacity: int,
        workers: int = 1,
        per_address: int | None = None,
        mint_per_minute: int = 120,
        secret: str | None = None,
        queue_seconds: float | None = None,
    ):
        self.capacity = capacity
        self.workers = workers
        self.per_address = per_address or max(1, capacity // 2)
        self.class_slots = settings().class_check_slots
        self.mint_per_minute = mint_per_minute
        self.queue_seconds = queue_seconds or settings().queue_seconds
        self._waiting: list[Ticket] = []
        self._slots_taken = 0
        self._usage = _Usage()
        self._strikes: dict[str, tuple[int, float]] = {}  # key -> (failures in a row, backing off until)
        self._key = _secret(secret or settings().session_secret)
        self._lock = threading.Lock()
        self._in_flight: set[Ticket] = set()  # admitted and not released: running or waiting
        self._per_client: dict[str, int] = {}
        self._per_address: dict[str, int] = {}
        self._presented: dict[str, dict[str, float]] = {}  # address -> its sessions seen this minute -> first seen
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

    def mint(self, address: str = "") -> str:
        """A new signed cookie value: sessions cost nothing to issue (what they count as is ``key``'s business)."""
        session = secrets.token_urlsafe(12)
        return f"{session}.{self._sign(session)}"

    def key(self, session: str | None, address: str) -> str:
        """Who a request counts as: its session while the address presents few enough, else a shared key."""
        if session is None:
            return f"new:{address}"
        now = time.monotonic()
        with self._lock:
            seen = self._presented.setdefault(address, {})
            if session in seen:
                seen[session] = now
                return f"session:{session}"
            for stale in [s for s, t in seen.items() if now - t > NEW_SESSION_SECONDS]:
                del seen[stale]
            if len(seen) >= self.mint_per_minute:
                return f"many:{address}"
            seen[session] = now
            if len(self._presented) > 10000:  # forget idle addresses
                for idle in [a for a, q in self._presented.items() if not q or now - max(q.values()) > 60]:
                    del self._presented[idle]
            return f"session:{session}"

    # admission ------------------------------------------------------------------------------
    def _retry_after(self, jobs_ahead: int) -> int:
        """Seconds until a slot is likely free: the mean job time for each job ahead per worker."""
        return max(1, min(30, math.ceil(self._mean_seconds * max(jobs_ahead, 1) / self.workers)))

    def _backing_off(self, key: str, threshold: int, now: float) -> float:
        count, until = self._strikes.get(key, (0, 0.0))
        return until - now if count >= threshold and until > now else 0.0

    def _weight(self, ticket: Ticket, now: float) -> tuple[float, float, float]:
        """Who goes first: least recent worker time of the address, then of the client, then arrival."""
        live = {ticket.address: 0.0, ticket.client: 0.0}
        for other in self._in_flight:
            if other.running:
                for key in (other.address, other.client):
                    if key in live:
                        live[key] += now - (other.ran_at or now)
        return (
            self._usage.get(ticket.address, now) + live[ticket.address],
            self._usage.get(ticket.client, now) + live[ticket.client],
            ticket.started,
        )

    def _make_room(self, newcomer: Ticket, among: list[Ticket], now: float) -> bool:
        """Give the newcomer the place of the heaviest waiting job in ``among`` if that one has used more."""
        if not among:
            return False
        mine = self._weight(newcomer, now)
        heaviest = max(among, key=lambda t: self._weight(t, now))
        if self._weight(heaviest, now)[:2] <= mine[:2]:
            return False
        self._drop(
            heaviest,
            Busy(
                "your place in the queue went to a session that has used the server less lately; try again shortly",
                self._retry_after(1),
            ),
        )
        return True

    def _lighter_than_the_address(self, newcomer: Ticket, now: float) -> bool:
        """Whether the newcomer's key has used less than the key of some job its address has in flight."""
        mine = self._weight(newcomer, now)[1]
        return any(mine < self._weight(t, now)[1] for t in self._in_flight if t.address == newcomer.address)

    def admit(self, client: str, address: str) -> Ticket:
        """Admit one job for ``client`` (``Fairness.key``: a session, or an address's shared key) or raise Busy.

        A refusal of a shared key is held (``Busy.hold``) for ``HOLD_SECONDS``, at most its ``retry_after``."""
        try:
            return self._admit(client, address)
        except Busy as refused:
            if shared(client):
                refused.hold = min(HOLD_SECONDS, float(refused.retry_after))
            raise

    def _admit(self, client: str, address: str) -> Ticket:
        now = time.monotonic()
        many = shared(client)
        with self._lock:
            # a session backs off for its own failures, an address's shared keys for the address's
            wait = (
                self._backing_off(address, self.per_address + 1, now)
                if many
                else self._backing_off(client, CLIENT_STRIKES, now)
            )
            if wait:
                raise Busy(
                    "your recent jobs ran out of time or memory; wait before sending more "
                    "(smaller systems or shorter simulations fit the limits)",
                    max(1, math.ceil(wait)),
                )
            if not many and self._per_client.get(client):
                raise Busy(
                    "you already have a derivation or simulation running; wait for it to finish",
                    self._retry_after(self.workers),
                )
            ticket = Ticket(self, client, address)
            from_address = self._per_address.get(address, 0)
            if address.startswith(CLASS):
                # a class's students are people, each with their own key (one check at a time, above): the class
                # has a budget of its own, sized for a lecture, in place of a network's share and beyond the
                # server's capacity; its checks still take their fair turn for a worker
                if from_address >= self.class_slots:
                    raise Busy(
                        f"{self.class_slots} checks of your class are already running; try again shortly",
                        self._retry_after(1),
                    )
            elif (
                from_address >= self.per_address
                and not self._make_room(ticket, [t for t in self._waiting if t.address == address], now)
                and (many or from_address >= 2 * self.per_address or not self._lighter_than_the_address(ticket, now))
            ):
                raise Busy(
                    f"{self.per_address} jobs from your network address are already running; try again shortly",
                    self._retry_after(1),
                )
            # classes' checks have their slots beside the capacity: they do not crowd out the other users
            classes = sum(n for key, n in self._per_address.items() if key.startswith(CLASS))
            crowd, room = (
                (len(self._in_flight), self.capacity + self.class_slots) if address.startswith(CLASS)
                else (len(self._in_flight) - classes, self.capacity)
            )
            if crowd >= room and not self._make_room(ticket, list(self._waiting), now):
                raise Busy(
                    "the server is busy with other users' systems; try again shortly",
                    self._retry_after(len(self._in_flight) - self.capacity + 1),
                    whole_server=True,
                )
            self._in_flight.add(ticket)
            self._per_client[client] = self._per_client.get(client, 0) + 1
            self._per_address[address] = self._per_address.get(address, 0) + 1
            return ticket

    async def turn(self, ticket: Ticket) -> None:
        """Wait until the ticket's job may run (a free worker), or raise Busy past ``queue_seconds``.

        Cancelling the wait (the client went away) gives up the ticket."""
        loop = asyncio.get_running_loop()
        granted: asyncio.Future = loop.create_future()
        with self._lock:
            if ticket.released:
                raise Busy("the server is busy with other users' systems; try again shortly", 1, whole_server=True)
            ticket.wake = (loop, granted)
            self._waiting.append(ticket)
            self._dispatch()
            victim = None if ticket.running or shared(ticket.client) else self._preempted_for(ticket)
        if victim is not None:
            victim.cancel()  # outside the lock: its done callback releases its ticket
        try:
            await asyncio.wait_for(asyncio.shield(granted), self.queue_seconds)
        except TimeoutError:
            with self._lock:
                if ticket.running:
                    return  # a slot came at the last moment
                ahead = len(self._waiting)
            ticket.release("expired")
            raise Busy(
                f"no worker became free within {self.queue_seconds:g} s; the server is busy, try again shortly",
                self._retry_after(ahead),
                whole_server=True,
            ) from None
        except BaseException:  # cancelled (the client left) or dropped from the queue
            ticket.release("cancelled")
            raise

    def _preempted_for(self, ticket: Ticket) -> Any:
        """The heaviest running job of a shared key heavier than ``ticket``'s session, marked to give way (lock held).

        A session never waits behind an address's newcomers: their job is cancelled (its worker is killed and
        replaced in a fraction of a second), its requests are answered with ``GAVE_WAY``, and the freed slot
        goes to the lightest waiting job."""
        now = time.monotonic()
        mine = self._weight(ticket, now)[:2]
        running = [
            t for t in self._in_flight
            if t.running and t.job is not None and shared(t.client) and self._weight(t, now)[:2] > mine
            and not getattr(t.job, "gave_way", None)
        ]  # fmt: skip
        if not running:
            return None
        victim = max(running, key=lambda t: self._weight(t, now)).job
        victim.gave_way = GAVE_WAY
        return victim

    def _dispatch(self) -> None:
        """Give free run slots to the lightest waiting jobs (called with the lock held)."""
        now = time.monotonic()
        while self._waiting and self._slots_taken < self.workers:
            chosen = min(self._waiting, key=lambda t: self._weight(t, now))
            self._waiting.remove(chosen)
            chosen.ran_at = now
            self._slots_taken += 1
            self._wake(chosen, None)

    @staticmethod
    def _wake(ticket: Ticket, error: BaseException | None) -> None:
        if ticket.wake is None:
            return
        loop, granted = ticket.wake

        def resolve() -> None:
            if not granted.done():
                if error is None:
                    granted.set_result(None)
                else:
                    granted.set_exception(error)

        loop.call_soon_threadsafe(resolve)

    def _drop(self, ticket: Ticket, error: Busy) -> None:
        """Take a waiting job out of the queue; its waiter gets ``error`` (called with the lock held)."""
        self._waiting.remove(ticket)
        self._forget(ticket)
        self._wake(ticket, error)

    def _forget(self, ticket: Ticket) -> None:
        ticket.released = True
        if ticket in self._in_flight:
            self._in_flight.discard(ticket)
            for counts, key in ((self._per_client, ticket.client), (self._per_address, ticket.address)):
                left = counts.get(key, 1) - 1
                if left > 0:
                    counts[key] = left
                else:
                    counts.pop(key, None)

    def _strike(self, key: str, outcome: str, threshold: int, now: float) -> None:
        count, _ = self._strikes.get(key, (0, 0.0))
        if outcome in STRIKES:
            count += 1
            extra = max(0, count - threshold)
            self._strikes[key] = (count, now + min(BACKOFF_MAX, BACKOFF_SECONDS * 2**extra))
        elif outcome == "done":
            self._strikes.pop(key, None)
        if len(self._strikes) > 20000:  # forget the keys whose back-off has passed
            for stale in [k for k, (_, until) in self._strikes.items() if until < now]:
                del self._strikes[stale]

    def _release(self, ticket: Ticket, outcome: str) -> None:
        now = time.monotonic()
        with self._lock:
            if ticket.released:
                return
            if ticket in self._waiting:
                self._waiting.remove(ticket)
            self._forget(ticket)
            if ticket.running:
                self._slots_taken -= 1
                elapsed = now - (ticket.ran_at or now)
                self._usage.add(ticket.client, elapsed, now)
                self._usage.add(ticket.address, elapsed, now)
                self._mean_seconds = 0.8 * self._mean_seconds + 0.2 * elapsed
                self._strike(ticket.client, outcome, CLIENT_STRIKES, now)
                self._strike(ticket.address, outcome, self.per_address + 1, now)
            self._dispatch()

    @property
    def in_flight(self) -> int:
        with self._lock:
            return len(self._in_flight)

    @property
    def waiting(self) -> int:
        with self._lock:
            return len(self._waiting)
