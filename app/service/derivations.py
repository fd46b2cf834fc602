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


# documents printed while a derivation was made (which computes its members), until derivation_document takes them
_printed: dict[str, dict[str, Any]] = {}


@cache
def _derivation(scene_id: str) -> Derivation:
    # The SymPy objects themselves, pickled by this program into its own cache folder (keyed by the
    # engine's and scenes' source), so a new worker loads the chapter in milliseconds instead of deriving it.
    # The derivation is pickled once its document is printed: printing computes every member (constraint
    # forces, Hamilton's equations, normal modes...), which the pickle then carries, so no process that
    # loads it (the web process's threads, where no time limit can interrupt SymPy) computes them again.
    path = _object_path(scene_id)
    try:
        return pickle.loads(path.read_bytes())
    except Exception:  # absent, or written by another version of SymPy: derive again
        s = SCENES[scene_id]
        d = derive(s.system)
        _printed[scene_id] = _document(s, d)  # taken by derivation_document
        write_atomically(path, pickle.dumps(d, protocol=pickle.HIGHEST_PROTOCOL))
        return d


def _document(s: Scene, d: Derivation) -> dict[str, Any]:
    return {"id": s.id, **derivation_json(d, scene=s)}


def derivation(scene_id: str) -> Derivation:
    """The SymPy derivation of a scene, its members included (memory- and disk-cached; one lock per scene)."""
    scene(scene_id)
    with _guard:
        lock = _locks.setdefault(scene_id, threading.Lock())
    with lock:
        return _derivation(scene_id)


def derivation_document(scene_id: str) -> dict[str, Any]:
    """The contract JSON of a scene's derivation (memory and disk cached): for printing only; every
    other reader takes the derivation's typed members (``derivation``)."""
    s = scene(scene_id)

    def printed() -> dict[str, Any]:
        d = derivation(scene_id)
        return _printed.pop(scene_id, None) or _document(s, d)

    document = _json_cache.get(scene_id, printed)
    _printed.pop(scene_id, None)  # printed again while the document came from the disk: not needed
    return document


def warm_all() -> None:
    """Compute (or load) every scene's derivation and its document: run at start-up and at image build."""
    for scene_id in SCENES:
        derivation(scene_id)
        derivation_document(scene_id)


if __name__ == "__main__":
    warm_all()
