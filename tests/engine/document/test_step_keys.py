"""Every step carries a stable key: what identifies it (reasons, placement, folding), its title being display text."""

import re

import pytest

from app.engine.document.report import CORE_STEPS
from app.scenes import SCENES
from app.service.chapter.derivations import derivation_document

KEY = re.compile(r"^[a-z]+(-[a-z]+)*(:[A-Za-z0-9_]+)?$")


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_each_step_has_a_unique_key_of_plain_words(scene_id):
    steps = derivation_document(scene_id)["steps"]
    keys = [s["key"] for s in steps]
    assert all(KEY.match(k) for k in keys), keys
    assert len(set(keys)) == len(keys), keys


def test_keys_name_what_titles_only_display():
    steps = {s["key"]: s["title"] for s in derivation_document("spherical-pendulum")["steps"]}
    # one key per coordinate for the derivatives, one per equilibrium for the modes
    assert steps["derivatives:theta"] == "Derivatives for θ" and steps["derivatives:phi"] == "Derivatives for φ"
    assert steps["euler-lagrange"] == "Euler–Lagrange equations" and steps["h-vs-e"] == "Is h equal to E?"
    modes = [k for k in steps if k.startswith(("normal-modes:", "steady-motion:"))]
    assert modes and all(
        steps[k].startswith(("Normal modes about", "Small oscillations about", "No oscillation about")) for k in modes
    )


def test_hamilton_follows_h_and_the_modes_precede_the_constraints():
    keys = [s["key"] for s in derivation_document("simple-pendulum")["steps"]]
    assert keys.index("hamilton-equations") > keys.index("h-vs-e")
    assert keys.index("equilibria") < keys.index("constraints")


def test_core_steps_are_keys_the_engine_builds():
    built = {s["key"] for scene_id in SCENES for s in derivation_document(scene_id)["steps"]}
    assert CORE_STEPS <= built
