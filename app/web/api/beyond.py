"""Beyond the chapter: Poincaré sections and measured normal modes, for scenes and user systems.

Scene routes are plain ``def`` (FastAPI's thread pool; the integration releases the GIL);
user systems go through the worker pool with its time limit, cache and fair share.
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body
from fastapi.responses import Response

from app.service.simulations import modes, poincare
from app.service.users.user_checks import checked
from app.web.api.deps import AnswersDep, ChapterDep, ClientDep, GatesDep, UserSystemsDep
from app.web.api.simulate import ERRORS, scene_route
from app.web.api.user import answer, system_route
from app.web.http.responses import FastJSONResponse
from app.web.schemas.beyond import (
    MeasuredModes,
    ModesRequest,
    PoincareRequest,
    PoincareResponse,
    UserPoincareRequest,
    poincare_options,
)
from app.web.schemas.user import SystemSpec, system_of

router = APIRouter(prefix="/api", tags=["beyond the chapter"])

POINCARE_TEXT = (
    "Several orbits on one energy surface h = E, each recorded where the chosen coordinate crosses the plane "
    "coordinate = value in the given direction; the points are (q, p) of the other coordinate. Needs two "
    "conservative degrees of freedom. Orbits start on the plane, spread across its accessible part."
)
MODES_CORE = (
    "For each equilibrium at rest with an oscillating mode: every mode's predicted ω = √ω² and shape beside the ω "
    "measured from a simulation started at the equilibrium displaced along the mode by a small amplitude"
)
MODES_TEXT = MODES_CORE + " (default parameters)."


@scene_route(
    router,
    "/scenes/{scene_id}/poincare",
    summary="A scene's Poincaré section",
    description=POINCARE_TEXT,
    document=PoincareResponse,
)
def scene_poincare(
    scene_id: str, request: PoincareRequest, gates: GatesDep, answers: AnswersDep, chapter: ChapterDep
) -> Any:
    # a refusal (SimulationError) or an unknown scene is answered by app/web/api/errors.py
    options = poincare_options(request)
    return FastJSONResponse(poincare.cached_section_of_scene(scene_id, gates, answers.sections, chapter, **options))


@router.get(
    "/scenes/{scene_id}/modes",
    summary="A scene's normal modes, predicted against measured",
    description=MODES_TEXT,
    response_model=list[MeasuredModes],
    responses={404: ERRORS[404], 429: ERRORS[429]},
)
def scene_modes(scene_id: str, gates: GatesDep, answers: AnswersDep, chapter: ChapterDep) -> Any:
    return FastJSONResponse(modes.measure_scene(scene_id, gates, answers.measured_modes, chapter))


@scene_route(
    router,
    "/scenes/{scene_id}/modes-at",
    summary="A scene's normal modes at given parameter values, predicted against measured",
    description=MODES_CORE
    + ", at the parameter values given (each missing one at the scene's default): the equilibria and M, K follow "
    "them from the engine's closed forms. An equilibrium the engine found only numerically is given at the "
    "defaults alone, with at_defaults true.",
    response_model=list[MeasuredModes],
)
def scene_modes_at(
    scene_id: str, request: ModesRequest, gates: GatesDep, answers: AnswersDep, chapter: ChapterDep
) -> Any:
    # a value out of range or an unknown name (SimulationError) is answered by app/web/api/errors.py
    return FastJSONResponse(modes.modes_at(scene_id, request.parameters, gates, answers.modes_at, chapter))


@system_route(
    router,
    "/poincare",
    summary="The Poincaré section of a system you declare",
    description=POINCARE_TEXT + " The system is given as for POST /api/derive; it runs in the worker pool.",
    response_model=PoincareResponse,
)
async def user_poincare(
    client: ClientDep, users: UserSystemsDep, body: Annotated[UserPoincareRequest, Body()]
) -> Response:
    spec = system_of(body)
    options = poincare_options(body)
    options.pop("parameters", None)
    return await answer(client, lambda key, address: users.poincare(checked(spec), options, key, address))


@system_route(
    router,
    "/modes",
    summary="Normal modes of a system you declare, predicted against measured",
    description=MODES_TEXT + " The system is given as for POST /api/derive; it runs in the worker pool.",
    response_model=list[MeasuredModes],
)
async def user_modes(client: ClientDep, users: UserSystemsDep, system: Annotated[SystemSpec, Body()]) -> Response:
    return await answer(client, lambda key, address: users.modes(checked(system.to_spec()), key, address))
