"""The classes' database: its engine, its migrations (at first use, under a lock) and retention.

``Database(config)`` connects nothing until ``session()`` is first called; then
it creates the engine, upgrades the schema to the newest revision (Alembic, the
scripts in ``migrations/``) and deletes the classes older than ``class_days``.
Several web processes may start together: on PostgreSQL the upgrade holds an
advisory lock, on SQLite an exclusive lock on a file beside the database.

SQLite runs in WAL mode (readers never wait for the writer) with
``synchronous=FULL``: a commit has reached the disk before it returns, so an
attempt acknowledged to a student survives a killed server (and a power cut).
Every call here blocks: the service runs them in threads.
"""

from __future__ import annotations

import fcntl
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from datetime import UTC, datetime, timedelta
from pathlib import Path
from typing import Any

from alembic import command
from alembic.config import Config
from sqlalchemy import Engine, create_engine, delete, event, select
from sqlalchemy.orm import Session, sessionmaker

from app.service.classroom.models import (
    AssignmentRow,
    AttemptRow,
    ClassAssignmentRow,
    ClassRow,
    HintRow,
    StudentRow,
)
from app.settings import Settings

MIGRATIONS = Path(__file__).resolve().parent / "migrations"
MIGRATION_LOCK = 7_330_033  # the advisory lock's number on PostgreSQL (any constant the app alone uses)
RETENTION_EVERY = timedelta(hours=1)  # how often a running server looks for expired classes


def now() -> datetime:
    """The current time as stored: naive UTC."""
    return datetime.now(UTC).replace(tzinfo=None)


def database_url(config: Settings) -> str:
    """The configured URL (PostgreSQL through psycopg 3), else the SQLite file in the data directory."""
    url = config.database_url
    if not url:
        return f"sqlite:///{Path(config.data_dir) / 'classes.sqlite3'}"
    for bare in ("postgresql://", "postgres://"):
        if url.startswith(bare):
            return "postgresql+psycopg://" + url[len(bare) :]
    return url


def _sqlite_pragmas(connection: Any, _record: Any) -> None:
    cursor = connection.cursor()
    cursor.execute("PRAGMA journal_mode=WAL")
    cursor.execute("PRAGMA synchronous=FULL")
    cursor.execute("PRAGMA foreign_keys=ON")
    cursor.execute("PRAGMA busy_timeout=30000")
    cursor.close()


def make_engine(url: str) -> Engine:
    if url.startswith("sqlite"):
        path = url.split("///", 1)[1]
        if path and path != ":memory:":
            Path(path).parent.mkdir(parents=True, exist_ok=True)
        engine = create_engine(url, connect_args={"check_same_thread": False, "timeout": 30}, pool_size=8)
        event.listen(engine, "connect", _sqlite_pragmas)
        return engine
    return create_engine(url, pool_size=8, max_overflow=8, pool_pre_ping=True, pool_recycle=1800)


def alembic_config(connection: Any) -> Config:
    config = Config()
    config.set_main_option("script_location", str(MIGRATIONS))
    config.attributes["connection"] = connection
    return config


@contextmanager
def _file_lock(path: Path) -> Iterator[None]:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "a") as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def migrate(engine: Engine, revision: str = "head") -> None:
    """Upgrade the schema to ``revision``, one process at a time."""
    if engine.dialect.name == "sqlite":
        database = engine.url.database or ""
        lock = _file_lock(Path(database + ".lock")) if database and database != ":memory:" else _nothing()
        with lock, engine.begin() as connection:
            command.upgrade(alembic_config(connection), revision)
        return
    with engine.begin() as connection:
        if engine.dialect.name == "postgresql":
            connection.exec_driver_sql(f"SELECT pg_advisory_xact_lock({MIGRATION_LOCK})")
        command.upgrade(alembic_config(connection), revision)


@contextmanager
def _nothing() -> Iterator[None]:
    yield


def delete_class(session: Session, class_id: int) -> None:
    """Remove a class and everything recorded for it (children first: no reliance on ON DELETE CASCADE)."""
    for table in (HintRow, AttemptRow, StudentRow, AssignmentRow, ClassAssignmentRow):
        session.execute(delete(table).where(table.class_id == class_id))
    session.execute(delete(ClassRow).where(ClassRow.id == class_id))


class Database:
    """The engine and sessions of the classes' database, created and migrated at first use."""

    def __init__(self, config: Settings) -> None:
        self.url = database_url(config)
        self.keep = timedelta(days=config.class_days)
        self._engine: Engine | None = None
        self._sessions: sessionmaker[Session] | None = None
        self._lock = threading.Lock()
        self._purged_at: datetime | None = None

    @property
    def started(self) -> bool:
        return self._engine is not None

    def _start(self) -> sessionmaker[Session]:
        with self._lock:
            if self._sessions is None:
                engine = make_engine(self.url)
                migrate(engine)
                self._engine = engine
                self._sessions = sessionmaker(engine, expire_on_commit=False)
            return self._sessions

    @contextmanager
    def session(self) -> Iterator[Session]:
        """A session in a transaction, committed at the end of the block (rolled back on an error)."""
        sessions = self._sessions or self._start()
        self.purge_expired(sessions)
        with sessions.begin() as session:
            yield session

    def purge_expired(self, sessions: sessionmaker[Session] | None = None) -> int:
        """Delete the classes older than the retention (at most once an hour per process); how many went."""
        moment = now()
        if self._purged_at is not None and moment - self._purged_at < RETENTION_EVERY:
            return 0
        self._purged_at = moment
        sessions = sessions or self._sessions or self._start()
        with sessions.begin() as session:
            old = session.scalars(select(ClassRow.id).where(ClassRow.created_at < moment - self.keep)).all()
            for class_id in old:
                delete_class(session, class_id)
        return len(old)

    def stop(self) -> None:
        if self._engine is not None:
            self._engine.dispose()
