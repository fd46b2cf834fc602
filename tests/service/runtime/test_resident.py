"""The memory budget with the web processes' measured size: a grown web process shrinks the next workers' share."""

import os
import subprocess
import sys

import pytest

from app.service.runtime import resident
from app.settings import Settings


@pytest.fixture
def config(tmp_path):
    """Settings whose cache folder (where the sizes are recorded) is the test's own."""
    return Settings(cache_dir=tmp_path)


@pytest.fixture
def folder(config):
    return config.cache_dir / resident.FOLDER


def test_a_web_process_records_its_resident_size(config, folder):
    resident.record(config=config)
    written = int((folder / str(os.getpid())).read_text())
    assert written == resident.resident_mb() > 10
    assert resident.measured_web_mb(config) == written


def test_an_ended_process_no_longer_counts(config, folder):
    ended = subprocess.Popen([sys.executable, "-c", "pass"])
    ended.wait()
    folder.mkdir(parents=True)
    (folder / str(ended.pid)).write_text("9999")
    assert resident.measured_web_mb(config) == 0 and not (folder / str(ended.pid)).exists()


def test_the_job_cap_uses_the_measured_size_when_it_is_larger(tmp_path, folder):
    config = Settings(memory_budget_mb=4000, web_processes=2, workers=1, web_process_mb=350, cache_dir=tmp_path)
    assumed = config.job_memory_mb
    folder.mkdir(parents=True)
    (folder / str(os.getpid())).write_text("500")  # this (live) process grew to 500 MB
    measured = resident.job_memory_mb(config)
    # the per-process share left for one job shrinks by exactly the growth
    assert measured == assumed - 150 == config.model_copy(update={"web_process_mb": 500}).job_memory_mb
    (folder / str(os.getpid())).write_text("200")  # smaller than configured: the configured size stands
    assert resident.job_memory_mb(config) == assumed
