"""The settings: one place, read from LAGRANGE_ variables, the table in docs/deployment.md generated from it; the memory
budget and the process counts derived from the container's cgroup."""

import os
import subprocess
import sys

import pytest

from app import settings as module
from app.settings import MIN_JOB_MB, ROOT, Settings


def test_a_setting_is_read_from_its_lagrange_variable(monkeypatch):
    monkeypatch.setenv("LAGRANGE_DERIVE_SECONDS", "12.5")
    monkeypatch.setenv("LAGRANGE_WARM", "0")
    read = Settings()
    assert read.derive_seconds == 12.5 and read.warm is False


@pytest.mark.slow
def test_the_docs_list_every_setting_as_settings_defines_it():
    check = subprocess.run(
        [sys.executable, "scripts/settings_table.py", "--check"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"},
    )
    assert check.returncode == 0, check.stdout + check.stderr


@pytest.fixture
def cgroup(monkeypatch):
    files = {}
    monkeypatch.setattr(module, "_read", lambda path: files.get(path))
    return files


def test_cpus_come_from_the_quota_and_memory_from_the_limit(cgroup):
    cgroup["/sys/fs/cgroup/cpu.max"] = "150000 100000"  # 1.5 CPUs: 2 to run on
    cgroup["/sys/fs/cgroup/memory.max"] = str(2 * 2**30)
    assert module.container_cpus() == min(2, len(os.sched_getaffinity(0)))
    assert module.container_memory_mb() == 2048
    s = Settings()
    assert s.budget_mb == int(0.9 * 2048)
    assert s.worst_case_mb <= s.budget_mb


def test_no_limit_means_the_machines(cgroup):
    cgroup["/sys/fs/cgroup/cpu.max"] = "max 100000"
    assert module.container_cpus() >= 1 and module.container_memory_mb() > 0


@pytest.mark.parametrize("budget", [1200, 2000, 4000, 16000])
@pytest.mark.parametrize("processes", [1, 2, 4])
def test_the_caps_fit_the_budget_or_take_the_smallest_useful_job(budget, processes):
    s = Settings(memory_budget_mb=budget, web_processes=processes)
    assert 128 <= s.job_memory_mb <= 1024
    assert s.worst_case_mb <= budget or (s.worker_count == 1 and s.job_memory_mb == MIN_JOB_MB)


def test_a_configured_job_cap_that_does_not_fit_is_lowered():
    s = Settings(memory_budget_mb=2000, web_processes=1, workers=2, worker_memory_mb=1024)
    assert s.job_memory_mb < 1024 and s.worst_case_mb <= 2000


def test_several_replicas_need_a_shared_database_and_secret():
    from pydantic import ValidationError

    from app.settings import Settings

    with pytest.raises(ValidationError, match="replicas=2 needs database_url"):
        Settings(replicas=2, session_secret="s" * 32)
    with pytest.raises(ValidationError, match="replicas=2 needs database_url"):
        Settings(replicas=2, session_secret="s" * 32, database_url="sqlite:///x.sqlite3")
    with pytest.raises(ValidationError, match="replicas=3 needs session_secret"):
        Settings(replicas=3, database_url="postgresql://db/lagrange")
    assert Settings(replicas=2, database_url="postgresql://db/lagrange", session_secret="s" * 32).replicas == 2


def test_trusted_proxies_are_addresses_or_ranges():
    from pydantic import ValidationError

    from app.settings import Settings

    assert Settings(trusted_proxies="10.0.0.0/8, fd00::/8, 127.0.0.1").trusted_proxies
    with pytest.raises(ValidationError, match="'proxy.local' is not an address or a CIDR range"):
        Settings(trusted_proxies="127.0.0.1,proxy.local")
