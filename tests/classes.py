"""Helpers of the classes' tests: a ``Classroom`` on SQLite (a temp dir) or on the test PostgreSQL cluster."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from app.service.classroom.service import Classroom
from app.service.tutor.checking import Checking
from app.settings import Settings

BACKENDS = ("sqlite", "postgresql")


def settings_for(backend: str, tmp: Path, postgres: Callable[[], str] | None, **extra) -> Settings:
    if backend == "sqlite":
        return Settings(data_dir=tmp, **extra)
    assert postgres is not None
    return Settings(data_dir=tmp, database_url=postgres(), **extra)


def classroom(checking: Checking, backend: str, tmp: Path, postgres, **extra) -> Classroom:
    return Classroom(checking, settings_for(backend, tmp, postgres, **extra))
