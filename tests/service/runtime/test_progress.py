"""A job's progress file: written whole as each part begins, read back with how long, gone when the job ends."""

from __future__ import annotations

import pytest

from app.engine.algebra import progress as engine_progress
from app.service.runtime import progress

KEY = "ab" * 32


@pytest.fixture
def folder(tmp_path, monkeypatch):
    monkeypatch.setattr(progress, "folder", lambda: tmp_path)
    return tmp_path


def test_the_part_is_read_while_the_job_runs_and_gone_after(folder):
    assert progress.read(KEY) is None
    with progress.reported(KEY):
        first = progress.read(KEY)
        assert first["part"] == progress.FIRST and first["seconds"] >= 0 and first["part_seconds"] >= 0
        engine_progress.now("Hamilton's equations")
        assert progress.read(KEY)["part"] == "Hamilton's equations"
        assert [p.name for p in folder.iterdir()] == [f"{KEY}.json"]  # no half-written spare left behind
    assert progress.read(KEY) is None and list(folder.iterdir()) == []


def test_the_file_goes_when_the_job_fails(folder):
    with pytest.raises(RuntimeError), progress.reported(KEY):
        raise RuntimeError("the job failed")
    assert list(folder.iterdir()) == []


@pytest.mark.parametrize("key", ["", "../../etc/passwd", "AB" * 32, "ab" * 33])
def test_only_a_derivations_key_names_a_file(folder, key):
    with pytest.raises(ValueError):
        progress.read(key)


def test_a_file_left_by_a_killed_worker_is_not_read_as_running(folder):
    import json
    import subprocess
    import sys

    gone = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    (folder / f"{KEY}.json").write_text(json.dumps({"part": "the normal modes", "since": 0, "started": 0,
                                                   "pid": int(gone.stdout)}))  # fmt: skip
    assert progress.read(KEY) is None and list(folder.iterdir()) == []
