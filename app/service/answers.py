"""The answers one running app remembers about the chapter's scenes and the playground's examples.

Each is a cache the app's ``Services`` hold (built in ``app.main``'s lifespan) and
the routes are given through ``Depends`` (``app.web.api.deps.AnswersDep``), then pass
down to the service function that fills it: none is a module global, so two apps
(or a test's own) never share one, and a test hands a route a cache of its own
(an empty one, or one whose disk is a temporary folder) with
``app.dependency_overrides`` instead of patching a module.

* ``Recent``: the last answers of a computation that depends on what a client
  sends (parameter values, options), kept in memory only;
* ``JsonCache``/``BytesCache``: a result computed once per version of the
  source (memory, then the disk that set-up filled, ``python -m app.web.warm``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from app.service.export import exporting
from app.service.runtime.cache import BytesCache, JsonCache, Recent, source_fingerprint
from app.service.simulations import action, lyapunov, modes, poincare, work_precision


def examples_cache(folder: Path | None = None) -> BytesCache:
    """The playground examples' derivation documents (app/web/pages/playground.py), keyed by the engine's and the
    service's source, so a restarted server loads them instead of deriving them again."""
    return BytesCache("example-derivations", source_fingerprint("engine", "service"), folder)


@dataclass(frozen=True)
class Answers:
    modes_at: Recent  # a scene's modes at the parameter values a slider sent
    measured_modes: JsonCache  # a scene's measured modes at its defaults
    sections: Recent  # Poincaré sections of scenes, by options
    actions: Recent  # the action of a scene's varied paths, by options
    exports: Recent  # a scene's derivation as a file, by format
    work_precision: JsonCache  # a scene's error against run time report
    examples: BytesCache  # the playground examples' derivations
    lyapunov: JsonCache  # a chaotic scene's largest Lyapunov exponent at its default start

    @classmethod
    def start(cls, folder: Path | None = None) -> Answers:
        """Empty memories; the disk caches under ``folder`` (by default the settings' ``cache_dir``)."""
        return cls(
            modes_at=Recent(modes.AT_CACHE_SIZE),
            measured_modes=modes.measured_cache(folder),
            sections=Recent(poincare.CACHED_SECTIONS),
            actions=Recent(action.CACHED_ANSWERS),
            exports=Recent(exporting.CACHED_EXPORTS),
            work_precision=work_precision.report_cache(folder),
            examples=examples_cache(folder),
            lyapunov=lyapunov.lyapunov_cache(folder),
        )
