"""A checked user system is one frozen, picklable value whose plain data is the API's request."""

import pickle

import pytest

from app.engine.user_system import UserSystem
from app.service.user_checks import InvalidSystem, checked, spec_key
from app.web.examples_user import DOUBLE_PENDULUM, FORCED_SPRING, SPINNING_HOOP
from app.web.schemas_user import SystemSpec


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
