"""A bound on the disk that users' systems take: an LRU of generated modules by total size.

Every distinct system a user simulates leaves a generated module
(``<cache>/generated-user/rhs_<key>.py``, app/numerics/paths.py) and numba's
compiled copies of its functions (``<numba cache>/generated-user_<hash>/rhs_<key>.*``).
``prune`` deletes whole modules, least recently used first (the module file's
modification time, touched on each use by app/numerics/jit.py), until the
total is at most ``settings().user_cache_mb``.  The chapter's modules live in
another folder and are never touched.  A module deleted while a worker has it
loaded keeps working there; the next worker that needs it writes and compiles
it again.
"""

from __future__ import annotations

import time
from pathlib import Path

from app.numerics.paths import USER_GENERATED, numba_dir, user_generated_dir
from app.settings import settings

PRUNE_EVERY = 10.0  # seconds between two looks at the folder from one worker
_last = 0.0


def _size(path: Path) -> int:
    try:
        return path.stat().st_size
    except OSError:
        return 0


def usage(generated: Path | None = None, compiled: Path | None = None) -> dict[str, tuple[float, list[Path]]]:
    """Each user module's key: (last use, its files: the module and its numba cache files)."""
    generated = generated or user_generated_dir()
    compiled = compiled or numba_dir()
    modules: dict[str, tuple[float, list[Path]]] = {}
    for module in generated.glob("rhs_*.py"):
        try:
            modules[module.stem] = (module.stat().st_mtime, [module])
        except OSError:
            continue
    for folder in compiled.glob(f"{USER_GENERATED}_*"):
        for cached in folder.glob("rhs_*"):
            key = cached.name.split(".", 1)[0]
            used, files = modules.get(key, (0.0, []))  # compiled files without a module: the first to go
            modules[key] = (used, [*files, cached])
    return modules


def total_bytes(generated: Path | None = None, compiled: Path | None = None) -> int:
    return sum(_size(f) for _, files in usage(generated, compiled).values() for f in files)


def prune(bound_bytes: int | None = None, generated: Path | None = None, compiled: Path | None = None) -> int:
    """Delete least recently used user modules until their total size is within the bound; bytes freed."""
    bound = bound_bytes if bound_bytes is not None else settings().user_cache_mb * 2**20
    modules = usage(generated, compiled)
    sizes = {key: sum(_size(f) for f in files) for key, (_, files) in modules.items()}
    total, freed = sum(sizes.values()), 0
    for key, (_, files) in sorted(modules.items(), key=lambda item: item[1][0]):
        if total <= bound:
            break
        for path in files:
            try:
                path.unlink()
            except OSError:
                pass  # another worker removed it first
        total -= sizes[key]
        freed += sizes[key]
    return freed


def prune_now_and_then() -> None:
    """``prune`` at most every PRUNE_EVERY seconds (called by a worker after each job)."""
    global _last
    now = time.monotonic()
    if now - _last >= PRUNE_EVERY:
        _last = now
        prune()


