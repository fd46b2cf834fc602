"""The derivation's members beyond the equations: typed, computed on first use, kept, bounded, pickled."""

import pickle

import pytest
import sympy as sp

from app.engine.algebra import work
from app.engine.algebra.budget import Skipped, work_limit
from app.engine.derivation import derive as derive_module
from app.engine.derivation.derive import derive, value_or
from app.engine.document.contract import derivation_json
from app.engine.equations.constraints import ConstraintForce
from app.engine.equations.hamilton import Hamilton
from app.engine.equilibria.modes import NormalModes
from app.scenes import SCENES

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


def test_members_are_typed_and_computed_once():
    d = derive(SCENES["pulley"].system)
    forces = d.constraint_forces
    assert isinstance(forces, tuple) and forces and all(isinstance(f, ConstraintForce) for f in forces)
    assert all(isinstance(f.force, sp.Expr) for f in forces)
    assert d.constraint_forces is forces  # kept, not computed again
    assert isinstance(d.hamilton, Hamilton) and d.hamilton is d.hamilton
    assert d.transformed is None  # the pulley declares no change of coordinates
    modes = d.normal_modes()
    assert isinstance(modes, NormalModes) and d.normal_modes({}) is modes


def test_normal_modes_are_kept_per_set_of_held_momenta():
    d = derive(SCENES["spherical-pendulum"].system)
    one, two = d.normal_modes({"p_phi": 1.0}), d.normal_modes({"p_phi": 2.0})
    assert isinstance(one, NormalModes) and isinstance(two, NormalModes)
    assert one is not two and d.normal_modes({"p_phi": 1.0}) is one
    assert one.equilibria != two.equilibria  # the relative equilibria move with the held momentum


def _endless(*args):
    x = sp.Symbol("x")
    while True:
        sp.expand((x + 1) ** 40)


def test_a_member_past_its_bound_is_skipped_with_its_reason(monkeypatch):
    monkeypatch.setitem(derive_module.MEMBER_WORK, "constraint_forces", 4_000)
    monkeypatch.setattr("app.engine.derivation.derive.constraint_forces", _endless)
    d = derive(SCENES["pulley"].system)
    skipped = d.constraint_forces
    assert isinstance(skipped, Skipped) and skipped.member == "constraint_forces"
    assert "bound" in skipped.reason
    assert d.constraint_forces is skipped  # its own bound would run out again: kept
    assert value_or(d.constraint_forces, ()) == ()
    # the document prints the reason in the member's place
    doc = derivation_json(d, beyond=False)
    assert doc["constraint_forces"] == []
    assert {"member": "constraint_forces", "reason": skipped.reason} in doc["skipped"]


def test_a_member_skipped_for_want_of_an_enclosing_bounds_work_is_tried_again():
    d = derive(SCENES["pulley"].system)
    assert work.left() is None
    with work_limit(10_000):  # less than the member reserve: nothing left for the member
        skipped = d.constraint_forces
    assert isinstance(skipped, Skipped) and "used up" in skipped.reason
    assert isinstance(d.constraint_forces, tuple)  # outside that bound, computed


def test_computed_members_survive_pickling():
    scene = SCENES["pulley"]
    d = derive(scene.system)
    derivation_json(d, scene=scene)  # printing computes every member
    loaded = pickle.loads(pickle.dumps(d, protocol=pickle.HIGHEST_PROTOCOL))
    assert loaded._members.keys() == d._members.keys()
    assert [f.force for f in value_or(loaded.constraint_forces, ())] == [f.force for f in value_or(d.constraint_forces, ())]
    assert isinstance(loaded.hamilton, Hamilton)


def test_the_document_prints_the_members():
    scene = SCENES["pulley"]
    d = derive(scene.system)
    doc = derivation_json(d, scene=scene)
    forces = value_or(d.constraint_forces, ())
    assert [f["name"] for f in doc["constraint_forces"]] == [f.constraint.name for f in forces]
    # the printed form (a denominator grouped as a textbook writes it, M(m₁ + m₂) + 4m₁m₂) is the engine's force
    printed = [sp.sympify(f["sympy"], locals=d.table.namespace()) for f in doc["constraint_forces"]]
    assert len(printed) == len(forces)
    assert all(sp.simplify(a - f.force) == 0 for a, f in zip(printed, forces, strict=True))
    ham = d.hamilton
    assert isinstance(ham, Hamilton)
    assert doc["hamilton"]["momenta"] == {q: p.name for q, p in zip(d.table.names, ham.momenta, strict=True)}
    p_dot = [sp.sympify(e["p_dot"]["sympy"], locals=d.table.namespace()) for e in doc["hamilton"]["equations"]]
    assert all(sp.simplify(a - b) == 0 for a, b in zip(p_dot, ham.p_dot, strict=True))
