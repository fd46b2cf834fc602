"""The engine tells a listener which part of a derivation it begins, in the page's words, and nobody otherwise."""

from __future__ import annotations

import pytest

from app.engine.algebra import progress
from app.engine.derivation.derive import derive
from app.engine.document.contract import derivation_json
from app.scenes import SCENES

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def test_a_derivation_tells_its_parts_in_order():
    heard: list[str] = []
    d = derive(SCENES["spherical-pendulum"].system)
    with progress.listening(heard.append):
        derivation_json(d)
    assert heard[0] == "the conserved quantities and the reduction to one coordinate"
    assert heard.index("the step-by-step derivation") < heard.index("Hamilton's equations")
    assert all(part[0].islower() or part.startswith("Hamilton") for part in heard)


def test_nobody_listening_hears_nothing_and_a_failing_listener_stops_nothing():
    progress.now("the normal modes")  # no listener: nothing happens

    def broken(part: str) -> None:
        raise OSError("disk full")

    with progress.listening(broken):
        document = derivation_json(derive(SCENES["simple-pendulum"].system))
    assert document["equations_of_motion"]
