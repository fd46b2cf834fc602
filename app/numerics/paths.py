"""Where compiled code and generated sources live on disk.

numba's on-disk cache goes to ``NUMBA_CACHE_DIR``; unless the environment sets
it, that is ``<settings().cache_dir>/numba``.  Generated right-hand
sides are written as modules under ``.../generated`` (numba only caches
functions defined in a real file).  A read-only cache directory falls back to
a per-user folder under the system's temporary directory.

The worker processes that run users' systems write theirs under
``.../generated-user`` instead (``use_user_folder``): that folder and its numba
cache are bounded in size (app/service/runtime/disk.py), while the chapter's stay.
"""

from __future__ import annotations

import hashlib
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
    drop_stale_kernels(target)
    return target


KERNELS = Path(__file__).resolve().with_name("kernels")
STAMP = "sources.sha256"


def kernels_cache(numba_cache: Path) -> Path:
    """The kernels' folder in numba's cache: the source folder's name and the SHA-1 of its path
    (the rule of numba's ``_CacheLocator.get_suitable_cache_subpath``, copied: that class is private)."""
    folder = str(KERNELS)
    return numba_cache / f"{KERNELS.name}_{hashlib.sha1(folder.encode()).hexdigest()}"


def kernels_stamp(folder: Path = KERNELS) -> str:
    """A hash of every source file of the kernels' package (``folder``)."""
    digest = hashlib.sha256()
    for source in sorted(folder.glob("*.py")):
        digest.update(source.name.encode())
        digest.update(source.read_bytes())
    return digest.hexdigest()


def drop_stale_kernels(numba_cache: Path) -> None:
    """Empty the kernels' cache when any of their sources changed since it was filled.

    numba checks only the date and size of the file that defines a cached function, but a kernel's
    machine code also holds what it inlined from its sibling modules (the unrolled stages, the
    tableaux as constants, common's helpers): after a change there, the cache would keep serving
    the old code.  So the folder carries the hash of all the kernels' sources, and a different
    hash (or none, from a cache filled before this rule) empties it; the kernels then compile again."""
    folder = kernels_cache(numba_cache)
    stamp = folder / STAMP
    now = kernels_stamp()
    try:
        if stamp.read_text() == now:
            return
    except OSError:
        pass
    try:
        folder.mkdir(parents=True, exist_ok=True)
        for cached in folder.iterdir():
            if cached.suffix in (".nbi", ".nbc"):
                cached.unlink(missing_ok=True)
        stamp.write_text(now)
    except OSError:  # a read-only cache: numba compiles in memory and cannot save anyway
        pass


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
