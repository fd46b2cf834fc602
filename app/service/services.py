"""The long-lived services of one running app, built at its start and stopped at its end.

``app.main``'s lifespan builds one ``Services`` and hands it to the routes as
lifespan state (``app.web.deps`` reads it from the request); nothing here is a
module global, so two apps (or a test's own service) never share a pool by accident.
The worker pool's processes start with the first user job, not here.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.service.checking import Checking
from app.service.simulation import Gates
from app.service.user_systems import UserSystems
from app.service.worker import WorkerPool
from app.settings import Settings


@dataclass(frozen=True)
class Services:
    pool: WorkerPool  # the processes that run user-driven SymPy and numerics
    users: UserSystems  # derive, simulate and export user systems (caches, fair share, the pool)
    checking: Checking  # judge students' steps (the same pool and fair share)
    gates: Gates  # how many scene simulations, Poincaré sections and mode measurements run at once

    @classmethod
    def start(cls, config: Settings) -> Services:
        pool = WorkerPool(config.worker_count, config.job_memory_mb, retire_mb=config.retire_rss_mb)
        users = UserSystems(pool, config=config)
        # a scene's run that steps in Python (scipy) goes to the pool while no user job runs or waits
        # there: in the web process it would hold the GIL the event loop needs
        gates = Gates(offload=pool.run, worker_free=lambda: users.gate.in_flight + users.gate.waiting < pool.workers)
        return cls(pool, users, Checking(users, config), gates)

    def stop(self) -> None:
        """Stop the worker pool and join its processes (a job still running is killed)."""
        self.pool.stop()
