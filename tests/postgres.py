"""A throwaway PostgreSQL cluster for the tests: Debian's ``postgresql`` binaries, a socket in a temp dir.

``postgres_server`` (import it into a conftest) is a session fixture: it runs
``initdb`` and ``pg_ctl start`` as a non-root user (``postgres`` when the tests
run as root; initdb refuses root), listening on a Unix socket only, and yields
a function that creates a fresh database and returns its SQLAlchemy URL.
scripts/test.sh installs the package; without it the tests that need it are
skipped on a developer's machine and fail in CI.
"""

from __future__ import annotations

import glob
import os
import pwd
import shutil
import socket
import subprocess
import tempfile
import uuid
from collections.abc import Callable, Iterator

import pytest


def _bin(name: str) -> str | None:
    found = sorted(glob.glob(f"/usr/lib/postgresql/*/bin/{name}"))
    return found[-1] if found else shutil.which(name)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="session")
def postgres_server() -> Iterator[Callable[[], str]]:
    initdb, pg_ctl = _bin("initdb"), _bin("pg_ctl")
    if not (initdb and pg_ctl):
        if os.environ.get("CI"):
            pytest.fail("PostgreSQL is not installed (scripts/test.sh installs Debian's postgresql)")
        pytest.skip("PostgreSQL is not installed: apt-get install -y postgresql (scripts/test.sh does)")
    root = tempfile.mkdtemp(prefix="lagrange-pg-")
    data, port = os.path.join(root, "data"), _free_port()
    prefix: list[str] = []
    if os.geteuid() == 0:
        user = pwd.getpwnam("postgres")
        os.chown(root, user.pw_uid, user.pw_gid)
        prefix = ["runuser", "-u", "postgres", "--"]
    run = lambda *args: subprocess.run([*prefix, *args], check=True, capture_output=True, text=True)  # noqa: E731
    run(initdb, "-D", data, "-U", "postgres", "--auth=trust", "-E", "UTF8", "--no-sync")
    options = f"-k {root} -p {port} -c listen_addresses='' -c fsync=on -c max_connections=200"
    run(pg_ctl, "-D", data, "-o", options, "-l", os.path.join(root, "log"), "-w", "start")

    def database() -> str:
        name = "t" + uuid.uuid4().hex[:12]
        run(_bin("createdb") or "createdb", "-h", root, "-p", str(port), "-U", "postgres", name)
        return f"postgresql+psycopg://postgres@/{name}?host={root}&port={port}"

    try:
        yield database
    finally:
        subprocess.run([*prefix, pg_ctl, "-D", data, "-m", "immediate", "stop"], capture_output=True)
        shutil.rmtree(root, ignore_errors=True)
