"""A worker that ends before its job says what ended it: a signal is named, and never blamed on memory."""

import os
import signal

import pytest

from app.service.runtime.worker import JobFailed, WorkerPool, stopped


def signal_self(number):
    os.kill(os.getpid(), number)


def exit_with(code):
    os._exit(code)


@pytest.fixture(scope="module")
def pool():
    p = WorkerPool(workers=1, memory_mb=256, retire_mb=0)
    yield p
    p.stop()


@pytest.mark.slow
def test_a_worker_stopped_by_a_signal_says_so_and_names_it(pool):
    with pytest.raises(JobFailed) as caught:
        pool.run(signal_self, signal.SIGUSR1, timeout=60)
    message = str(caught.value)
    assert caught.value.kind == "crashed"
    assert "stopped by SIGUSR1" in message and "memory" not in message
    assert pool.run(abs, -3, timeout=60) == 3  # the pool heals


@pytest.mark.slow
def test_a_worker_that_exits_gives_its_exit_code_and_does_not_blame_memory(pool):
    with pytest.raises(JobFailed) as caught:
        pool.run(exit_with, 3, timeout=60)
    assert "exit code 3" in str(caught.value) and "memory" not in str(caught.value)


@pytest.mark.parametrize(("code", "words"), [(-9, "SIGKILL"), (-15, "SIGTERM"), (-99, "signal 99"), (None, "ended")])
def test_each_ending_in_words(code, words):
    assert words in stopped(code) and "memory" not in stopped(code)
