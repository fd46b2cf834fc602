"""The long-lived services of one running app, built at its start and stopped at its end.

``app.main``'s lifespan builds one ``Services`` and hands it to the routes as
lifespan state (``app.web.api.deps`` reads it from the request); nothing here is a
module global, so two apps (or a test's own service) never share a pool by accident.
The users' pool starts its processes with its first job, the scenes' worker with
the warm-up (``warm``) or its first run; none starts here.
"""

from __future__ import annotations

import logging
import threading
from dataclasses import dataclass

from app.service.answers import Answers
from app.service.chapter.derivations import Scenes
from app.service.classroom.service import Classroom
from app.service.runtime.worker import WorkerPool
from app.service.simulations.simulation import Gates, load_scenes
from app.service.tutor.checking import Checking
from app.service.users.user_systems import UserSystems
from app.settings import Settings

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Services:
    pool: WorkerPool  # the processes that run user-driven SymPy and numerics
    users: UserSystems  # derive, simulate and export user systems (caches, fair share, the pool)
    checking: Checking  # judge students' steps (the same pool and fair share)
    gates: Gates  # how many scene simulations, Poincaré sections and mode measurements run at once
    scenes: WorkerPool  # one process for the scenes' runs that step in Python (scipy), off the event loop's GIL
    classes: Classroom  # classes and their recorded attempts (a database, connected at first use)
    answers: Answers  # what the app remembers of scenes' answers and the examples (app/service/answers.py)
    # the scenes' derivations, documents and compiled systems (app/service/chapter/derivations.py); the scenes' worker
    # process (``scenes`` above) keeps its own
    chapter: Scenes

    @classmethod
    def start(cls, config: Settings, chapter: Scenes) -> Services:
        """The services of an app; ``chapter``: the scenes' state it serves (the lifespan gives this process's,
        one copy of the chapter's SymPy objects and systems per process, shared with the code the app does not
        reach, docs/state.md; a test may give its own)."""
        pool = WorkerPool(config.worker_count, config.job_memory_mb, retire_mb=config.retire_rss_mb)
        users = UserSystems(pool, config=config)
        # a scene's run that steps in Python (scipy) holds the GIL for its whole run: in the web
        # process it would delay the event loop.  It goes to a worker of its own (in the memory
        # budget, app/settings.py), never queued behind users' derivations in the pool.
        scenes = WorkerPool(
            1, config.scene_worker_mb, retire_mb=config.worker_base_mb + config.scene_worker_mb // 2, users=False
        )
        # a server that compiles in the background (the warm setting) answers from scipy meanwhile
        gates = Gates(offload=scenes.run, answer_while_compiling=config.warm)
        checking = Checking(users, config)
        return cls(
            pool, users, checking, gates, scenes, Classroom(checking, config), Answers.start(config.cache_dir),
            chapter,
        )  # fmt: skip

    def warm(self, after: threading.Thread | None = None) -> threading.Thread:
        """Start the scenes' worker and load the chapter's systems in it (after ``after``, the
        server's own warm-up, which fills the disk caches it reads), so that a first scipy run
        does not wait for a process to start."""

        def warm() -> None:
            if after is not None:
                after.join()
            try:
                self.scenes.run(load_scenes, timeout=120)
            except Exception:  # noqa: BLE001 - optional: the first run starts the worker itself
                log.warning("the scenes' worker could not be warmed", exc_info=True)

        thread = threading.Thread(target=warm, name="warm-scenes-worker", daemon=True)
        thread.start()
        return thread

    def stop(self) -> None:
        """Stop the worker pools and join their processes (a job still running is killed)."""
        self.pool.stop()
        self.scenes.stop()
        self.classes.stop()
