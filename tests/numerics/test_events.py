"""Terminal events: the block on the fixed incline stops at the foot of its ramp."""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from app.numerics.simulate import simulate
from app.scenes import SCENES
from app.service.chapter import compiled
from app.service.chapter.derivations import derivation
from tests.served import scene_run

G, ALPHA = 9.81, 0.5


def request(**fields):
    base = {"parameters": {}, "initial": {}, "t_end": None, "method": "auto", "rtol": None, "atol": None}
    return SimpleNamespace(**{"samples": None, **base, **fields})


def test_the_block_stops_at_the_foot_with_the_defaults():
    doc = scene_run("incline-block", request())
    event = doc["stats"]["event"]
    # up the slope at 3 m/s and back: X = 0 again at t = 2 v0 / (g sin alpha)
    assert event["name"] == "foot of the ramp"
    assert event["t"] == pytest.approx(2 * 3.0 / (G * math.sin(ALPHA)), rel=1e-9)
    assert "foot of the ramp" in event["message"]
    x = np.array(doc["state"]["X"])
    assert x.min() > -1e-9 and abs(x[-1]) < 1e-9  # no X beyond the foot, and the last sample is at it
    assert doc["t"][-1] == pytest.approx(event["t"]) and doc["t"][-1] < SCENES["incline-block"].t_end
    assert doc["stats"]["warnings"] == [] and doc["stats"]["error_estimate"] < 1e-6


def test_a_run_that_stays_on_the_ramp_has_no_event():
    doc = scene_run("incline-block", request(t_end=1.0, samples=100))
    assert doc["stats"]["event"] is None and len(doc["t"]) == 100 and doc["t"][-1] == 1.0


def test_a_start_below_the_foot_ends_at_once():
    doc = scene_run("incline-block", request(initial={"X": -0.5}))
    assert doc["stats"]["event"]["t"] == 0.0 and list(doc["t"]) == [0.0]


def test_scenes_without_events_run_to_the_end():
    doc = scene_run("simple-pendulum", request(samples=50))
    assert doc["stats"]["event"] is None and doc["t"][-1] == 10.0


def test_every_method_stops_at_the_same_instant():
    d = derivation("incline-block")
    systems = compiled.Compiled()
    system, _ = systems.get("incline-block", d, [])
    events = systems.events(SCENES["incline-block"], system)
    k, y0 = np.array([1.0, G, ALPHA]), np.array([0.0, 3.0])
    for method in ("DOP853-compiled", "Yoshida4", "RK45"):
        out = simulate(system, k, y0, 2.0, 200, method=method, events=events)
        assert out.event is not None and out.event.t == pytest.approx(6 / (G * math.sin(ALPHA)), rel=1e-8)


def test_the_wedge_block_pushed_up_stops_at_the_top_corner():
    """D < 0 would put the block above the wedge's top corner, off its slope (prof-f 12): the run ends at D = 0."""
    doc = scene_run("movable-incline", request(initial={"D": 0.2, "D_dot": 3.0 * -1}))
    event = doc["stats"]["event"]
    assert event["name"] == "top corner" and "top corner" in event["message"]
    D = np.array(doc["state"]["D"])
    assert D.min() > -1e-9 and abs(D[-1]) < 1e-9 and doc["t"][-1] < SCENES["movable-incline"].t_end
