"""The Poincaré section as the pages will call it: options checked, the documented JSON returned."""

import math

import pytest

from app.numerics.errors import SimulationError
from app.service.chapter.derivations import PROCESS_SCENES
from app.service.runtime.gates import Gates
from app.service.simulations.poincare import COUNT_MAX, section_of_scene


def test_scene_section_document():
    doc = section_of_scene("coupled-oscillators", Gates(), PROCESS_SCENES, count=2, t_end=20.0)
    assert doc["coordinate"] == "x2" and doc["value"] == 0.0 and doc["direction"] == 1
    assert doc["axes"] == {"q": "x1", "q_dot": "x1_dot", "p": "p_x1"}
    # the energy defaults to h at the scene's initial state: k x1²/2 + κ x1²/2 with x1 = 0.2
    assert doc["energy"] == pytest.approx((10.0 + 1.0) * 0.2**2 / 2)
    assert len(doc["orbits"]) == 2
    for orbit in doc["orbits"]:
        assert set(orbit) == {"initial", "t", "q", "q_dot", "p", "energy_drift", "complete"}
        assert len(orbit["t"]) == len(orbit["q"]) == len(orbit["p"]) > 3 and orbit["complete"]
        assert orbit["initial"]["x2"] == 0.0 and orbit["initial"]["x2_dot"] > 0
        # p_x1 = m x1_dot
        assert orbit["p"] == pytest.approx(orbit["q_dot"])
    assert doc["stats"]["crossings"] == sum(len(o["t"]) for o in doc["orbits"])


@pytest.mark.parametrize(
    ("scene_id", "options", "message"),
    [
        ("simple-pendulum", {}, "at least two coordinates"),
        ("double-pendulum", {"coordinate": "phi"}, "unknown coordinate"),
        ("double-pendulum", {"count": COUNT_MAX + 1}, "count"),
        ("double-pendulum", {"direction": 0}, "direction"),
        ("double-pendulum", {"energy": math.nan}, "finite"),
        ("double-pendulum", {"parameters": {"g": -1.0}}, "outside its allowed range"),
        ("double-pendulum", {"energy": -100.0}, "below the potential"),
        ("tabletop-spring", {"t_end": 1e9}, "t_end"),
    ],
)
def test_bad_options_are_refused_with_a_reason(scene_id, options, message):
    with pytest.raises(SimulationError, match=message):
        section_of_scene(scene_id, Gates(), PROCESS_SCENES, **options)
