"""POST /api/scenes/{id}/simulate and GET /api/scenes/{id}/work-precision.

Plain ``def`` routes: FastAPI runs them in its thread pool, and the compiled
integration loops release the GIL, so simulations run in parallel and never
block the event loop; the response is encoded there too (orjson).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from fastapi import APIRouter

from app.service.simulations import simulation, work_precision
from app.web.api.deps import AnswersDep, ChapterDep, GatesDep
from app.web.api.limits import MAX_BODY_BYTES
from app.web.http.responses import FastJSONResponse
from app.web.schemas.common import Problem
from app.web.schemas.simulate import SimulateRequest, SimulateResponse, WorkPrecision

router = APIRouter(prefix="/api", tags=["simulation"])

ERRORS = {
    400: {"model": Problem, "description": "The body is not JSON (or not UTF-8, or nested too deeply)."},
    404: {"model": Problem, "description": "No scene has this id."},
    422: {
        "model": Problem,
        "description": "A value outside its range, NaN or Infinity, an unknown name, a method that does not apply, "
        "or too much work for the time and step budget (the message says which and what to change).",
    },
    429: {"model": Problem, "description": "Too many simulations are running at once."},
}
BODY_ERRORS = {413: {"model": Problem, "description": f"The body is larger than {MAX_BODY_BYTES} bytes."}}


def scene_route(
    router: APIRouter, path: str, summary: str, description: str, document: Any = None, **route: Any
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """POST ``path`` for a scene with a request body: documented with the scenes' errors and, for a route that
    answers encoded JSON (FastJSONResponse, which FastAPI does not check), its ``document``'s model."""
    responses: dict[int | str, dict[str, Any]] = {**ERRORS, **BODY_ERRORS}
    if document is not None:
        responses = {200: {"model": document}, **responses}
        route["response_model"] = None
    return router.post(path, summary=summary, description=description, responses=responses, **route)


@scene_route(
    router,
    "/scenes/{scene_id}/simulate",
    summary="Simulate a scene",
    description=(
        "Integrate the engine's equations of motion from the given initial state. Returns evenly spaced samples "
        "of the state, the energy E, the energy function h, each conserved quantity and constraint force, and stats: "
        "the method (and why 'auto' chose it), steps, right-hand-side evaluations, wall time, an estimate of the "
        "global error of the coordinates (from a second, more accurate run), drifts and warnings."
    ),
    document=SimulateResponse,
)
def simulate_scene(scene_id: str, request: SimulateRequest, gates: GatesDep, chapter: ChapterDep) -> Any:
    # encoded here, in the thread pool, by orjson (numpy arrays directly); a refusal is answered by app/web/api/errors.py
    return FastJSONResponse(simulation.simulate_scene(scene_id, request, gates, chapter))


@router.get(
    "/scenes/{scene_id}/work-precision",
    summary="Error against run time for several methods",
    description=(
        "For at least four methods over a tolerance sweep (rtol 1e-3 to 1e-12): the final-state error against "
        "an exact solution where one is known (else a high-precision reference whose own error is checked), the "
        "run time (minimum of several runs after a warm-up) and the right-hand-side evaluations. Cached per scene."
    ),
    response_model=WorkPrecision,
    responses={404: ERRORS[404]},
)
def scene_work_precision(scene_id: str, answers: AnswersDep) -> dict[str, Any]:
    return work_precision.for_scene(scene_id, answers.work_precision)
