"""GET /docs: the interactive API reference, served entirely by this server.

FastAPI's built-in page loads swagger-ui from a CDN (a third-party script on
our origin, and a blank page in an offline classroom); this one loads the
copy scripts/assets.sh takes from npm into static/vendor, and starts it from a
file (static/js/api-docs.js), not an inline script, so the pages' CSP holds.
"""

from __future__ import annotations

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse

from app.web.rendering.templating import templates

router = APIRouter(include_in_schema=False)


@router.get("/docs", response_class=HTMLResponse)
async def api_docs(request: Request) -> HTMLResponse:
    return templates.TemplateResponse(request, "docs.html", {"spec_url": request.app.openapi_url})
