"""A scene's derivation is pickled with its members, so a process that loads it never computes them again;
each ``Scenes`` (an app's, or this test's on a temporary disk) holds its own."""

import json
import pickle

import pytest

from app.engine.equations.constraints import ConstraintForce
from app.engine.equations.hamilton import Hamilton
from app.service.chapter.derivations import PROCESS_SCENES, Scenes


@pytest.mark.slow
def test_the_pickled_derivation_carries_the_members_its_document_printed(tmp_path, monkeypatch):
    scenes = Scenes(tmp_path)
    made = scenes.derived("pulley")  # a miss: derived, printed, pickled
    printed = scenes._printed["pulley"]  # the document printed with it, for ``document``
    assert printed.id == "pulley"
    (path,) = (tmp_path / "derivation-objects").glob("pulley-*.pickle")
    loaded = pickle.loads(path.read_bytes())
    assert set(loaded._members) == set(made._members) >= {"constraint_forces", "hamilton", "transformed"}

    def never(*args):
        raise AssertionError("a member computed again after loading")

    monkeypatch.setattr("app.engine.derivation.derive.constraint_forces", never)
    monkeypatch.setattr("app.engine.derivation.derive.hamilton", never)
    again = Scenes(tmp_path).derived("pulley")  # a hit: from the disk
    forces = again.constraint_forces
    assert isinstance(forces, tuple) and all(isinstance(f, ConstraintForce) for f in forces) and forces
    assert isinstance(again.hamilton, Hamilton)
    assert [f.force for f in forces] == [f.force for f in made.constraint_forces]
    # the document is the one printed with the derivation (taken, not printed again), then on the disk
    assert scenes.document("pulley") is printed and "pulley" not in scenes._printed
    assert list((tmp_path / "derivations").glob("pulley-*.json"))


def test_each_holder_remembers_its_own():
    """Two holders never share a derivation or a system; one holder derives and builds a scene once."""
    mine = Scenes()  # on the same disk: loaded from the pickles, not derived again
    d = mine.derivation("simple-pendulum")
    assert mine.derivation("simple-pendulum") is d and d is not PROCESS_SCENES.derivation("simple-pendulum")
    system, _ = mine.system("simple-pendulum")
    assert mine.system("simple-pendulum")[0] is system and list(mine.compiled.items) == ["simple-pendulum"]
    assert PROCESS_SCENES.compiled.items.get("simple-pendulum", (None,))[0] is not system
    assert mine.document("simple-pendulum") == PROCESS_SCENES.document("simple-pendulum")


def test_the_chapter_holds_the_model_and_the_disk_its_json(tmp_path):
    from app.engine.document.model import Document

    document = Scenes(tmp_path).document("simple-pendulum")
    assert isinstance(document, Document) and document.id == "simple-pendulum"
    # the file on the disk is the model's JSON, and a new holder reads it back as the model
    on_disk = next((tmp_path / "derivations").glob("simple-pendulum-*.json")).read_bytes()
    assert on_disk == json.dumps(document.as_json()).encode()
    assert Scenes(tmp_path).document("simple-pendulum") == document
