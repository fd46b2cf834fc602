"""A scene's derivation is pickled with its members, so a process that loads it never computes them again."""

import pickle

from app.engine.constraints import ConstraintForce
from app.engine.hamilton import Hamilton
from app.service import derivations


def test_the_pickled_derivation_carries_the_members_its_document_printed(tmp_path, monkeypatch):
    monkeypatch.setattr(derivations, "cache_dir", lambda: tmp_path)
    monkeypatch.setattr(derivations, "_printed", {})
    made = derivations._derivation.__wrapped__("pulley")  # a miss: derived, printed, pickled
    assert derivations._printed["pulley"]["id"] == "pulley"  # the document printed with it, for derivation_document
    (path,) = (tmp_path / "derivation-objects").glob("pulley-*.pickle")
    loaded = pickle.loads(path.read_bytes())
    assert set(loaded._members) == set(made._members) >= {"constraint_forces", "hamilton", "transformed"}

    def never(*args):
        raise AssertionError("a member computed again after loading")

    monkeypatch.setattr("app.engine.constraints.constraint_forces", never)
    monkeypatch.setattr("app.engine.hamilton.hamilton", never)
    again = derivations._derivation.__wrapped__("pulley")  # a hit: from the disk
    forces = again.constraint_forces
    assert isinstance(forces, tuple) and all(isinstance(f, ConstraintForce) for f in forces) and forces
    assert isinstance(again.hamilton, Hamilton)
    assert [f.force for f in forces] == [f.force for f in made.constraint_forces]
