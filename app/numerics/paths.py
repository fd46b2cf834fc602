"""Where compiled code and generated sources live on disk.

numba's on-disk cache goes to ``NUMBA_CACHE_DIR``; unless the environment sets
it, that is ``<settings().cache_dir>/numba``.  Generated right-hand
sides are written as modules under ``.../generated`` (numba only caches
functions defined in a real file).  A read-only cache directory falls back to
a per-user folder under the system's temporary directory.

The worker processes that run users' systems write theirs under
``.../generated-user`` instead (``use_user_folder``): that folder and its numba
cache are bounded in size (app/service/disk.py), while the chapter's stay.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from app.settings import settings


def _writable(path: Path) -> bool:
    try:
        path.mkdir(parents=True, exist_ok=True)
        probe = path / f".probe-{os.getpid()}"
        probe.write_text("")
        probe.unlink()
        return True
    except OSError:
        return False


def cache_root() -> Path:
    base = settings().cache_dir
    if _writable(base):
        return base
    return Path(tempfile.gettempdir()) / f"lagrange-cache-{os.getuid()}"


def configure_numba() -> Path:
    """Point numba's cache at a writable folder; call before any @njit(cache=True)."""
    target = Path(os.environ.get("NUMBA_CACHE_DIR") or cache_root() / "numba")
    if not _writable(target):
        target = Path(tempfile.gettempdir()) / f"lagrange-numba-{os.getuid()}"
        target.mkdir(parents=True, exist_ok=True)
    os.environ["NUMBA_CACHE_DIR"] = str(target)
    import numba.core.config

    if numba.core.config.CACHE_DIR != str(target):
        numba.core.config.reload_config()
    return target


GENERATED = "generated"
USER_GENERATED = "generated-user"
_folder = GENERATED


def use_user_folder() -> None:
    """Write this process's generated modules to the bounded folder for users' systems."""
    global _folder
    _folder = USER_GENERATED


def generated_dir() -> Path:
    path = cache_root() / _folder
    path.mkdir(parents=True, exist_ok=True)
    return path


def user_generated_dir() -> Path:
    return cache_root() / USER_GENERATED


def numba_dir() -> Path:
    return Path(os.environ.get("NUMBA_CACHE_DIR") or cache_root() / "numba")
