"""Work threads are reniced once to the setting; the event loop's thread and lower-priority threads are left alone."""

from __future__ import annotations

import os
import threading

import pytest

from app.service import priority
from app.settings import settings


def _nice_after(call) -> int:
    seen: list[int] = []

    def work() -> None:
        call()
        seen.append(os.getpriority(os.PRIO_PROCESS, threading.get_native_id()))

    thread = threading.Thread(target=work)
    thread.start()
    thread.join()
    return seen[0]


@pytest.fixture
def niceness(monkeypatch):
    def set_to(value: int) -> None:
        monkeypatch.setenv("LAGRANGE_WORK_NICENESS", str(value))
        settings.cache_clear()

    yield set_to
    settings.cache_clear()


def test_a_work_thread_takes_the_settings_nice_value_and_the_main_thread_keeps_its_own(niceness):
    niceness(7)
    before = os.getpriority(os.PRIO_PROCESS, 0)
    assert _nice_after(priority.yield_to_the_loop) == max(before, 7)
    priority.yield_to_the_loop()  # the main thread (the event loop's, in a server) is never reniced
    assert os.getpriority(os.PRIO_PROCESS, 0) == before


def test_zero_turns_it_off_and_a_thread_already_lower_stays_lower(niceness):
    niceness(0)
    base = os.getpriority(os.PRIO_PROCESS, 0)
    assert _nice_after(priority.yield_to_the_loop) == base
    niceness(3)

    def already_lower() -> None:
        os.setpriority(os.PRIO_PROCESS, threading.get_native_id(), max(base, 9))
        priority.yield_to_the_loop()

    assert _nice_after(already_lower) == max(base, 9)
