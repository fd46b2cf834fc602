"""A small two-level cache: memory, then JSON files on disk, then compute.

Keys carry a fingerprint of the engine's source, so a changed engine never
serves a stale derivation.  Each key is computed at most once per process even
under concurrent requests (a lock per key).
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

from cachetools import LRUCache

from app.settings import settings


class Recent:
    """The last ``size`` answers of a computation, by key, shared by threads (the least recently used goes
    first).  Two threads asking for the same new key may both compute it: these answers are cheap enough
    that a lock per key would cost more than it saves."""

    def __init__(self, size: int) -> None:
        self._answers: LRUCache[Any, Any] = LRUCache(size)
        self._lock = threading.Lock()

    def get(self, key: Any, compute: Callable[[], Any]) -> Any:
        with self._lock:
            found = self._answers.get(key, _MISSING)
        if found is not _MISSING:
            return found
        value = compute()
        with self._lock:
            self._answers[key] = value
        return value


_MISSING = object()

# the ``app`` package whose sources fingerprint a cache (beside site-packages once installed): the nearest
# folder named app above this file, wherever in the service this module sits
APP_SOURCE = next(folder for folder in Path(__file__).resolve().parents if folder.name == "app")


def cache_dir() -> Path:
    return settings().cache_dir


def source_fingerprint(*packages: str) -> str:
    """A hash of every Python file in the named packages of ``app``, and of ``app/limits.py`` (the time bounds
    and defaults every layer reads, which shape what is cached as much as the packages' own code)."""
    digest = hashlib.sha256()
    for paths in ([APP_SOURCE / "limits.py"], *(sorted((APP_SOURCE / p).rglob("*.py")) for p in packages)):
        for path in paths:
            digest.update(path.relative_to(APP_SOURCE.parent).as_posix().encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def write_atomically(path: Path, data: bytes) -> None:
    """Write then rename, so a reader never sees half a file; a read-only disk is no error."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile("wb", dir=path.parent, delete=False, suffix=".tmp") as handle:
            handle.write(data)
        os.replace(handle.name, path)
    except OSError:
        pass  # a read-only disk only costs a recomputation in the next process


class JsonCache:
    """Memory and disk cache of JSON-serialisable results."""

    suffix = ".json"

    def __init__(self, namespace: str, fingerprint: str, folder: Path | None = None):
        self.namespace = namespace
        self.fingerprint = fingerprint
        self.folder = folder  # the cache's root (``settings().cache_dir`` when not given)
        self._memory: dict[str, Any] = {}
        self._locks: dict[str, threading.Lock] = {}
        self._guard = threading.Lock()

    def _path(self, key: str) -> Path:
        return (self.folder or cache_dir()) / self.namespace / f"{key}-{self.fingerprint}{self.suffix}"

    def _lock(self, key: str) -> threading.Lock:
        with self._guard:
            return self._locks.setdefault(key, threading.Lock())

    def get(self, key: str, compute: Callable[[], Any]) -> Any:
        if key in self._memory:
            return self._memory[key]
        with self._lock(key):
            if key in self._memory:
                return self._memory[key]
            path = self._path(key)
            try:
                value = self.decode(path.read_bytes())
            except (OSError, ValueError):
                value = compute()
                self._write(path, value)
            self._memory[key] = value
            return value

    def _write(self, path: Path, value: Any) -> None:
        write_atomically(path, self.encode(value))

    @staticmethod
    def decode(data: bytes) -> Any:
        return json.loads(data)

    @staticmethod
    def encode(value: Any) -> bytes:
        return json.dumps(value).encode()


class BytesCache(JsonCache):
    """Memory and disk cache of documents already encoded (JSON bytes, stored as they are)."""

    @staticmethod
    def decode(data: bytes) -> bytes:
        if not data:
            raise ValueError("an empty file is no document")
        return data

    @staticmethod
    def encode(value: bytes) -> bytes:
        return value
