"""The memory budget with the web processes' measured size: a grown web process shrinks the next workers' share."""

import os
import subprocess
import sys

import pytest

from app.service import resident
from app.settings import Settings


@pytest.fixture
def folder(tmp_path, monkeypatch):
    monkeypatch.setattr(resident, "_folder", lambda: tmp_path / resident.FOLDER)
    return tmp_path / resident.FOLDER


def test_a_web_process_records_its_resident_size(folder):
    resident.record()
    written = int((folder / str(os.getpid())).read_text())
    assert written == resident.resident_mb() > 10
    assert resident.measured_web_mb() == written


def test_an_ended_process_no_longer_counts(folder):
    ended = subprocess.Popen([sys.executable, "-c", "pass"])
    ended.wait()
    folder.mkdir(parents=True)
    (folder / str(ended.pid)).write_text("9999")
    assert resident.measured_web_mb() == 0 and not (folder / str(ended.pid)).exists()


def test_the_job_cap_uses_the_measured_size_when_it_is_larger(folder):
    config = Settings(memory_budget_mb=4000, web_processes=2, workers=1, web_process_mb=350)
    assumed = config.job_memory_mb
    folder.mkdir(parents=True)
    (folder / str(os.getpid())).write_text("500")  # this (live) process grew to 500 MB
    measured = resident.job_memory_mb(config)
    # the per-process share left for one job shrinks by exactly the growth
    assert measured == assumed - 150 == config.model_copy(update={"web_process_mb": 500}).job_memory_mb
    (folder / str(os.getpid())).write_text("200")  # smaller than configured: the configured size stands
    assert resident.job_memory_mb(config) == assumed
