"""A throwaway Redis for the tests: Debian's ``redis-server`` on a Unix socket in a temp dir, nothing saved.

``redis_server`` (import it into a conftest) is a session fixture yielding the server's URL.
scripts/test.sh installs the package; without it the tests that need it are skipped on a
developer's machine and fail in CI.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import time
from collections.abc import Iterator

import pytest


@pytest.fixture(scope="session")
def redis_server() -> Iterator[str]:
    binary = shutil.which("redis-server")
    if binary is None:
        if os.environ.get("CI"):
            pytest.fail("redis-server is not installed (scripts/test.sh installs Debian's redis-server)")
        pytest.skip("redis-server is not installed: apt-get install -y redis-server (scripts/test.sh does)")
    root = tempfile.mkdtemp(prefix="lagrange-redis-")
    sock = os.path.join(root, "redis.sock")
    server = subprocess.Popen(
        [binary, "--port", "0", "--unixsocket", sock, "--save", "", "--appendonly", "no", "--dir", root],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        for _ in range(200):
            if os.path.exists(sock):
                break
            time.sleep(0.025)
        else:
            pytest.fail("redis-server did not start within 5 s")
        yield f"unix://{sock}"
    finally:
        server.terminate()
        server.wait(timeout=10)
        shutil.rmtree(root, ignore_errors=True)
