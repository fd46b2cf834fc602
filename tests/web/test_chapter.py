"""The scenes' derivations, documents and compiled systems reach the routes as the app's ``Scenes``
(``Services.chapter``, ``ChapterDep``); a test gives the routes its own instead of patching a module."""

import pytest

from app.service.answers import Answers
from app.service.chapter.derivations import PROCESS_SCENES, Scenes
from app.web.api.deps import remembered_answers, scenes_chapter


class Asked(Scenes):
    """A ``Scenes`` that records which scenes' derivations and documents it was asked for."""

    def __init__(self) -> None:
        super().__init__()  # the same disk: loaded from the caches set-up filled
        self.asked: list[tuple[str, str]] = []

    def derivation(self, scene_id):
        self.asked.append(("derivation", scene_id))
        return super().derivation(scene_id)

    def document(self, scene_id):
        self.asked.append(("document", scene_id))
        return super().document(scene_id)


def test_the_app_serves_the_one_copy_of_the_process(services):
    # the checking and typesetting threads read the process's derivations too: one copy (docs/state.md)
    assert services.chapter is PROCESS_SCENES


@pytest.mark.slow
def test_the_scene_routes_read_the_scenes_they_are_given(client, override):
    mine = override(scenes_chapter, Asked())
    override(remembered_answers, Answers.start())  # nothing remembered from another test's requests
    assert client.get("/api/scenes/pulley/derivation").json() == PROCESS_SCENES.document("pulley").as_json()
    assert client.get("/scenes/incline-block").status_code == 200
    simulated = client.post("/api/scenes/simple-pendulum/simulate", json={"initial": {}, "samples": 20})
    assert simulated.status_code == 200, simulated.text
    action = {"initial": {"theta": 0.5}, "t_end": 0.6, "epsilons": [0.1]}
    assert client.post("/api/scenes/damped-pendulum/action", json=action).status_code == 200
    section = client.post("/api/scenes/double-pendulum/poincare", json={"count": 1, "t_end": 5})
    assert section.status_code == 200, section.text
    at = client.post("/api/scenes/coupled-oscillators/modes-at", json={"parameters": {"kappa": 0.2}})
    assert at.status_code == 200, at.text
    assert ("document", "pulley") in mine.asked and ("document", "incline-block") in mine.asked
    # each run built its scene's numeric system in the given holder, from its derivation
    built = ["simple-pendulum", "damped-pendulum", "double-pendulum", "coupled-oscillators"]
    assert list(mine.compiled.items) == built
    assert [("derivation", s) for s in built] == [a for a in mine.asked if a[0] == "derivation" and a[1] in built]
