"""The classes' database: untouched until used, migrated from empty and from the previous schema, WAL mode,
commits on disk, retention."""

from __future__ import annotations

import sqlite3
from datetime import timedelta

import pytest
from sqlalchemy import func, inspect, select, text
from sqlalchemy.exc import IntegrityError

from app.errors import Refused, WrongKey
from app.service.classroom import store
from app.service.classroom.database import Database, database_url, make_engine, migrate, now
from app.service.classroom.models import AttemptRow, ClassRow
from app.settings import Settings
from tests.postgres import postgres_server  # noqa: F401 - the session fixture

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

TABLES = {"classes", "students", "assignments", "attempts", "class_assignments", "hints", "alembic_version"}
HEAD = "0010"  # the newest revision


@pytest.fixture(params=["sqlite", "postgresql"])
def url(request, tmp_path):
    if request.param == "sqlite":
        return database_url(Settings(data_dir=tmp_path))
    return request.getfixturevalue("postgres_server")()


def test_nothing_is_touched_before_first_use(tmp_path):
    db = Database(Settings(data_dir=tmp_path / "data"))
    assert not db.started
    assert not (tmp_path / "data").exists()
    code, *_ = store.create_class(db, "first use")
    assert db.started and (tmp_path / "data" / "classes.sqlite3").is_file()
    assert len(code) == 6
    db.stop()


def test_migrates_an_empty_database_to_the_models(url):
    engine = make_engine(url)
    try:
        migrate(engine)
        found = inspect(engine)
        assert TABLES <= set(found.get_table_names())
        assert {"mistake", "mistake_name"} <= {c["name"] for c in found.get_columns("attempts")}
        with engine.connect() as c:
            assert c.execute(text("SELECT version_num FROM alembic_version")).scalar() == HEAD
        migrate(engine)  # again: nothing to do
    finally:
        engine.dispose()


def test_migrates_the_previous_schema_keeping_its_rows(url):
    engine = make_engine(url)
    try:
        migrate(engine, "0001")
        assert "assignments" not in inspect(engine).get_table_names()
        with engine.begin() as c:
            c.execute(text("INSERT INTO classes (id, code, title, teacher_hash, created_at) "
                           "VALUES (1, 'ACEFHK', 'old', :h, :t)"), {"h": "0" * 64, "t": now()})
            c.execute(text("INSERT INTO students (id, class_id, name, key_hash, joined_at) "
                           "VALUES (1, 1, 'Ada', :h, :t)"), {"h": "1" * 64, "t": now()})
            c.execute(text("INSERT INTO attempts (class_id, student_id, item, step, coordinate, verdict, answer, at) "
                           "VALUES (1, 1, 'simple-pendulum', 'kinetic', NULL, 'incorrect', 'm*x', :t)"), {"t": now()})
        migrate(engine)
        with engine.connect() as c:
            row = c.execute(text("SELECT item, verdict, mistake, answer FROM attempts")).one()
            assert tuple(row) == ("simple-pendulum", "incorrect", None, "m*x")
            assert c.execute(text("SELECT count(*) FROM assignments")).scalar() == 0
    finally:
        engine.dispose()


def test_migrates_the_schema_before_mistake_names_keeping_the_keys(url):
    engine = make_engine(url)
    try:
        migrate(engine, "0002")
        with engine.begin() as c:
            c.execute(text("INSERT INTO classes (id, code, title, teacher_hash, created_at) "
                           "VALUES (1, 'ACEFHK', 'old', :h, :t)"), {"h": "0" * 64, "t": now()})
            c.execute(text("INSERT INTO students (id, class_id, name, key_hash, joined_at) "
                           "VALUES (1, 1, 'Ada', :h, :t)"), {"h": "1" * 64, "t": now()})
            c.execute(text("INSERT INTO attempts (class_id, student_id, item, step, coordinate, verdict, mistake, "
                           "answer, at) VALUES (1, 1, 'simple-pendulum', 'kinetic', NULL, 'incorrect', 'missing_half', "
                           "'m*x', :t)"), {"t": now()})
        migrate(engine)
        with engine.connect() as c:
            row = c.execute(text("SELECT mistake, mistake_name FROM attempts")).one()
            assert tuple(row) == ("missing_half", None)
    finally:
        engine.dispose()


def test_sqlite_runs_in_wal_mode_and_commits_reach_the_file(tmp_path):
    db = Database(Settings(data_dir=tmp_path))
    code, *_ = store.create_class(db, "wal")
    with db.session() as session:
        assert session.execute(text("PRAGMA journal_mode")).scalar() == "wal"
        assert session.execute(text("PRAGMA synchronous")).scalar() == 2  # FULL
    # another connection (as another process would open) sees the committed row at once
    with sqlite3.connect(tmp_path / "classes.sqlite3") as other:
        assert other.execute("SELECT code FROM classes").fetchall() == [(code,)]
    db.stop()


def test_classes_older_than_the_retention_are_deleted(url, tmp_path):
    db = Database(Settings(data_dir=tmp_path, database_url=url, class_days=30))
    old, *_ = store.create_class(db, "last year")
    new, *_ = store.create_class(db, "this week")
    _, who, _code = store.join(db, old, "Ada")
    store.record(db, who, "simple-pendulum", "kinetic", None, "correct", None, "T")
    with db.session() as session:
        session.execute(ClassRow.__table__.update().where(ClassRow.code == old).values(created_at=now() - timedelta(days=31)))
    db._purged_at = None  # the hourly look is due
    assert db.purge_expired() == 1
    with db.session() as session:
        assert session.scalars(select(ClassRow.code)).all() == [new]
        assert session.scalars(select(AttemptRow.id)).all() == []
    db.stop()


def test_migrates_the_schema_before_attempt_ids_keeping_the_attempts(url):
    engine = make_engine(url)
    try:
        migrate(engine, "0003")
        with engine.begin() as c:
            c.execute(text("INSERT INTO classes (id, code, title, teacher_hash, created_at) "
                           "VALUES (1, 'ACEFHK', 'old', :h, :t)"), {"h": "0" * 64, "t": now()})
            c.execute(text("INSERT INTO students (id, class_id, name, key_hash, joined_at) "
                           "VALUES (1, 1, 'Ada', :h, :t)"), {"h": "1" * 64, "t": now()})
            for _ in range(2):  # two attempts recorded before ids: both stay
                c.execute(text("INSERT INTO attempts (class_id, student_id, item, step, coordinate, verdict, answer, "
                               "at) VALUES (1, 1, 'simple-pendulum', 'kinetic', NULL, 'incorrect', 'm*x', :t)"),
                          {"t": now()})
        migrate(engine)
        insert = text("INSERT INTO attempts (class_id, student_id, item, step, verdict, answer, at, attempt_id) "
                      "VALUES (1, 1, 'simple-pendulum', 'kinetic', 'correct', 'T', :t, 'press-one')")
        with engine.begin() as c:
            assert c.execute(text("SELECT count(*) FROM attempts WHERE attempt_id IS NULL")).scalar() == 2
            c.execute(insert, {"t": now()})
        with pytest.raises(IntegrityError), engine.begin() as c:  # the same student's id twice: refused by the table
            c.execute(insert, {"t": now()})
        with engine.connect() as c:
            assert c.execute(text("SELECT version_num FROM alembic_version")).scalar() == HEAD
    finally:
        engine.dispose()


def test_a_press_recorded_twice_at_once_keeps_the_first(tmp_path):
    """Two copies of one press that both were judged (a retry racing the first to the database): the second
    insert meets the unique id, records nothing and gets the first verdict back."""
    db = Database(Settings(data_dir=tmp_path))
    code, *_ = store.create_class(db, "race")
    _, who, _code = store.join(db, code, "Ada")
    first = store.record(db, who, "simple-pendulum", "kinetic", None, "incorrect", "missing_half", "T", None,
                         "press-0001", b'{"verdict":"incorrect"}')
    second = store.record(db, who, "simple-pendulum", "kinetic", None, "incorrect", "missing_half", "T", None,
                          "press-0001", b'{"verdict":"incorrect","second":true}')
    assert first is None and second is not None and second.response == b'{"verdict":"incorrect"}'
    with db.session() as session:
        assert session.scalar(select(func.count()).select_from(AttemptRow)) == 1
    db.stop()


def test_migrates_the_single_assignment_into_the_first_of_a_series(url, tmp_path):
    """Revision 0005: a class's assignment becomes assignment 1 of its series (with its attempts at its items);
    a class with no assignment gets no series, and an attempt at an item outside the assignment stays unassigned."""
    engine = make_engine(url)
    try:
        migrate(engine, "0004")
        with engine.begin() as c:
            for class_id, code in ((1, "ACEFHK"), (2, "MNPRTW")):
                c.execute(text("INSERT INTO classes (id, code, title, teacher_hash, created_at) "
                               "VALUES (:i, :c, 'old', :h, :t)"), {"i": class_id, "c": code, "h": str(class_id) * 64,
                                                                    "t": now()})
            c.execute(text("INSERT INTO students (id, class_id, name, key_hash, joined_at) "
                           "VALUES (1, 1, 'Ada', :h, :t)"), {"h": "a" * 64, "t": now()})
            c.execute(text("INSERT INTO assignments (class_id, position, item, system, steps, parameters) VALUES "
                           "(1, 0, 'simple-pendulum', NULL, :s, '{}')"),
                      {"s": '[{"step": "kinetic", "coordinate": null}]'})
            for item in ("simple-pendulum", "double-pendulum"):
                c.execute(text("INSERT INTO attempts (class_id, student_id, item, step, coordinate, verdict, answer, "
                               "at) VALUES (1, 1, :i, 'kinetic', NULL, 'correct', 'T', :t)"), {"i": item, "t": now()})
        migrate(engine)
        with engine.connect() as c:
            assert c.execute(text("SELECT version_num FROM alembic_version")).scalar() == HEAD
            heads = c.execute(text("SELECT id, class_id, position, title, due FROM class_assignments")).all()
            assert [tuple(h)[1:] for h in heads] == [(1, 0, "Assignment 1", None)]
            first = heads[0][0]
            assert c.execute(text("SELECT assignment_id FROM assignments")).scalars().all() == [first]
            got = c.execute(text("SELECT item, assignment_id FROM attempts ORDER BY id")).all()
            assert [tuple(g) for g in got] == [("simple-pendulum", first), ("double-pendulum", None)]
            assert c.execute(text("SELECT recovery_hash FROM classes")).scalars().all() == [None, None]
    finally:
        engine.dispose()
    # the store reads the migrated class as a series of one
    db = Database(Settings(data_dir=tmp_path, database_url=url))
    try:
        found = store.series(db, 1)
        assert [(a["n"], a["title"], a["due"]) for a in found] == [(1, "Assignment 1", None)]
        assert found[0]["items"] == [{"scene": "simple-pendulum", "steps": [{"step": "kinetic", "coordinate": None}],
                                      "parameters": {}}]
        assert store.series(db, 2) == [] and store.assignment(db, 2) == []
        # a class from before recovery codes: no recovery code opens it
        with pytest.raises(WrongKey):
            store.recover(db, "ACEFHK", "ACEF-HKMN-PRTW-XY34-79AC-EFHK")
    finally:
        db.stop()


def test_downgrade_from_the_series_keeps_the_first_assignment(url):
    engine = make_engine(url)
    try:
        migrate(engine)
        with engine.begin() as c:
            c.execute(text("INSERT INTO classes (id, code, title, teacher_hash, created_at) "
                           "VALUES (1, 'ACEFHK', 'new', :h, :t)"), {"h": "0" * 64, "t": now()})
            for position in (0, 1):
                c.execute(text("INSERT INTO class_assignments (id, class_id, position, title) "
                               "VALUES (:i, 1, :p, 'week')"), {"i": position + 1, "p": position})
                c.execute(text("INSERT INTO assignments (class_id, assignment_id, position, item, steps, parameters) "
                               "VALUES (1, :a, 0, :item, '[]', '{}')"),
                          {"a": position + 1, "item": f"scene-{position}"})
        with engine.begin() as c:
            from alembic import command

            from app.service.classroom.database import alembic_config
            command.downgrade(alembic_config(c), "0004")
        with engine.connect() as c:
            assert c.execute(text("SELECT item FROM assignments")).scalars().all() == ["scene-0"]
            assert "class_assignments" not in inspect(engine).get_table_names()
    finally:
        engine.dispose()


def test_migrates_the_schema_before_logins_keeping_its_students_and_back(url):
    engine = make_engine(url)
    try:
        migrate(engine, "0007")
        with engine.begin() as c:
            c.execute(text("INSERT INTO classes (id, code, title, teacher_hash, created_at) "
                           "VALUES (1, 'ACEFHK', 'old', :h, :t)"), {"h": "0" * 64, "t": now()})
            c.execute(text("INSERT INTO students (id, class_id, name, key_hash, joined_at, recovery_hash) "
                           "VALUES (1, 1, 'Ada', :h, :t, :r)"), {"h": "1" * 64, "t": now(), "r": "2" * 64})
        migrate(engine)
        with engine.connect() as c:
            # a class from before asks for no login; its students have none, and keep their recovery codes
            assert c.execute(text("SELECT login_column FROM classes")).one() == (None,)
            assert tuple(c.execute(text("SELECT name, login, recovery_hash FROM students")).one()) == ("Ada", None, "2" * 64)
            assert c.execute(text("SELECT version_num FROM alembic_version")).scalar() == HEAD
        with engine.begin() as c:
            c.execute(text("UPDATE students SET login = 'alovelace'"))
        with engine.begin() as c:
            from alembic import command

            from app.service.classroom.database import alembic_config
            command.downgrade(alembic_config(c), "0007")
        with engine.connect() as c:
            assert c.execute(text("SELECT name FROM students")).scalars().all() == ["Ada"]
            assert "login" not in {col["name"] for col in inspect(engine).get_columns("students")}
    finally:
        engine.dispose()


def test_two_equal_pseudonyms_cannot_both_be_written_even_past_the_check(url, tmp_path, monkeypatch):
    """The race the check in Python cannot close (two replicas each reading the class before the other writes):
    with the check made blind, the database's unique key still refuses "grace" beside "Grace"."""
    database = Database(Settings(data_dir=tmp_path, database_url=url))
    code, *_ = store.create_class(database, "race")
    store.join(database, code, "Grace")
    # each replica's read saw no "Grace" yet: the check in Python passes
    monkeypatch.setattr(store, "_same_pseudonym", lambda names, name: None)
    monkeypatch.setattr(store, "pseudonym_key", lambda name: name)
    monkeypatch.setattr(store, "pseudonym_digest", _digest_of_folded)
    with pytest.raises(Refused) as refused:
        store.join(database, code, "grace")
    assert "taken" in str(refused.value)
    database.stop()


def _digest_of_folded(name):
    import hashlib
    import unicodedata

    return hashlib.sha256(unicodedata.normalize("NFKC", unicodedata.normalize("NFKC", name.strip()).casefold()).encode()).hexdigest()


def test_migrates_the_schema_before_pseudonym_keys_keeping_case_twins_apart(url):
    engine = make_engine(url)
    try:
        migrate(engine, "0009")
        with engine.begin() as c:
            c.execute(text("INSERT INTO classes (id, code, title, teacher_hash, created_at) "
                           "VALUES (1, 'ACEFHK', 'old', :h, :t)"), {"h": "0" * 64, "t": now()})
            for sid, name in [(1, "Grace"), (2, "grace"), (3, "Ada")]:
                c.execute(text("INSERT INTO students (id, class_id, name, key_hash, joined_at) "
                               "VALUES (:i, 1, :n, :h, :t)"), {"i": sid, "n": name, "h": str(sid) * 64, "t": now()})
        migrate(engine)
        with engine.connect() as c:
            keys_ = dict(c.execute(text("SELECT name, name_key FROM students")).all())
        # the first to join keeps the key; its case twin from before the rule keeps its record, without one
        assert keys_["Grace"] == store.pseudonym_digest("grace") and keys_["grace"] is None
        assert keys_["Ada"] == store.pseudonym_digest("ADA")
        with engine.begin() as c:
            from alembic import command

            from app.service.classroom.database import alembic_config
            command.downgrade(alembic_config(c), "0009")
        assert "name_key" not in {col["name"] for col in inspect(engine).get_columns("students")}
        with engine.connect() as c:
            assert sorted(c.execute(text("SELECT name FROM students")).scalars()) == ["Ada", "Grace", "grace"]
    finally:
        engine.dispose()
