"""A checked user system is one frozen, picklable value whose plain data is the API's request."""

import pickle

import pytest

from app.engine.parser.user_system import UserSystem
from app.service.users.user_checks import InvalidSystem, checked, spec_key
from app.web.api.examples_user import DOUBLE_PENDULUM, FORCED_SPRING, SPINNING_HOOP
from app.web.schemas.user import SystemSpec


@pytest.mark.parametrize("body", [DOUBLE_PENDULUM, FORCED_SPRING, SPINNING_HOOP])
def test_the_request_survives_the_round_trip_and_pickling(body):
    spec = SystemSpec.model_validate(body).to_spec()
    user = checked(spec)
    assert user.as_json() == spec
    assert SystemSpec.model_validate(user.as_json()).to_spec() == spec
    again = pickle.loads(pickle.dumps(user))
    assert again == user and hash(again) == hash(user) and spec_key(again) == spec_key(user)
    with pytest.raises(AttributeError):
        user.coordinates = ("x",)  # type: ignore[misc]


def test_a_planar_particle_moves_in_z_equal_zero_for_the_engine():
    user = UserSystem.of({"coordinates": ["x"], "particles": [{"mass": "m", "position": ["x", "1"]}], "potential": "0"})
    assert user.system().particles[0].position == ("x", "1", "0") and user.form == "particles"


def test_the_key_tells_systems_and_requests_apart():
    user = checked(SystemSpec.model_validate(SPINNING_HOOP).to_spec())
    other = checked(SystemSpec.model_validate(FORCED_SPRING).to_spec())
    assert len({spec_key(user), spec_key(other), spec_key(user, "modes")}) == 3


def test_a_refusal_is_located_in_the_request():
    with pytest.raises(InvalidSystem) as refused:
        checked({"coordinates": ["x"], "lagrangian": "x_dot**2 - y"})
    assert refused.value.loc == ("lagrangian",) and refused.value.part == "y"


def test_a_checked_system_carries_each_expression_as_read_across_pickling():
    spec = SystemSpec.model_validate(DOUBLE_PENDULUM).to_spec()
    user = checked(spec)
    assert user.parsed is not None
    assert {loc: p.text for loc, p in user.parsed.items()} == {loc: text for loc, text, _ in user.expressions()}
    again = pickle.loads(pickle.dumps(user))
    assert again.parsed is not None and again.parsed.keys() == user.parsed.keys()
    # what was read is not part of the value: the same declaration unchecked is equal, with the same key
    plain = UserSystem.of(spec)
    assert plain.parsed is None and plain == user and hash(plain) == hash(user) and spec_key(plain) == spec_key(user)


def test_the_workers_declaration_carries_what_it_built_and_derives_the_same():
    from app.engine.derivation.derive import derive
    from app.service.users.user_jobs import build_system

    spec = SystemSpec.model_validate(FORCED_SPRING).to_spec()
    built = build_system(checked(spec))
    assert set(built.built) == {"m*x_dot**2/2", "k*x**2/2", "F*cos(w*t) - b*x_dot", "0"}
    # the same declaration without what was built: the engine reads the text itself, to the same equations
    unbuilt = UserSystem.of(spec).system()
    assert unbuilt.built == {} and unbuilt == built
    assert derive(built).equations.accelerations == derive(unbuilt).equations.accelerations


@pytest.mark.parametrize("check", [checked, UserSystem.of])
def test_the_worker_builds_what_was_read_or_checks_what_was_not_with_the_same_refusals(check):
    from app.service.users.user_jobs import build_system

    # refused by gate 2 (an undeclared name): by the web process's check, or by the worker's when unchecked
    bad_name = {"coordinates": ["x"], "parameters": ["m"], "lagrangian": "m*x_dot**2/2 - y"}
    with pytest.raises(InvalidSystem) as refused:
        build_system(check(bad_name))
    assert refused.value.loc == ("lagrangian",) and refused.value.part == "y"
    # passes gates 1 and 2, refused when built (gate 3), located at its field with its span in the text
    undefined = {"coordinates": ["x"], "parameters": ["m"], "kinetic": "m*x_dot**2/2", "potential": "m/(x - x)"}
    with pytest.raises(InvalidSystem) as refused:
        build_system(check(undefined))
    assert refused.value.loc == ("potential",) and "division by zero" in str(refused.value)
    assert (refused.value.start, refused.value.end, refused.value.part) == (3, 8, "x - x")
