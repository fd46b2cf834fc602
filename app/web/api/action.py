"""POST /api/scenes/{id}/action and POST /api/action: the action of the true path and of its variations.

The scene route is a plain ``def`` (FastAPI's thread pool; the integration releases the GIL and the
numbers are numpy on a generated L, no SymPy); a user system's job runs in the worker pool with its
time limit, cache and fair share, as POST /api/simulate does.
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body
from fastapi.responses import Response

from app.service.simulations import action
from app.service.users import user_jobs
from app.service.users.user_checks import checked
from app.web.api.deps import AnswersDep, ChapterDep, ClientDep, GatesDep, UserSystemsDep
from app.web.api.simulate import scene_route
from app.web.api.user import answer, system_route
from app.web.http.responses import FastJSONResponse
from app.web.schemas.action import (
    ActionRequest,
    ActionResponse,
    RelaxRequest,
    UserActionRequest,
    UserRelaxRequest,
    action_options,
    relax_options,
)

router = APIRouter(prefix="/api", tags=["the action"])

TEXT = (
    "The true path q(t) on [0, t_end] (a simulation from `initial`) and the varied paths q + ε η of one coordinate, "
    "η(t) = sin(kπt/T), zero at both ends. Answers S(ε) = ∫ L dt for each ε (quadrature on the path's dense output "
    "with an error estimate), dS/dε and d²S/dε² at ε = 0 (the latter from the Jacobi operator), whether the true "
    "path is a minimum, a saddle or a maximum over the shapes k = 1 … K, and the first conjugate time (kinetic "
    "focus) before t_end, where the true path stops being a minimum."
)


@scene_route(
    router,
    "/scenes/{scene_id}/action",
    summary="The action of a scene's true path and of its variations",
    description=TEXT,
    document=ActionResponse,
)
def scene_action(
    scene_id: str, request: ActionRequest, gates: GatesDep, answers: AnswersDep, chapter: ChapterDep
) -> Any:
    # a refusal (SimulationError) or an unknown scene is answered by app/web/api/errors.py
    return FastJSONResponse(
        action.cached_action_of_scene(scene_id, gates, answers.actions, chapter, **action_options(request))
    )


@system_route(
    router,
    "/action",
    summary="The action of a system you declare",
    description=TEXT + " The system is given under `system` as for POST /api/derive; it runs in the worker pool.",
    response_model=ActionResponse,
)
async def user_action(client: ClientDep, users: UserSystemsDep, body: Annotated[UserActionRequest, Body()]) -> Response:
    spec, options = body.system.to_spec(), action_options(body)
    return await answer(
        client,
        lambda key, address: users.simulation_job("action", user_jobs.action_job, checked(spec), options, key, address),
    )


RELAX_TEXT = (
    "Fix q(0) and q(T) (by default the true path's, from `initial`) and give a trial path between them (by default "
    "the straight line): the path that makes the discretized action stationary is found by Newton's method on the "
    "discrete Euler–Lagrange equations (a variational integrator, midpoint rule, on `steps` and twice as many steps, "
    "extrapolated). The answer has the path, some of the iterates (for an animation), whether it is a minimum or a "
    "saddle of the discrete action (its Hessian's negative directions), and the shooting solution to compare."
)


@scene_route(
    router,
    "/scenes/{scene_id}/action/relax",
    summary="Find a scene's path between two ends by making the action stationary",
    description=RELAX_TEXT,
)
def scene_relax(scene_id: str, request: RelaxRequest, gates: GatesDep, chapter: ChapterDep) -> Any:
    return FastJSONResponse(action.relax_of_scene(scene_id, gates, chapter, **relax_options(request)))


@system_route(
    router,
    "/action/relax",
    summary="Find the path of a system you declare between two ends",
    description=RELAX_TEXT + " The system is given under `system` as for POST /api/derive; it runs in the worker pool.",
)
async def user_relax(client: ClientDep, users: UserSystemsDep, body: Annotated[UserRelaxRequest, Body()]) -> Response:
    spec, options = body.system.to_spec(), relax_options(body)
    return await answer(
        client,
        lambda key, address: users.simulation_job("relax", user_jobs.relax_job, checked(spec), options, key, address),
    )
