"""The uvicorn command-line options for this machine's settings (scripts/run.sh, scripts/serve.sh, the Dockerfile).

A module of its own, importing only the settings: the scripts run it in a separate
interpreter before uvicorn starts, so it must cost next to nothing (uvicorn's protocol
classes, which ``app.web.http.slow_clients`` needs, take longer to import than the rest of it).

    python -m app.web.http.server_options
"""

from __future__ import annotations

import sys

from app.settings import settings


def options() -> list[str]:
    """uvicorn's command-line options: worker processes, keep-alive, connection cap, header deadline."""
    s = settings()
    return [
        "--workers", str(s.web_process_count),
        "--timeout-keep-alive", str(s.keep_alive_seconds),  # long: many students behind one address reuse theirs
        "--limit-concurrency", str(s.connections),
        "--http", "app.web.http.slow_clients:HeaderDeadline",
        "--timeout-graceful-shutdown", "20",
        "--no-proxy-headers",  # the client's address is app/web/http/address.py's decision (LAGRANGE_PROXY_HEADER)
    ]  # fmt: skip


if __name__ == "__main__":
    sys.stdout.write(" ".join(options()) + "\n")
