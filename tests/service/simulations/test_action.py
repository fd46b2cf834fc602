"""The action service: scene answers cached per request, the documented fields, user systems through the job."""

import json

import pytest

from app.service.chapter.derivations import PROCESS_SCENES
from app.service.runtime.cache import Recent
from app.service.simulations import action, simulation
from app.service.users import user_jobs
from app.service.users.user_checks import InvalidSystem, checked

OSCILLATOR = {
    "coordinates": ["x"],
    "parameters": [{"name": "m", "value": 1}, {"name": "w", "value": 2}],
    "lagrangian": "m*x_dot**2/2 - m*w**2*x**2/2",
}


def test_scene_answers_are_kept_per_request():
    options = {"t_end": 0.5, "epsilons": [0.1]}
    remembered = Recent(action.CACHED_ANSWERS)  # the app's own, as app/service/answers.py builds it
    first = action.cached_action_of_scene("simple-pendulum", simulation.Gates(), remembered, PROCESS_SCENES, **options)
    assert (
        action.cached_action_of_scene("simple-pendulum", simulation.Gates(), remembered, PROCESS_SCENES, **options)
        is first
    )
    other = action.cached_action_of_scene(
        "simple-pendulum", simulation.Gates(), remembered, PROCESS_SCENES, t_end=0.6, epsilons=[0.1]
    )
    assert other is not first
    # another app's memory is its own
    assert (
        action.cached_action_of_scene("simple-pendulum", simulation.Gates(), Recent(4), PROCESS_SCENES, **options)
        is not first
    )


def test_the_job_answers_for_a_user_system_and_locates_refusals():
    user = checked(OSCILLATOR)
    answer = json.loads(user_jobs.action_job(user, {"t_end": 2.0, "initial": {"x": 0.3}, "epsilons": []}))
    assert answer["kind"] == "saddle" and answer["conjugate_time"] == pytest.approx(3.141592653589793 / 2, rel=1e-8)
    with pytest.raises(InvalidSystem) as refused:
        user_jobs.action_job(user, {"t_end": 1.0, "epsilons": [0.0] * (action.EPSILONS_MAX + 1)})
    assert f"at most {action.EPSILONS_MAX}" in str(refused.value) and refused.value.loc == ("epsilons",)


def test_relax_job_for_a_user_system():
    user = checked(OSCILLATOR)
    answer = json.loads(user_jobs.relax_job(user, {"t_end": 0.5, "start": {"x": 0.0}, "end": {"x": 0.2}, "steps": 50}))
    assert answer["kind"] == "minimum" and answer["difference"] < 1e-6
