"""Routes for the chapter's scenes: list them, serve their derivations and their exports."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Query
from fastapi.responses import Response

from app.engine.document.contract import scene_json
from app.engine.document.model import Document
from app.service.chapter import derivations
from app.service.export import exporting
from app.service.export.exporting import Exported
from app.service.export.source import FORMATS
from app.service.runtime.encoding import dumps
from app.web.api.deps import AnswersDep, ChapterDep
from app.web.schemas.common import Problem, SceneSummary
from app.web.schemas.export import FORMAT_HELP, ExportFormat

router = APIRouter(prefix="/api", tags=["scenes"])


@router.get("/scenes", response_model=list[SceneSummary], summary="List the chapter's scenes")
def list_scenes() -> list[dict[str, Any]]:
    return [scene_json(s) for s in derivations.SCENES.values()]


@router.get(
    "/scenes/{scene_id}/derivation",
    summary="The step-by-step derivation of a scene",
    response_model=Document,
    responses={404: {"model": Problem, "description": "No scene has this id."}},
)
def scene_derivation(scene_id: str, chapter: ChapterDep) -> Response:
    # A plain `def`: FastAPI runs it in its thread pool, so a first (uncached) derivation and the document's
    # encoding (orjson) never block the event loop; the model is the OpenAPI's description. The bytes go out
    # uncompressed, so that the ETag (a digest of them, app/web/http/etags.py) is one for every coding; ApiCompression
    # compresses them after it.
    return Response(dumps(chapter.document(scene_id).as_json()), media_type="application/json")


def download(exported: Exported) -> Response:
    """A file to save: its media type and a Content-Disposition with its name."""
    return Response(
        exported.content,
        media_type=exported.media_type,
        headers={"Content-Disposition": f'attachment; filename="{exported.filename}"'},
    )


EXPORT_CONTENT = {media: {"schema": {"type": "string"}} for media, _ in FORMATS.values()}


@router.get(
    "/scenes/{scene_id}/export",
    summary="A scene's derivation as a notebook, a Python script or a LaTeX document",
    description=(
        "`format=ipynb`: a Jupyter notebook with each step in SymPy beside the engine's result, a simulation with "
        "scipy and a plot (needs sympy, scipy, matplotlib). `format=py`: a standalone script (numpy, scipy, sympy) "
        "that derives the accelerations from L, integrates the default start to t_end with DOP853 (rtol 1e-10, "
        'atol 1e-12) and prints `{"t": t_end, "state": {q: ..., q_dot: ...}}` as JSON on its last line. '
        "`format=tex`: a whole LaTeX document (article, amsmath) with every step."
    ),
    response_class=Response,
    responses={
        200: {"content": EXPORT_CONTENT, "description": "The file, as an attachment."},
        404: {"model": Problem, "description": "No scene has this id."},
        422: {"model": Problem, "description": "The format is missing or not one of ipynb, py, tex."},
    },
)
def scene_export(
    scene_id: str,
    fmt: Annotated[ExportFormat, Query(alias="format", description=FORMAT_HELP)],
    answers: AnswersDep,
    chapter: ChapterDep,
) -> Response:
    # a plain `def`: the first export of a scene may derive it, in FastAPI's thread pool
    return download(exporting.scene_export(scene_id, fmt, chapter.document, answers.exports))
