"""Derivations of the chapter's scenes, computed once and cached."""

from __future__ import annotations

import pickle
import threading
from functools import cache
from typing import Any

from app.engine.contract import derivation_json
from app.engine.derive import Derivation, derive
from app.errors import UnknownScene
from app.scenes import SCENES, Scene
from app.service.cache import JsonCache, cache_dir, source_fingerprint, write_atomically

_json_cache = JsonCache("derivations", source_fingerprint("engine", "scenes"))


def scene(scene_id: str) -> Scene:
    try:
        return SCENES[scene_id]
    except KeyError:
        raise UnknownScene(scene_id, tuple(sorted(SCENES))) from None


_guard = threading.Lock()
_locks: dict[str, threading.Lock] = {}


def _object_path(scene_id: str):
    return cache_dir() / "derivation-objects" / f"{scene_id}-{_json_cache.fingerprint}.pickle"


@cache
def _derivation(scene_id: str) -> Derivation:
    # The SymPy objects themselves, pickled by this program into its own cache folder (keyed by the
    # engine's and scenes' source), so a new worker loads the chapter in milliseconds instead of deriving it.
    path = _object_path(scene_id)
    try:
        return pickle.loads(path.read_bytes())
    except Exception:  # absent, or written by another version of SymPy: derive again
        d = derive(SCENES[scene_id].system)
        write_atomically(path, pickle.dumps(d, protocol=pickle.HIGHEST_PROTOCOL))
        return d


def derivation(scene_id: str) -> Derivation:
    """The SymPy derivation of a scene (memory- and disk-cached; one lock per scene)."""
    scene(scene_id)
    with _guard:
        lock = _locks.setdefault(scene_id, threading.Lock())
    with lock:
        return _derivation(scene_id)


def derivation_document(scene_id: str) -> dict[str, Any]:
    """The contract JSON of a scene's derivation (memory and disk cached)."""
    s = scene(scene_id)
    return _json_cache.get(scene_id, lambda: {"id": s.id, **derivation_json(derivation(scene_id), scene=s)})


def warm_all() -> None:
    """Compute (or load) every scene's derivation and its document: run at start-up and at image build."""
    for scene_id in SCENES:
        derivation(scene_id)
        derivation_document(scene_id)


if __name__ == "__main__":
    warm_all()
