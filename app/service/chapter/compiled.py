"""Numeric systems (right-hand sides and observables) compiled once per scene or user system, per holder.

A ``Compiled`` is held by the scenes' state of a process (``app.service.chapter.derivations.Scenes``: the app's
services in the web process, the process's own in a worker or a script); none is a module global."""

from __future__ import annotations

import hashlib
import threading
import time
from collections import OrderedDict
from collections.abc import Sequence
from pathlib import Path

import sympy as sp

from app.engine.derivation.derive import Derivation, value_or
from app.engine.equations.constraints import ConstraintForce
from app.engine.equations.distances import distance_events
from app.numerics.events import EventFunction, compile_events
from app.numerics.observables import Observables, build
from app.numerics.system import NumericSystem, generated_sources, numeric_system
from app.scenes import Scene
from app.service.runtime.cache import JsonCache, source_fingerprint


def scene_sources(folder: Path | None = None) -> JsonCache:
    """The scenes' generated sources on disk (keyed by the engine's, scenes' and numerics' source), so a new
    process skips the code generation; under ``folder`` (by default the settings' ``cache_dir``)."""
    return JsonCache("generated-sources", source_fingerprint("engine", "scenes", "numerics"), folder)


class Compiled:
    """Numeric systems per scene id (or per generated source for user systems), and the scenes' terminal events.

    One lock per key: a request for one scene never waits while another scene's system is built
    (by the warm-up thread or another request); two requests for the same scene build it once.
    ``sources``: where a scene's generated sources are kept (``scene_sources()``)."""

    def __init__(self, size: int = 32, sources: JsonCache | None = None):
        self.size = size
        self.sources = scene_sources() if sources is None else sources
        self.items: OrderedDict[str, tuple[NumericSystem, Observables]] = OrderedDict()
        self.lock = threading.Lock()  # guards ``items`` and ``_building``, held only briefly
        self._building: dict[str, threading.Lock] = {}
        self.build_seconds: dict[str, float] = {}
        self._events: dict[str, list[EventFunction]] = {}  # per scene id: its terminal events, compiled once

    def _cached(self, key: str) -> tuple[NumericSystem, Observables] | None:
        with self.lock:
            if key in self.items:
                self.items.move_to_end(key)
                return self.items[key]
            return None

    def get(
        self, key: str | None, d: Derivation, forces: Sequence[ConstraintForce] | None = None
    ) -> tuple[NumericSystem, Observables]:
        """The numeric system and its observables; ``forces``: the constraint forces observed (by default the
        derivation's own, a typed member computed with the derivation)."""
        forces = value_or(d.constraint_forces, ()) if forces is None else tuple(forces)
        # a user system's key is its declaration (and its constraint forces), known before any code
        # generation: a warm system is found here without printing a line of its source again
        scene = key is not None
        found_key = key if key is not None else system_key(d, forces)
        found = self._cached(found_key)
        if found is not None:
            return found
        with self.lock:
            building = self._building.setdefault(found_key, threading.Lock())
        with building:
            return self._cached(found_key) or self._build(found_key, d, forces, scene)

    def _build(
        self, key: str, d: Derivation, forces: Sequence[ConstraintForce], scene: bool
    ) -> tuple[NumericSystem, Observables]:
        start = time.perf_counter()
        # a scene's generated sources come from the disk cache (keyed by the engine's, scenes' and
        # numerics' source), so a new worker skips the code generation
        sources = self.sources.get(key, lambda: generated_sources(d)) if scene else None
        system = numeric_system(d, sources)
        entry = (system, build(system, forces))
        with self.lock:
            self.build_seconds[key] = time.perf_counter() - start
            self.items[key] = entry
            while len(self.items) > self.size:
                self.items.popitem(last=False)
        return entry

    def events(self, scene: Scene | None, system: NumericSystem) -> list[EventFunction]:
        """A scene's terminal events compiled for its system (once); for a user system, one per coordinate
        declared never negative (the run ends where it reaches 0)."""
        if scene is None:
            return compile_events(system, distance_events(system.derivation.system.nonnegative))
        if not scene.events:
            return []
        with self.lock:
            found = self._events.get(scene.id)
        if found is None:
            found = compile_events(system, scene.events)
            with self.lock:
                found = self._events.setdefault(scene.id, found)
        return found


def system_key(d: Derivation, forces: Sequence[ConstraintForce]) -> str:
    """A user system's cache key: a digest of its declaration (the parsed System) and its constraint forces."""
    text = repr(d.system) + "".join(f"|{f.constraint!r}={sp.srepr(f.force)}" for f in forces)
    return "system:" + hashlib.sha256(text.encode()).hexdigest()
