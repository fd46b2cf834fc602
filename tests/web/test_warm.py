"""The playground examples at start: loaded from the disk cache set-up filled, derived only when it lacks them."""

import threading

import pytest

from app.service.answers import examples_cache
from app.service.users import user_systems
from app.web.pages import playground

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def test_examples_are_derived_once_then_loaded_from_disk(tmp_path):
    derived = []

    def derive(spec):
        derived.append(spec)
        return b'{"derived": %d}' % len(derived)

    def start():
        """A new process: empty memory caches (the app's services build its own), the same disk."""
        service = user_systems.UserSystems(pool=object(), gate=object())
        playground.load_examples(service, examples_cache(tmp_path), derive)
        return [service.derivations.get(key) for key in keys]

    keys = [
        playground.spec_key(playground.checked(playground.spec_of(playground.form_of(e))))
        for e in playground.EXAMPLES.values()
    ]
    first = start()
    assert len(derived) == len(playground.EXAMPLES) and all(first)
    assert len(list((tmp_path / "example-derivations").iterdir())) == len(playground.EXAMPLES)
    again = start()  # a restart: nothing derived, the same documents
    assert len(derived) == len(playground.EXAMPLES) and again == first


def test_examples_wait_for_the_scenes_warm_up():
    order = []
    scenes = threading.Thread(target=lambda: (threading.Event().wait(0.2), order.append("scenes")))
    scenes.start()
    cache = examples_cache()
    loaded = playground.warm_examples(object(), cache, after=scenes, load=lambda service, given: order.append(given))
    loaded.join(timeout=10)
    assert order == ["scenes", cache]
