"""After the warm-up, the objects alive are frozen: a full collection no longer scans them."""

from __future__ import annotations

import gc
import threading

import pytest

from app.service.runtime.memory import freeze_imported, freeze_when_done

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def test_what_the_imports_left_is_frozen_at_the_start():
    gc.unfreeze()
    try:
        freeze_imported()
        frozen = gc.get_freeze_count()
        assert frozen > 10_000  # the modules, their classes and functions
        assert len(gc.get_objects()) < frozen  # a full collection scans only what came after
    finally:
        gc.unfreeze()


def test_the_long_lived_objects_are_frozen_once_the_warm_up_ends():
    gc.unfreeze()
    release = threading.Event()
    warming = threading.Thread(target=release.wait)
    warming.start()
    try:
        settle = freeze_when_done(warming)
        settle.join(timeout=0.2)
        assert settle.is_alive() and gc.get_freeze_count() == 0  # waits for the warm-up
        release.set()
        settle.join(timeout=30)
        assert not settle.is_alive()
        assert gc.get_freeze_count() > 10_000  # the modules and everything loaded
    finally:
        release.set()
        gc.unfreeze()
