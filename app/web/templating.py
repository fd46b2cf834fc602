"""The Jinja2 templates object and the /static files app, shared by every page.

``templates`` renders files under ``templates/`` (autoescaped); ``static_app()``,
the app's own (mounted by ``app.main``, with its cache of compressed files), serves ``static/`` (our CSS and JS modules, and ``static/vendor`` -- KaTeX and
plotly.js copied from npm by scripts/assets.sh, never from a CDN).
Templates get ``static(path)``, a URL with a version stamp so a browser never
keeps a stale module after an upgrade.
"""

from __future__ import annotations

import gzip
import hashlib
import stat as stat_mode
from functools import cache
from pathlib import Path
from typing import Any

import anyio
from fastapi.staticfiles import StaticFiles
from fastapi.templating import Jinja2Templates
from starlette.datastructures import Headers
from starlette.responses import Response
from starlette.types import Scope

from app.settings import ROOT
from app.viz.chapter import ABOUT
from app.viz.page_model import SLIDER_STEPS, unit_text
from app.web.compression import negotiate
from app.web.embed_views import offers as embed_offers
from app.web.mathml import mathml
from app.web.prose import prose_html


class ClassroomStaticFiles(StaticFiles):
    """Static files for a room of browsers on one network.

    A client that accepts gzip gets the ``name.gz`` sibling that scripts/assets.sh
    wrote next to each vendor file (plotly.js basic bundle: 1.2 MB on disk, about 0.36 MB sent),
    without compressing anything per request; a URL stamped with a content hash
    (``?v=...``, see ``static()``) may be kept by the browser for a year.
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # our own small modules and styles, gzipped, by (path, modification time, size): this app's, not a module's
        self._gzipped: dict[tuple[str, int, int], bytes] = {}

    async def get_response(self, path: str, scope: Scope) -> Response:
        response = await self._compressed(path, scope) or await super().get_response(path, scope)
        if b"v=" in scope.get("query_string", b"") and response.status_code in (200, 304):
            response.headers["Cache-Control"] = "public, max-age=31536000, immutable"
        return response

    async def _compressed(self, path: str, scope: Scope) -> Response | None:
        gzip_accepted = negotiate(Headers(scope=scope).get("accept-encoding", ""), ("gzip",))
        if scope["method"] not in ("GET", "HEAD") or not gzip_accepted:
            return None
        try:
            full_path, found = await anyio.to_thread.run_sync(self.lookup_path, path + ".gz")
        except (OSError, ValueError):
            return None
        if found is None or not stat_mode.S_ISREG(found.st_mode):
            return await self._compress_small(path)
        response = self.file_response(full_path, found, scope)
        response.headers["Content-Encoding"] = "gzip"
        response.headers["Vary"] = "Accept-Encoding"
        return response

    async def _compress_small(self, path: str) -> Response | None:
        """Our own modules and styles (no .gz sibling, which could go stale while they are edited),
        compressed once per version of the file and kept in memory."""
        if not path.endswith((".js", ".css", ".svg")):
            return None
        try:
            full_path, found = await anyio.to_thread.run_sync(self.lookup_path, path)
        except (OSError, ValueError):
            return None
        if found is None or not stat_mode.S_ISREG(found.st_mode) or found.st_size > _SMALL:
            return None
        key = (full_path, found.st_mtime_ns, found.st_size)
        body = self._gzipped.get(key)
        if body is None:
            body = await anyio.to_thread.run_sync(lambda: gzip.compress(Path(full_path).read_bytes(), 9))
            self._gzipped[key] = body
        media = {"js": "text/javascript", "css": "text/css", "svg": "image/svg+xml"}[path.rsplit(".", 1)[1]]
        return Response(body, media_type=media, headers={"Content-Encoding": "gzip", "Vary": "Accept-Encoding"})


_SMALL = 512 * 1024


TEMPLATES_DIR = ROOT / "templates"
STATIC_DIR = ROOT / "static"

templates = Jinja2Templates(directory=str(TEMPLATES_DIR))


def static_app() -> ClassroomStaticFiles:
    """A new /static files app (each app mounts its own: its compressed files are its own)."""
    return ClassroomStaticFiles(directory=str(STATIC_DIR), check_dir=False)


@cache
def _stamp(path: str) -> str:
    try:
        return hashlib.sha256((STATIC_DIR / path).read_bytes()).hexdigest()[:10]
    except OSError:
        return "missing"


def static(path: str) -> str:
    """The URL of a static file, stamped with a hash of its content."""
    return f"/static/{path}?v={_stamp(path)}"


def vendor_ready() -> bool:
    """Whether scripts/assets.sh has copied KaTeX and plotly.js into static/vendor."""
    return (STATIC_DIR / "vendor" / "katex" / "katex.min.js").is_file() and (
        STATIC_DIR / "vendor" / "plotly" / "plotly.min.js"
    ).is_file()


templates.env.globals["static"] = static
templates.env.globals["embed_offers"] = embed_offers  # the scene page's frames for a course page
templates.env.globals["vendor_ready"] = vendor_ready
templates.env.globals["chapter_about"] = ABOUT
templates.env.globals["slider_steps"] = SLIDER_STEPS  # the controls' slider resolution, for the browser
templates.env.filters["mathml"] = mathml
templates.env.filters["prose"] = prose_html  # a sentence's symbols with their subscripts set (app/web/prose.py)
templates.env.filters["unit"] = unit_text  # a unit as printed: m/s², m⁻¹ (app/viz/page_model.py)
