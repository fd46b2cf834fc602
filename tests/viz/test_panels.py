"""The panel registry: one list, rules evaluated on the derivation, optional panels only where declared."""

import pytest

from app.scenes import SCENES
from app.service.chapter.derivations import scene_document
from app.viz.panels import BY_NAME, NAMES, OPTIONAL, PANELS, Facts, linear_equations, shown

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def facts(scene_id, scene=True):
    doc = scene_document(scene_id)
    return Facts(doc, {"omega_squared": None} if doc.effective_potential else None, 2, scene)


def test_names_are_unique_and_every_panel_explains_itself():
    assert len(NAMES) == len(PANELS)
    for p in PANELS:
        assert p.title and len(p.text) > 40 and p.rule


@pytest.mark.parametrize(
    ("scene_id", "panel", "expected"),
    [
        ("simple-pendulum", "modes", False),  # one coordinate
        ("coupled-oscillators", "modes", True),
        ("double-pendulum", "modes", True),
        ("rail-two-body", "modes", True),  # a vibration beside the free translation
        ("pulley", "modes", False),  # no equilibrium
        ("double-pendulum", "poincare", True),
        ("coupled-oscillators", "poincare", False),  # linear: two normal modes, integrable
        ("spherical-pendulum", "poincare", False),  # p_φ conserved: one degree of freedom left
        ("simple-pendulum", "poincare", False),  # one coordinate
        ("damped-pendulum", "poincare", False),
        ("rotating-parabola", "h-vs-e", True),
        ("simple-pendulum", "h-vs-e", False),
        ("tabletop-spring", "momenta", True),
        ("simple-pendulum", "momenta", False),
        ("pulley", "constraint-force", True),
    ],
)
def test_rules_read_the_derivation(scene_id, panel, expected):
    assert BY_NAME[panel].available(facts(scene_id)) is expected


def test_optional_panels_need_a_declaration_and_the_others_do_not():
    f = facts("double-pendulum")
    assert "poincare" in shown(f, ["poincare"]) and "poincare" not in shown(f, [])
    assert "modes" in shown(f, []) and "energy" in shown(f, [])
    assert "work-precision" not in shown(facts("double-pendulum", scene=False), [])
    assert set(OPTIONAL) >= {"poincare", "effective-potential"}


def test_the_scenes_beyond_the_chapter_ask_for_a_poincare_section():
    assert {s.id for s in SCENES.values() if "poincare" in s.panels} == {"double-pendulum"}


def test_every_panel_has_a_drawing_in_the_browser_and_every_drawing_a_panel():
    import re
    from pathlib import Path

    plots = (Path(__file__).resolve().parents[2] / "static" / "js" / "plots.js").read_text()
    block = re.search(r"const KINDS = \{(.*?)\n\};", plots, re.S)
    assert block, "plots.js no longer maps panel names to drawings in KINDS"
    drawn = set(re.findall(r'^\s*"?([a-z0-9-]+)"?:', block.group(1), re.M))
    # the animations are drawn by static/js/animation.js (simulation.js hands it every animation-* panel)
    assert drawn == {name for name in NAMES if not name.startswith("animation")}


# the scenes where the choice of integrator teaches something: a dissipative run, and a nonlinear system with two
# degrees of freedom and no conserved momentum (chaos); linear ones and those a momentum reduces fold it away
METHOD_MATTERS = {"damped-pendulum", "double-pendulum"}


def test_linear_equations_are_told_from_nonlinear_ones():
    linear = {sid for sid in SCENES if linear_equations(scene_document(sid))}
    assert {"coupled-oscillators", "rail-two-body", "pulley", "incline-block", "movable-incline"} <= linear
    assert not linear & {"simple-pendulum", "double-pendulum", "damped-pendulum", "spherical-pendulum"}


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_the_method_comparison_is_open_only_where_the_method_matters(client, scene_id):
    html = client.get(f"/scenes/{scene_id}").text
    if 'id="panel-work-precision"' not in html:
        return  # a motion in t² has no comparison at all
    folded = '<details class="panel-details" id="details-work-precision">' in html
    assert folded == (scene_id not in METHOD_MATTERS), scene_id
    if folded:
        summary = html.split('id="details-work-precision"><summary>', 1)[1].split("</summary>", 1)[0]
        assert summary.startswith("More: error against run time, how accurate each way of stepping")


def test_the_phase_text_speaks_of_angles_only_where_a_coordinate_is_one(client):
    from app.viz.panels import texts

    assert "is shown wrapped into (−π, π]" in texts(angles=True)["phase"]["text"]
    assert "is shown wrapped into (−π, π]" not in texts(angles=False)["phase"]["text"]
    assert "is shown wrapped into (−π, π]" in client.get("/scenes/simple-pendulum").text
    assert "is shown wrapped into (−π, π]" not in client.get("/scenes/rail-two-body").text
    # prof-e 5: the spherical pendulum's polar angle lies in [0, π]: no page says every angle is in (−π, π]
    assert "An angle is shown in (−π, π]" not in client.get("/scenes/spherical-pendulum").text


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_a_poincare_section_is_shown_only_where_the_motion_can_be_chaotic(scene_id):
    """prof-f 20, 38: sections of integrable systems (linear, or a conserved momentum) are closed curves only."""
    from app.service.chapter.derivations import PROCESS_SCENES
    from app.web.pages.chapter import page_model

    assert ("poincare" in page_model(scene_id, None, PROCESS_SCENES)["panels"]) == (scene_id == "double-pendulum")


def test_typed_systems_get_a_poincare_section_only_where_the_motion_can_be_chaotic():
    from tests.viz.test_user_page import model
    from tests.web.pages.test_playground_prof_d import CONE

    # the cone: φ is cyclic, p_φ is conserved, one degree of freedom is left (prof-f 38)
    assert "poincare" not in model(CONE)["panels"]
    # Hénon and Heiles' potential: two coupled nonlinear degrees of freedom, chaotic at high energy
    henon = {"coordinates": ["x", "y"], "parameters": [{"name": "m", "value": 1.0}],
             "kinetic": "m*(x_dot**2 + y_dot**2)/2", "potential": "(x**2 + y**2)/2 + x**2*y - y**3/3"}  # fmt: skip
    assert "poincare" in model(henon)["panels"]
