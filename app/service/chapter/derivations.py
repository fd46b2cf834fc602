"""The chapter's scenes as a process serves them: their derivations, documents and compiled systems (``Scenes``).

A ``Scenes`` holds in memory what the disk caches keep between processes (the pickled derivations,
the JSON documents, the generated sources).  The web app's services hold one (``Services.chapter``,
given to routes through ``app.web.api.deps.ChapterDep``, to the warm-up as an argument); the lifespan gives
it this process's ``PROCESS_SCENES``, which a worker process or a script (no app) passes explicitly too,
and which the code the app does not reach reads, so the web process keeps one copy of each scene's SymPy
objects and compiled system (docs/state.md says why).  A test passes this one or builds its own, on a
temporary disk if it likes.
"""

from __future__ import annotations

import json
import pickle
import threading
from pathlib import Path
from typing import Any

from app.engine.algebra.budget import patience
from app.engine.derivation.derive import Derivation, derive
from app.engine.document.contract import printed_document
from app.engine.document.model import Document
from app.errors import UnknownScene
from app.limits import SCENE_PATIENCE
from app.numerics.observables import Observables
from app.numerics.system import NumericSystem
from app.scenes import SCENES, Scene
from app.service.chapter.compiled import Compiled, scene_sources
from app.service.runtime.cache import JsonCache, cache_dir, source_fingerprint, write_atomically


def scene(scene_id: str) -> Scene:
    try:
        return SCENES[scene_id]
    except KeyError:
        raise UnknownScene(scene_id, tuple(sorted(SCENES))) from None


def _document(s: Scene, d: Derivation) -> Document:
    # a scene's document is printed once per version and kept on disk: its bounds are patient, so what the
    # book prints does not depend on how loaded the machine was (members, Hamilton's forms, the modes)
    with patience(SCENE_PATIENCE):
        return printed_document(d, scene=s)


class DocumentCache(JsonCache):
    """The chapter's documents: the model in memory, its JSON on disk (the same file as the dict it replaced)."""

    @staticmethod
    def decode(data: bytes) -> Document:
        return Document.model_validate_json(data)

    @staticmethod
    def encode(value: Document) -> bytes:
        return json.dumps(value.as_json()).encode()


class Scenes:
    """Each scene's derivation (memory, then the pickles on disk), its contract document (memory, then JSON on
    disk) and its numeric system (``compiled``), each computed once; the disk caches under ``folder`` (by
    default the settings' ``cache_dir``).  One lock per scene: a request for one scene never waits while
    another is derived."""

    def __init__(self, folder: Path | None = None) -> None:
        self.folder = folder
        self.documents = DocumentCache("derivations", source_fingerprint("engine", "scenes"), folder)
        self.compiled = Compiled(sources=scene_sources(folder))
        self._derivations: dict[str, Derivation] = {}
        self._guard = threading.Lock()  # guards ``_locks``, held only briefly
        self._locks: dict[str, threading.Lock] = {}
        # documents printed while a derivation was made (which computes its members), until ``document`` takes them
        self._printed: dict[str, Document] = {}

    def object_path(self, scene_id: str) -> Path:
        """Where a scene's pickled derivation is kept (keyed by the engine's and scenes' source)."""
        return (self.folder or cache_dir()) / "derivation-objects" / f"{scene_id}-{self.documents.fingerprint}.pickle"

    def derived(self, scene_id: str) -> Derivation:
        """A scene's derivation from the disk, else derived (and its document printed) and pickled: no memory."""
        # The SymPy objects themselves, pickled by this program into its own cache folder (keyed by the
        # engine's and scenes' source), so a new worker loads the chapter in milliseconds instead of deriving it.
        # The derivation is pickled once its document is printed: printing computes every member (constraint
        # forces, Hamilton's equations, normal modes...), which the pickle then carries, so no process that
        # loads it (the web process's threads, where no time limit can interrupt SymPy) computes them again.
        path = self.object_path(scene_id)
        try:
            return pickle.loads(path.read_bytes())
        except Exception:  # absent, or written by another version of SymPy: derive again
            s = SCENES[scene_id]
            with patience(SCENE_PATIENCE):
                d = derive(s.system)
            self._printed[scene_id] = _document(s, d)  # taken by document
            write_atomically(path, pickle.dumps(d, protocol=pickle.HIGHEST_PROTOCOL))
            return d

    def derivation(self, scene_id: str) -> Derivation:
        """The SymPy derivation of a scene, its members included (memory- and disk-cached; one lock per scene)."""
        scene(scene_id)
        with self._guard:
            lock = self._locks.setdefault(scene_id, threading.Lock())
        with lock:
            found = self._derivations.get(scene_id)
            if found is None:
                found = self._derivations[scene_id] = self.derived(scene_id)
            return found

    def document(self, scene_id: str) -> Document:
        """The printed document of a scene's derivation (memory and disk cached): for printing only; every
        other reader takes the derivation's typed members (``derivation``)."""
        s = scene(scene_id)

        def printed() -> Document:
            d = self.derivation(scene_id)
            return self._printed.pop(scene_id, None) or _document(s, d)

        document = self.documents.get(scene_id, printed)
        self._printed.pop(scene_id, None)  # printed again while the document came from the disk: not needed
        return document

    def system(self, scene_id: str) -> tuple[NumericSystem, Observables]:
        """A scene's numeric system and its observables (built, or loaded from the disk caches, once)."""
        return self.compiled.get(scene_id, self.derivation(scene_id))

    def warm_all(self) -> None:
        """Compute (or load) every scene's derivation and its document: run at start-up and at image build."""
        for scene_id in SCENES:
            self.derivation(scene_id)
            self.document(scene_id)


# this process's: the web app's services hold it, a worker process or a script (no app) reads it (docs/state.md)
PROCESS_SCENES = Scenes()


def derivation(scene_id: str) -> Derivation:
    """The process's derivation of a scene (``Scenes.derivation``)."""
    return PROCESS_SCENES.derivation(scene_id)


def scene_document(scene_id: str) -> Document:
    """The process's document of a scene's derivation (``Scenes.document``)."""
    return PROCESS_SCENES.document(scene_id)


def derivation_document(scene_id: str) -> dict[str, Any]:
    """The JSON of the process's document of a scene, as GET /api/scenes/{id}/derivation sends it: what a script
    or a test of the served contract reads."""
    return PROCESS_SCENES.document(scene_id).as_json()


def warm_all() -> None:
    """Every scene's derivation and document in the process's ``Scenes``: at start-up and at image build."""
    PROCESS_SCENES.warm_all()


if __name__ == "__main__":
    warm_all()
