"""The run note of a scene that asks for its Lyapunov exponent, when the exponent cannot be measured now."""

import pytest

from app.numerics.errors import TooMuchWork
from app.scenes import SCENES
from app.service.chapter.derivations import PROCESS_SCENES
from app.service.simulations import lyapunov

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


def test_a_measurement_cut_short_leaves_the_note_without_it_and_nothing_cached(monkeypatch):
    scene = next(s for s in SCENES.values() if s.lyapunov_seconds)

    def busy(*args, **kwargs):
        raise TooMuchWork("the run beside the start stopped at t = 3 s")

    monkeypatch.setattr(lyapunov, "largest_exponent", busy)

    class Empty:  # a cache that holds nothing yet, and keeps only what is computed
        held: dict = {}

        def get(self, key, compute):
            return self.held[key] if key in self.held else compute()

    cache = Empty()
    assert lyapunov.run_note(scene.id, cache, PROCESS_SCENES) == scene.run_note
    assert cache.held == {}
