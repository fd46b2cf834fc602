"""Stop waiting for work when the client that asked for it has gone.

Starlette keeps running a route after its client disconnects; a queued job
would then still take a worker for nobody.  ``unless_gone`` runs the work
beside a watch on the request's receive channel (after the body, the next
message is ``http.disconnect``) and cancels the work when the client leaves.
"""

from __future__ import annotations

import asyncio
from collections.abc import Coroutine
from typing import Any, TypeVar

from starlette.requests import Request

T = TypeVar("T")


class ClientGone(Exception):
    """The client disconnected before its answer was ready."""


async def unless_gone(request: Request | None, work: Coroutine[Any, Any, T]) -> T:
    """The work's result; raises ClientGone (having cancelled the work) if the client disconnects first."""
    if request is None:  # a caller without a connection (a test, a script): nobody can leave
        return await work
    task = asyncio.ensure_future(work)

    async def watch() -> None:
        while (await request.receive())["type"] != "http.disconnect":
            pass
        task.cancel()

    watcher = asyncio.ensure_future(watch())
    try:
        return await task
    except asyncio.CancelledError:
        if watcher.done() and not watcher.cancelled():
            raise ClientGone() from None
        raise
    finally:
        watcher.cancel()
