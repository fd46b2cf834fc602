"""POST /api/typeset: a student's answer typeset as it is typed, by the checker's own parser.

The practice boxes of the pages send the text as it is typed and show the LaTeX, or the parser's
refusal word for word as POST /api/check would give it.  The route is ``async`` and runs no SymPy:
the service refuses bad text in pure Python and typesets in the worker pool, under the checker's time
limit and fair share (app/service/tutor/typesetting.py).
"""

from __future__ import annotations

from fastapi import APIRouter
from fastapi.responses import Response

from app.web.api.check import ERRORS
from app.web.api.deps import CheckingDep, ClientDep
from app.web.api.user import answer
from app.web.schemas.typeset import TypesetRequest, TypesetResponse

router = APIRouter(prefix="/api", tags=["practice"])


@router.post(
    "/typeset",
    summary="Typeset an answer as the checker reads it",
    description="The LaTeX of `text` as the step checker parses it, for the scene `scene` or for a declared system "
    "given by its `coordinates` and `parameters`; a text the checker would refuse gets the checker's own 422 "
    "(`part` and `start`/`end` locate the offending part). For live typesetting while a student types.",
    response_model=TypesetResponse,
    responses=ERRORS,
)
async def typeset(client: ClientDep, checker: CheckingDep, body: TypesetRequest) -> Response:
    return await answer(
        client,
        lambda key, address: checker.typesetter.typeset(
            body.text, body.step, body.scene, body.names(), key, address, body.coordinate
        ),
    )
