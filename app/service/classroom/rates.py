"""Joins and checks per minute, per class and per client: a sliding window of one minute per key.

The fair share of the worker pool (app/service/runtime/fairness.py) already keeps one
check in flight per student and a few per address; these windows bound the
rate of what the classes' database records: a class accepts at most so many
joins and checks a minute (one code cannot flood the disk), and each client
(a session or an address for a join, a student for a check) at most so many.
Counted per web process, like the fair share; with a shared store, across replicas
(app/service/classroom/shared_rates.py).
"""

from __future__ import annotations

import math
import threading
import time
from collections import deque

from app.errors import OverCapacity
from app.limits import RATE_WINDOW_SECONDS as WINDOW_SECONDS

MAX_KEYS = 20000


class Window:
    """At most ``limit`` events per key in any ``WINDOW_SECONDS``; ``hit`` raises OverCapacity past it."""

    def __init__(self, limit: int, what: str) -> None:
        self.limit = limit
        self.what = what
        self._events: dict[str, deque[float]] = {}
        self._lock = threading.Lock()

    async def take(self, key: str) -> None:
        """Count one event of ``key`` (the routes' way in; a shared window asks the store)."""
        self.hit(key)

    def hit(self, key: str) -> None:
        now = time.monotonic()
        with self._lock:
            recent = self._events.setdefault(key, deque())
            while recent and now - recent[0] > WINDOW_SECONDS:
                recent.popleft()
            if len(recent) >= self.limit:
                wait = max(1, math.ceil(WINDOW_SECONDS - (now - recent[0])))
                raise OverCapacity(f"{self.what}: at most {self.limit} a minute; try again in {wait} s", wait)
            recent.append(now)
            if len(self._events) > MAX_KEYS:  # forget the idle keys
                for stale in [k for k, q in self._events.items() if not q or now - q[-1] > WINDOW_SECONDS]:
                    del self._events[stale]
