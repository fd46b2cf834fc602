"""Every setting of the server, in one place, read once from the environment.

Each field is set by an environment variable ``LAGRANGE_<NAME>`` (``LAGRANGE_WORKERS=4``);
the defaults suit a classroom machine.  Code reads ``settings()``, never ``os.environ``;
tests build their own ``Settings(...)`` and override the app's through its dependencies.
This module sits left of every layer: it imports nothing from ``app``.
"""

from __future__ import annotations

import os
from functools import lru_cache
from pathlib import Path

from pydantic import Field
from pydantic_settings import BaseSettings, SettingsConfigDict

# The source tree: templates, static files and the default cache live beside ``app``.  An
# installed package (the Docker image) runs from its working directory instead.
_HERE = Path(__file__).resolve().parents[1]
ROOT = _HERE if (_HERE / "templates").is_dir() else Path.cwd()


class Settings(BaseSettings):
    """The server's settings; ``LAGRANGE_`` + the field's name in capitals sets each one."""

    model_config = SettingsConfigDict(env_prefix="LAGRANGE_", frozen=True, extra="ignore")

    cache_dir: Path = Field(default=ROOT / ".cache", description="compiled kernels, generated code, cached derivations")
    workers: int = Field(default=0, ge=0, description="worker processes for users' systems; 0: min(2, CPUs)")
    worker_memory_mb: int = Field(default=1024, gt=0, description="address space one job may add to its worker")
    derive_seconds: float = Field(default=30.0, gt=0, description="hard time limit of a user system's derivation")
    simulate_seconds: float = Field(default=30.0, gt=0, description="hard time limit of a user system's simulation")
    check_seconds: float = Field(default=10.0, gt=0, description="hard time limit of checking a student's step")
    session_secret: str | None = Field(default=None, description="key that signs session cookies; else a file in the cache")
    warm: bool = Field(default=True, description="compile kernels and fill caches in the background at start-up")

    @property
    def worker_count(self) -> int:
        return self.workers or min(2, os.cpu_count() or 1)


@lru_cache(maxsize=1)
def settings() -> Settings:
    """The settings of this process, read from the environment the first time they are asked for."""
    return Settings()
