"""Routes for the chapter's scenes: list them and serve their derivations."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter

from app.service import derivations
from app.web.schemas import ErrorResponse, SceneSummary

router = APIRouter(prefix="/api", tags=["scenes"])


@router.get("/scenes", response_model=list[SceneSummary], summary="List the chapter's scenes")
def list_scenes() -> list[dict[str, Any]]:
    return [derivations.scene_summary(s) for s in derivations.SCENES.values()]


@router.get(
    "/scenes/{scene_id}/derivation",
    summary="The step-by-step derivation of a scene",
    responses={404: {"model": ErrorResponse, "description": "No scene has this id."}},
)
def scene_derivation(scene_id: str) -> dict[str, Any]:
    # A plain `def`: FastAPI runs it in its thread pool, so a first (uncached)
    # derivation never blocks the event loop.
    return derivations.derivation_document(scene_id)
