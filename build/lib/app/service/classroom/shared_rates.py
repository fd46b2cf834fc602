"""Joins and checks per minute counted by every replica together, in a shared store (Redis).

One replica's ``Window`` (app/service/classroom/rates.py) counts what that process saw, so
behind a load balancer with three replicas a class could join three times as fast as its
limit. With ``shared_store_url`` set, each window is a sorted set per key in Redis: the
members are events, their scores the times. One Lua script, run atomically by the store,
drops the events older than the window, counts the rest and adds the new one if there is room.
The time is the store's own clock (``TIME``), so replicas whose clocks differ still agree.

If the store cannot be reached, a window falls back to counting in this process (the limit
then holds per replica, as without a store) and says so in the log once; a class in progress
keeps working.
"""

from __future__ import annotations

import logging
import math
import uuid

from redis import asyncio as aioredis
from redis.exceptions import RedisError

from app.errors import OverCapacity
from app.limits import RATE_WINDOW_SECONDS as WINDOW_SECONDS
from app.limits import STORE_SECONDS
from app.service.classroom.rates import Window

log = logging.getLogger(__name__)

# KEYS[1]: the window's key; ARGV: the window in seconds, the limit, a unique member.
# Returns {1, 0} when the event is counted, {0, seconds to wait} when the window is full.
TAKE = """
local t = redis.call('TIME')
local now = tonumber(t[1]) + tonumber(t[2]) / 1e6
local window = tonumber(ARGV[1])
redis.call('ZREMRANGEBYSCORE', KEYS[1], '-inf', now - window)
if redis.call('ZCARD', KEYS[1]) >= tonumber(ARGV[2]) then
  local oldest = redis.call('ZRANGE', KEYS[1], 0, 0, 'WITHSCORES')
  return {0, tostring(window - (now - tonumber(oldest[2])))}
end
redis.call('ZADD', KEYS[1], now, ARGV[3])
redis.call('EXPIRE', KEYS[1], math.ceil(window) + 1)
return {1, '0'}
"""


class Store:
    """The connection to the shared store, one per web process (its pool is shared by the windows)."""

    def __init__(self, url: str) -> None:
        self.client = aioredis.from_url(
            url, socket_timeout=STORE_SECONDS, socket_connect_timeout=STORE_SECONDS
        )
        self.take = self.client.register_script(TAKE)
        self.warned = False

    async def close(self) -> None:
        await self.client.aclose()


class SharedWindow(Window):
    """At most ``limit`` events per key in any ``WINDOW_SECONDS``, counted across replicas in ``store``."""

    def __init__(self, limit: int, what: str, store: Store, name: str) -> None:
        super().__init__(limit, what)
        self.store = store
        self.prefix = f"lagrange:rate:{name}:"

    async def take(self, key: str) -> None:
        try:
            counted, wait = await self.store.take(
                keys=[self.prefix + key], args=[WINDOW_SECONDS, self.limit, uuid.uuid4().hex]
            )
        except (RedisError, OSError) as exc:
            if not self.store.warned:
                self.store.warned = True
                log.warning("shared store unreachable (%s): counting %s in this replica only", exc, self.what)
            self.hit(key)
            return
        self.store.warned = False
        if not int(counted):
            seconds = max(1, math.ceil(float(wait)))
            raise OverCapacity(f"{self.what}: at most {self.limit} a minute; try again in {seconds} s", seconds)
