"""Every setting of the server, in one place, read once from the environment.

Each field is set by an environment variable ``LAGRANGE_<NAME>`` (``LAGRANGE_WORKERS=4``);
the defaults suit a classroom machine.  Code reads ``settings()``, never ``os.environ``;
tests build their own ``Settings(...)`` and override the app's through its dependencies.
This module sits left of every layer: it imports nothing from ``app``.
"""

from __future__ import annotations

import ipaddress
import os
import re
from functools import lru_cache
from pathlib import Path
from typing import Annotated

from pydantic import (
    Field,
    NonNegativeFloat,
    NonNegativeInt,
    PositiveFloat,
    PositiveInt,
    field_validator,
    model_validator,
)
from pydantic_settings import BaseSettings, SettingsConfigDict

# The source tree: templates, static files and the default cache live beside ``app``.  An
# installed package (the Docker image) runs from its working directory instead.
_HERE = Path(__file__).resolve().parents[1]
ROOT = _HERE if (_HERE / "templates").is_dir() else Path.cwd()
# a site's origin as a CSP source: scheme, host (its first label may be *), optional port, nothing else
ORIGIN = re.compile(r"https?://(\*\.)?[A-Za-z0-9-]+(\.[A-Za-z0-9-]+)*(:[0-9]{1,5})?")


class Settings(BaseSettings):
    """The server's settings; ``LAGRANGE_`` + the field's name in capitals sets each one."""

    # each field's docstring is its description (the settings table in docs/deployment.md shows it)
    model_config = SettingsConfigDict(
        env_prefix="LAGRANGE_", frozen=True, extra="ignore", use_attribute_docstrings=True
    )

    cache_dir: Path = ROOT / ".cache"
    """compiled kernels, generated code, cached derivations"""
    workers: NonNegativeInt = 0
    """worker processes per web process; 0: two where memory allows"""
    worker_memory_mb: NonNegativeInt = 0
    """memory one job may add to its worker; 0: from the budget"""
    web_processes: NonNegativeInt = 0
    """uvicorn processes (scripts/serve.sh sets it); 0: from CPUs"""
    memory_budget_mb: NonNegativeInt = 0
    """memory for the whole server; 0: 90 % of the container's"""
    web_process_mb: PositiveInt = 350
    """resident memory allowed for one web process"""
    worker_base_mb: PositiveInt = 250
    """resident memory of an idle worker (engine and numerics loaded)"""
    scene_worker_mb: Annotated[int, Field(ge=64)] = 128
    """memory a scene's Python-loop run (scipy) may add to its worker"""
    queue_seconds: PositiveFloat = 35.0
    """longest wait for a worker before a 503 (over the job limit: one job ends meanwhile)"""
    scene_queue_seconds: NonNegativeFloat = 0.5
    """longest wait for a scene simulation slot (then 429)"""
    user_cache_mb: PositiveInt = 64
    """disk for user systems' generated code and compiled cache"""
    header_seconds: PositiveFloat = 10.0
    """time a client has to send a request's headers"""
    keep_alive_seconds: PositiveInt = 75
    """time an idle connection waits for its next request"""
    connections: PositiveInt = 400
    """open connections and requests per web process; then 503"""
    connections_per_address: PositiveInt = 150
    """open connections from one address per web process; then 503"""
    slow_per_address: PositiveInt = 32
    """answers one address may leave unread at once (beyond: closed)"""
    write_seconds: PositiveFloat = 20.0
    """time an answer may wait for a client that does not read it"""
    body_seconds: PositiveFloat = 10.0
    """time a client has to send a request's body"""
    derive_seconds: PositiveFloat = 30.0
    """hard time limit of a user system's derivation"""
    simulate_seconds: PositiveFloat = 30.0
    """hard time limit of a user system's simulation"""
    check_seconds: PositiveFloat = 10.0
    """hard time limit of checking a student's step"""
    proxy_header: str = ""
    """header naming the client behind a trusted reverse proxy (X-Forwarded-For); empty: none"""
    trusted_proxies: str = "127.0.0.1,::1"
    """addresses or CIDR ranges of the reverse proxies whose proxy_header is believed"""
    session_secret: str | None = None
    """key that signs session cookies (the same for every replica); else a file in the cache"""
    shared_store_url: str | None = None
    """Redis URL (redis://host:6379/0) where all replicas count the classes' joins and checks; else each its own"""
    replicas: PositiveInt = 1
    """servers sharing the classes (more than 1 needs database_url and session_secret)"""
    warm: bool = True
    """compile kernels and fill caches in the background at start-up"""
    data_dir: Path = ROOT / ".data"
    """classes' SQLite database (a volume in the image)"""
    database_url: str | None = None
    """a PostgreSQL URL for the classes (shared by replicas); else SQLite in data_dir"""
    class_days: PositiveInt = 180
    """days a class and its record are kept, then deleted"""
    class_joins_per_minute: PositiveInt = 300
    """joins one class accepts per minute"""
    class_checks_per_minute: PositiveInt = 3000
    """checks one class records per minute"""
    client_joins_per_minute: PositiveInt = 20
    """joins one client may make per minute"""
    student_checks_per_minute: PositiveInt = 30
    """checks one student may make per minute"""
    class_check_slots: PositiveInt = 24
    """a class's checks in flight at once (judged or queued), whatever its network"""
    embed_ancestors: str = ""
    """sites whose pages may show /embed/ pages in a frame, comma-separated (https://lms.example.edu); empty: none"""
    source_notes: bool = True
    """pages name the source notes (section line, contents paragraph, table of their misprints); 0: a course from another book"""

    @field_validator("trusted_proxies")
    @classmethod
    def _proxies_are_addresses(cls, listed: str) -> str:
        for entry in (a.strip() for a in listed.split(",") if a.strip()):
            try:
                ipaddress.ip_network(entry, strict=False)
            except ValueError:
                raise ValueError(
                    f"trusted_proxies: {entry!r} is not an address or a CIDR range (e.g. 10.0.0.0/8, fd00::/8)"
                ) from None
        return listed

    @field_validator("shared_store_url")
    @classmethod
    def _store_is_redis(cls, url: str | None) -> str | None:
        if url and not url.startswith(("redis://", "rediss://", "unix://")):
            raise ValueError(
                f"shared_store_url: {url[:60]!r} is not a Redis URL (redis://host:6379/0, rediss://… or unix://…)"
            )
        return url or None

    @field_validator("embed_ancestors")
    @classmethod
    def _ancestors_are_origins(cls, listed: str) -> str:
        # a CSP source list: origins only (a path, a quote or a space would change what the header says)
        for entry in (a.strip() for a in listed.split(",") if a.strip()):
            if not ORIGIN.fullmatch(entry):
                raise ValueError(
                    f"embed_ancestors: {entry[:60]!r} is not a site's origin: write scheme://host[:port], "
                    "e.g. https://lms.example.edu or https://*.example.edu"
                )
        return ",".join(a.strip() for a in listed.split(",") if a.strip())

    @model_validator(mode="after")
    def _replicas_share_the_classes(self) -> Settings:
        # replicas must see one record of the classes and honour each other's session cookies
        if self.replicas > 1 and (not self.database_url or self.database_url.startswith("sqlite")):
            raise ValueError(
                f"replicas={self.replicas} needs database_url (PostgreSQL): on SQLite each replica would keep a "
                "record of its own, and a teacher and her students could land in different classes"
            )
        if self.replicas > 1 and not self.session_secret:
            raise ValueError(
                f"replicas={self.replicas} needs session_secret, the same on every replica: else a session cookie "
                "made by one replica is a stranger to the others"
            )
        return self

    # The memory budget (docs/deployment.md, "Capacity").  With P web processes, each with a forkserver, one
    # worker for the scenes' Python-loop runs (capped at S = scene_worker_mb) and W pool workers for
    # users' jobs, and a job cap J, the most resident memory the server can reach is
    #     P * (web_process_mb + worker_base_mb + (worker_base_mb + S) + W * (worker_base_mb + J))  <=  budget,
    # so J defaults to the largest value that fits (at most 1024 MB), and a W that leaves a job
    # less than 128 MB is lowered until it does not (a configured J that does not fit, too).  A worker that ends a job above
    # worker_base_mb + J / 2 resident retires (app/service/runtime/worker.py).  P defaults to one per
    # CPU (at most 2), fewer if the budget cannot give each a worker with a 128 MB job.
    @property
    def web_process_count(self) -> int:
        if self.web_processes:
            return self.web_processes
        wanted = min(2, container_cpus())
        while wanted > 1 and self._per_worker_mb(1, wanted) < MIN_JOB_MB:  # a small container: fewer processes
            wanted -= 1
        return wanted

    @property
    def budget_mb(self) -> int:
        return self.memory_budget_mb or int(0.9 * container_memory_mb())

    def _per_worker_mb(self, workers: int, processes: int | None = None) -> int:
        """J for W = ``workers`` and P = ``processes`` (or the process count): the budget's inequality solved."""
        processes = processes or self.web_process_count
        per_process = self.budget_mb // processes - self.web_process_mb - self.worker_base_mb - self._scene_worker_mb
        return per_process // workers - self.worker_base_mb

    @property
    def worker_count(self) -> int:
        # two by default (where memory allows), whatever the CPUs: with one, a job that runs to its time limit
        # held every other session's derivation behind it (19 s for a one-link pendulum)
        wanted = self.workers or 2
        # fewer workers, each able to take a useful job (128 MB), rather than many that cannot
        while wanted > 1 and self._per_worker_mb(wanted) < MIN_JOB_MB:
            wanted -= 1
        return wanted

    @property
    def job_memory_mb(self) -> int:
        fits = self._per_worker_mb(self.worker_count)
        wanted = self.worker_memory_mb or MAX_JOB_MB
        return max(MIN_JOB_MB, min(wanted, fits))

    @property
    def worst_case_mb(self) -> int:
        """The left side of the budget's inequality, for these settings."""
        workers = self.worker_count * (self.worker_base_mb + self.job_memory_mb)
        return self.web_process_count * (self.web_process_mb + self.worker_base_mb + self._scene_worker_mb + workers)

    @property
    def _scene_worker_mb(self) -> int:
        """The scenes' worker at its most: an idle worker and one run's cap."""
        return self.worker_base_mb + self.scene_worker_mb

    @property
    def retire_rss_mb(self) -> int:
        return self.worker_base_mb + self.job_memory_mb // 2


MIN_JOB_MB = 128
MAX_JOB_MB = 1024


def _read(path: str) -> str | None:
    try:
        with open(path) as handle:
            return handle.read().strip()
    except OSError:
        return None


def container_cpus() -> int:
    """CPUs this container may use: the cgroup's quota (cpu.max), else the CPUs it may run on."""
    available = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    quota = (_read("/sys/fs/cgroup/cpu.max") or "max").split()
    if quota and quota[0] != "max":
        period = int(quota[1]) if len(quota) > 1 else 100_000
        return max(1, min(available, -(-int(quota[0]) // period)))
    return max(1, available)


def container_memory_mb() -> int:
    """Memory this container may use: the cgroup's limit (memory.max), else the machine's."""
    limit = _read("/sys/fs/cgroup/memory.max")
    if limit and limit.isdigit():
        return int(limit) // 2**20
    return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2**20


@lru_cache(maxsize=1)
def settings() -> Settings:
    """The settings of this process, read from the environment the first time they are asked for."""
    return Settings()
