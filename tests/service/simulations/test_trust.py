"""The verdict on a run: its error estimate against how far each coordinate moves."""

import numpy as np
import pytest

from app.service.simulations.trust import judge
from app.web.schemas.simulate import SimulateRequest
from tests.served import scene_run


def test_an_error_comparable_to_the_motion_is_not_trusted():
    y = np.array([[0.0], [3.0], [6.0]])
    out = judge(1.9, {"theta": 1.9}, ["theta"], y)
    assert out["trusted"] is False and out["coordinate"] == "theta" and out["ratio"] == pytest.approx(1.9 / 6)
    assert out["message"].startswith("Not reliable: the estimated error is 32 % of how far θ moves")


def test_a_small_error_is_trusted_and_no_estimate_is_no_verdict():
    y = np.array([[-1.0, 5.0], [1.0, 5.0]])
    assert judge(1e-8, {}, ["x", "y"], y)["trusted"] is True
    # a coordinate at rest is judged against a thousandth of its size: 1e-8 / 5e-3
    assert judge(1e-8, {}, ["x", "y"], y)["ratio"] == pytest.approx(2e-6)
    assert judge(None, {}, ["x"], y[:, :1]) == {"trusted": None, "ratio": None, "coordinate": None, "message": None}


def test_the_simulate_result_carries_the_verdict():
    good = scene_run("simple-pendulum", SimulateRequest(initial={}))
    assert good["trust"]["trusted"] is True and good["trust"]["message"] is None
    loose = scene_run("double-pendulum", SimulateRequest(initial={"theta1": 2.0, "theta2": 2.0}, t_end=60.0, rtol=1e-3))
    assert loose["trust"]["trusted"] is False, loose["trust"]
    assert "Choose a smaller tolerance" in loose["trust"]["message"]
