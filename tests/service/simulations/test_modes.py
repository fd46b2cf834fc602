"""Measured normal modes: every oscillating mode of every scene's equilibria, within 1 % of the prediction."""

import pytest

from app.scenes import SCENES
from app.service.chapter.derivations import PROCESS_SCENES, scene_document
from app.service.runtime.gates import Gates
from app.service.simulations.modes import measure_scene, modes_at
from app.viz.panels import oscillating_equilibria

WITH_MODES = sorted(s for s in SCENES if oscillating_equilibria(scene_document(s)))


def test_the_scenes_with_oscillating_equilibria():
    assert {"double-pendulum", "coupled-oscillators", "simple-pendulum", "rail-two-body"} <= set(WITH_MODES)


@pytest.mark.slow  # compiles each scene's right-hand side on first use
@pytest.mark.parametrize("scene_id", WITH_MODES)
def test_measured_frequencies_are_within_one_percent(scene_id):
    found = measure_scene(scene_id, Gates(), None, PROCESS_SCENES)
    assert len(found) == len(oscillating_equilibria(scene_document(scene_id)))
    for eq in found:
        for m in eq["modes"]:
            if m["omega_squared"] > 0:
                assert m["measured"] == pytest.approx(m["predicted"], rel=0.01)
                assert abs(m["relative_difference"]) < 0.01
            else:
                assert m["measured"] is None and m["predicted"] is None


@pytest.mark.slow  # compiles each scene's right-hand side on first use
@pytest.mark.parametrize("scene_id", WITH_MODES)
def test_modes_at_the_defaults_are_the_engines(scene_id):
    at = modes_at(scene_id, {}, Gates(), None, PROCESS_SCENES)
    doc = oscillating_equilibria(scene_document(scene_id))
    assert len(at) == len(doc)
    for mine, engine in zip(at, doc, strict=True):
        assert mine["equilibrium"] == pytest.approx(engine.equilibrium)
        assert [m["omega_squared"] for m in mine["modes"]] == pytest.approx([m.omega_squared for m in engine.modes])


def test_double_pendulum_modes_follow_its_lengths():
    # equal masses m, lengths l1 = l2 = l: omega^2 = (2 +- sqrt 2) g / l
    (low,) = [
        e
        for e in modes_at("double-pendulum", {"l1": 2.0, "l2": 2.0}, Gates(), None, PROCESS_SCENES)
        if e["kind"] == "stable"
    ]
    assert [m["omega_squared"] for m in low["modes"]] == pytest.approx(
        [(2 - 2**0.5) * 9.81 / 2, (2 + 2**0.5) * 9.81 / 2]
    )
