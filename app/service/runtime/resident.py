"""The memory budget on measured sizes: each web process records its resident size, each new worker reads them.

The budget (app/settings.py) gives a job what is left after P web processes of ``web_process_mb``
each, their forkservers and workers.  A web process was assumed to hold 350 MB; after half an hour
of classroom traffic each held 478-513 MB, so jobs were allowed memory the machine did not have.
Now every web process writes its resident size (VmRSS) to a small file in the cache folder every
``EVERY`` seconds, and a worker, as it starts (app/service/runtime/worker.py ``initialize_worker``), caps
its job at what the budget leaves with the largest size recorded by a live web process in place
of ``web_process_mb`` when that is larger: a grown web process shrinks the next workers' share
instead of pushing the machine past its limit.  Workers start afresh often (after a time-out, a
failure, a large job, or ``MAX_TASKS`` jobs), so the cap follows the measurement within minutes.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path

from app.settings import Settings, settings

EVERY = 30.0  # seconds between two records of a web process's size
FOLDER = "web-resident"


def resident_mb(pid: int | None = None) -> int:
    """The resident set size of a process (this one by default), in MB; 0 if it cannot be read."""
    try:
        with open(f"/proc/{pid or 'self'}/statm") as statm:
            return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") // 2**20
    except (OSError, ValueError, IndexError):
        return 0


def _folder(config: Settings | None) -> Path:
    return Path((config or settings()).cache_dir) / FOLDER


def record(pid: int | None = None, config: Settings | None = None) -> None:
    """Write this web process's resident size where the workers read it (``config``'s cache folder)."""
    pid = pid or os.getpid()
    folder = _folder(config)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        temporary = folder / f".{pid}.tmp"
        temporary.write_text(str(resident_mb(pid)))
        temporary.replace(folder / str(pid))
    except OSError:
        pass  # a read-only disk: the budget keeps its configured size


def measured_web_mb(config: Settings | None = None) -> int:
    """The largest resident size recorded by a live web process (0 when none is recorded); stale files go."""
    largest = 0
    try:
        entries = list(_folder(config).iterdir())
    except OSError:
        return 0
    for entry in entries:
        if not entry.name.isdigit():
            continue
        if not Path(f"/proc/{entry.name}").exists():
            entry.unlink(missing_ok=True)  # that process has ended
            continue
        try:
            largest = max(largest, int(entry.read_text() or 0))
        except (OSError, ValueError):
            continue
    return largest


def job_memory_mb(config: Settings | None = None) -> int:
    """The per-job memory cap with the measured web size in the budget (when larger than the configured one)."""
    config = config or settings()
    measured = measured_web_mb(config)
    if measured > config.web_process_mb:
        config = config.model_copy(update={"web_process_mb": measured})
    return config.job_memory_mb


def start_recording(config: Settings | None = None) -> threading.Event:
    """Record this process's size now and every ``EVERY`` seconds (a daemon thread), until the event is set."""
    stop = threading.Event()

    def loop() -> None:
        record(config=config)
        while not stop.wait(EVERY):
            record(config=config)

    threading.Thread(target=loop, name="record-resident", daemon=True).start()
    return stop
