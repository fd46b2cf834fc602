"""What the action panel says about the kinetic focus (static/js/action-focus.js, run in node) on the server's answers
for every scene's every coordinate: each sentence names its family of variations (the coordinate varied alone, or all
of them together), and no page says "no kinetic focus" of a family whose focus the server finds before the run ends
(prof-e 17, 18, 22: the tabletop said "No kinetic focus before 10 s" with the focus of r and θ at 1.571 s)."""

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from app.scenes import SCENES
from app.service.chapter.derivations import PROCESS_SCENES, derivation_document
from app.service.runtime.gates import Gates
from app.service.simulations.action import action_of_scene
from app.viz.names import label

NODE = shutil.which("node")
WORDS = Path(__file__).resolve().parents[2] / "static" / "js" / "action-focus.js"
RUN = """
import { readFileSync } from "node:fs";
const { focusSentences } = await import(process.argv[1]);
const cases = JSON.parse(readFileSync(0, "utf8"));
process.stdout.write(JSON.stringify(cases.map((c) => focusSentences(c))));
"""
pytestmark = pytest.mark.skipif(NODE is None, reason="node is installed by scripts/assets.sh")


def _said(cases: list[dict]) -> list[dict]:
    run = subprocess.run(
        [NODE, "--input-type=module", "-e", RUN, WORDS.as_uri()],
        input=json.dumps(cases), capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def _case(scene: str, c: int, T: float) -> dict:
    """The panel's context for coordinate c at τ = T: the server's foci over the whole run and its kind at τ."""
    doc = derivation_document(scene)
    names = doc["coordinates"]
    labels = [label(q) for q in names]
    run = action_of_scene(
        scene, Gates(), PROCESS_SCENES, t_end=SCENES[scene].t_end, epsilons=[0.0], coordinate=names[c]
    )
    at = action_of_scene(scene, Gates(), PROCESS_SCENES, t_end=T, epsilons=[0.0], coordinate=names[c])
    return {
        "labels": labels, "c": c, "T": T, "tEnd": SCENES[scene].t_end, "tAll": run["conjugate_time"],
        "tAlone": run["varied_conjugate_time"], "kind": at["kind"], "never": not doc["kinetic_focus_possible"],
        "lowering": "The variation on screen lowers S.",
    }  # fmt: skip


def _focused_scenes() -> list[str]:
    """Scenes whose action panel speaks of a kinetic focus: no forces Q (the damped pendulum names none)."""
    return [s for s in SCENES if not derivation_document(s).get("generalized_forces")]


@pytest.mark.slow
def test_no_page_denies_a_focus_the_server_finds_before_the_run_ends():
    cases, facts = [], []
    for scene in _focused_scenes():
        n = len(derivation_document(scene)["coordinates"])
        for c in range(n):
            case = _case(scene, c, SCENES[scene].t_end / 10)
            cases.append(case)
            facts.append((scene, case))
    for (scene, case), said in zip(facts, _said(cases), strict=True):
        text = f"{said['verdict']} {said['focus']}"
        label = case["labels"][case["c"]]
        if case["never"]:
            assert "at any τ, whatever coordinates are varied" in said["focus"], (scene, text)
            continue
        # the sentence names the family: the coordinate varied (alone, with several), and all of them together
        alone = f"For the variations of {label} alone" if len(case["labels"]) > 1 else f"For the variations of {label} "
        assert said["focus"].startswith(alone), (scene, said["focus"])
        if len(case["labels"]) > 1:
            assert " varied together " in said["focus"], (scene, said["focus"])
        # "no kinetic focus" only of a family the server finds none for, before the run's end
        if case["tAll"] is not None:
            assert "none comes before then either" not in said["focus"], (scene, said["focus"])
            assert "t* = " in said["focus"], (scene, said["focus"])
        if case["tAlone"] is not None or (len(case["labels"]) == 1 and case["tAll"] is not None):
            assert "no kinetic focus comes before" not in said["focus"], (scene, said["focus"])


@pytest.mark.slow
def test_the_tabletop_names_which_variations_reach_a_focus():
    # prof-e 17: "Vary r" said "No kinetic focus before 10 s" while the derivation puts the focus at π √(m/k);
    # the focus of r and θ together is a touch of det J (the server's), and r or θ alone reaches none in the run
    opening, past = (_case("tabletop-spring", c, T) for c, T in ((0, 1.0), (1, 3.0)))
    said_opening, said_past = _said([opening, past])
    assert opening["tAll"] == pytest.approx(1.5707963, rel=1e-6) and opening["tAlone"] is None
    assert said_opening["focus"] == (
        "For the variations of r alone (θ kept on the true path) no kinetic focus comes before 10 s, the end of the "
        "run. For r and θ varied together the first comes earlier, at t* = 1.571 s."
    )
    assert said_opening["verdict"] == (
        "With τ = 1 s, before any kinetic focus, the true path is a minimum of S: every variation with the same ends "
        "raises it."
    )
    # prof-e 18: with θ varied at τ = 3 s the plot shows a minimum, and the text says what kind of minimum it is
    assert past["kind"] == "minimum"
    assert said_past["verdict"] == (
        "With τ = 3 s the true path is a minimum among the variations of θ alone, as S(ε) shows, but not a minimum "
        "of S: τ is past t* = 1.571 s, the first kinetic focus of r and θ varied together, and a variation that moves "
        "r too lowers S."
    )
    assert said_past["marks"] == [{"t": pytest.approx(1.5707963, rel=1e-6), "text": "focus: r and θ together"}]


@pytest.mark.slow
def test_the_spherical_pendulum_marks_each_focus_with_its_family():
    # prof-e 22: the t* marker (0.8159 s) was on the plot without saying which variations it refers to
    case = _case("spherical-pendulum", 0, 2.0)
    (said,) = _said([case])
    assert case["kind"] == "saddle" and case["tAll"] < case["tAlone"] < 2.0
    assert [m["text"] for m in said["marks"]] == ["focus: θ and φ together", "focus: θ alone"]
    assert said["verdict"].startswith("With τ = 2 s, past the kinetic focus of θ alone, the true path is no longer a "
                                      "minimum of S: it is a saddle.")  # fmt: skip
    assert said["focus"] == (
        "For the variations of θ alone (φ kept on the true path) the first kinetic focus (conjugate point) of this "
        "start is at 1.63 s, marked on the time axis. For θ and φ varied together the first comes earlier, at "
        "t* = 0.8159 s, marked on the time axis."
    )


def test_one_coordinate_has_one_focus_named_for_its_variations():
    case = _case("simple-pendulum", 0, 2.0)
    (said,) = _said([case])
    assert said["focus"] == (
        "For the variations of θ the first kinetic focus (conjugate point) of this start is at t* = 1.07 s, marked on "
        "the time axis."
    )
    assert said["marks"] == [{"t": pytest.approx(1.0695688, rel=1e-6), "text": "kinetic focus t*"}]
