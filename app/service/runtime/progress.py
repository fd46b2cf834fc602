"""A long derivation's progress, from the worker that runs it to the page that waits for it.

The worker's job listens to the engine (app/engine/algebra/progress.py) and keeps, in a small JSON file named by the
job's key under ``cache_dir/progress``, the part it is on and since when: written whole and renamed into
place, so a reader never sees half a file; removed when the job ends, however it ends.  The web process reads
it for ``GET /api/derive/progress/{key}``.  The file lives on the machine that runs the job, so a replica
that does not run it answers that nothing of that key runs there.
"""

from __future__ import annotations

import json
import os
import re
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from app.engine.algebra.progress import listening
from app.settings import settings

# a job's key is a SHA-256 in hexadecimal (app/service/users/user_checks.py spec_key)
KEY = re.compile(r"[0-9a-f]{64}")
FIRST = "the equations of motion"


def folder() -> Path:
    return settings().cache_dir / "progress"


def _path(key: str) -> Path:
    if not KEY.fullmatch(key):
        raise ValueError("a derivation's key is 64 hexadecimal digits")
    return folder() / f"{key}.json"


@contextmanager
def reported(key: str) -> Iterator[None]:
    """Within the block, the engine's parts are written to the key's file as each begins; the file goes after."""
    path = _path(key)
    path.parent.mkdir(parents=True, exist_ok=True)
    started = time.time()

    def write(part: str) -> None:
        spare = path.with_suffix(f".{os.getpid()}.tmp")
        spare.write_text(json.dumps({"part": part, "since": time.time(), "started": started, "pid": os.getpid()}))
        os.replace(spare, path)

    write(FIRST)
    try:
        with listening(write):
            yield
    finally:
        path.unlink(missing_ok=True)


def clear(key: str) -> None:
    """Remove the key's file: its job has ended (the web process's word, for a worker killed before it could)."""
    _path(key).unlink(missing_ok=True)


def _alive(pid: Any) -> bool:
    try:
        os.kill(int(pid), 0)
    except (ProcessLookupError, TypeError, ValueError):
        return False
    except PermissionError:  # there, but another user's
        return True
    return True


def read(key: str) -> dict[str, Any] | None:
    """The part a running job of this key is on, for how long (s) and since its start (s); None if none runs."""
    path = _path(key)
    try:
        stored = json.loads(path.read_text())
    except (OSError, ValueError):  # none, or being replaced this instant
        return None
    if not _alive(stored.get("pid")):
        # a worker killed between the web process's clearing and its own last word left it behind
        path.unlink(missing_ok=True)
        return None
    now = time.time()
    return {
        "part": stored["part"],
        "part_seconds": round(max(0.0, now - stored["since"]), 1),
        "seconds": round(max(0.0, now - stored["started"]), 1),
    }
