"""Measured normal modes: every oscillating mode of every scene's equilibria, within 1 % of the prediction."""

import pytest

from app.scenes import SCENES
from app.service.derivations import derivation_document
from app.service.modes import measure_scene
from app.viz.panels import oscillating_equilibria

WITH_MODES = sorted(s for s in SCENES if oscillating_equilibria(derivation_document(s)))


def test_the_scenes_with_oscillating_equilibria():
    assert {"double-pendulum", "coupled-oscillators", "simple-pendulum", "rail-two-body"} <= set(WITH_MODES)


@pytest.mark.slow  # compiles each scene's right-hand side on first use
@pytest.mark.parametrize("scene_id", WITH_MODES)
def test_measured_frequencies_are_within_one_percent(scene_id):
    found = measure_scene(scene_id)
    assert len(found) == len(oscillating_equilibria(derivation_document(scene_id)))
    for eq in found:
        for m in eq["modes"]:
            if m["omega_squared"] > 0:
                assert m["measured"] == pytest.approx(m["predicted"], rel=0.01)
                assert abs(m["relative_difference"]) < 0.01
            else:
                assert m["measured"] is None and m["predicted"] is None
