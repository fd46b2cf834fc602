"""The Jinja2 templates object and the /static files app, shared by every page.

``templates`` renders files under ``templates/`` (autoescaped); ``static_app()``,
the app's own (mounted by ``app.main``, with its cache of compressed files), serves ``static/`` (our CSS and JS modules, and ``static/vendor`` -- KaTeX and
plotly.js copied from npm by scripts/assets.sh, never from a CDN).
Templates get ``static(path)``, a URL with a version stamp so a browser never
keeps a stale module after an upgrade.
"""

from __future__ import annotations

import hashlib
import mimetypes
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
from app.web.http.compression import STATIC, compress_once, negotiate
from app.web.rendering.embed_views import embeddable
from app.web.rendering.embed_views import offers as embed_offers
from app.web.rendering.mathml import mathml
from app.web.rendering.prose import prose_html, statement_html


class ClassroomStaticFiles(StaticFiles):
    """Static files for a room of browsers on one network.

    A client that accepts zstd or gzip gets the file compressed once, in the coding it prefers (ours: zstd, then
    gzip, ``compression.STATIC``): a vendor library from the copy beside it (``name.zst`` written by
    app/web/precompress.py at set-up, ``name.gz`` by scripts/assets.sh; plotly.js basic is 1.2 MB on disk, 344 kB
    sent in zstd and 395 kB in gzip), our own modules and styles compressed in memory on first use; nothing is
    compressed per request. A URL stamped with a content hash (``?v=...``, see ``static()``) may be kept by the
    browser for a year.
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # our own small modules and styles, compressed, by (path, modification time, size, coding): this app's
        self._packed: dict[tuple[str, int, int, str], bytes] = {}

    async def get_response(self, path: str, scope: Scope) -> Response:
        response = await self._compressed(path, scope) or await super().get_response(path, scope)
        if b"v=" in scope.get("query_string", b"") and response.status_code in (200, 304):
            response.headers["Cache-Control"] = "public, max-age=31536000, immutable"
        return response

    async def _compressed(self, path: str, scope: Scope) -> Response | None:
        accept = Headers(scope=scope).get("accept-encoding", "")
        coding = negotiate(accept, STATIC)
        if scope["method"] not in ("GET", "HEAD") or coding is None:
            return None
        # the preferred coding's copy, else gzip's (a set-up that wrote no .zst), else compressed here
        for choice in dict.fromkeys((coding, negotiate(accept, ("gzip",)))):
            if choice is None:
                continue
            try:
                full_path, found = await anyio.to_thread.run_sync(self.lookup_path, path + STATIC[choice][0])
            except (OSError, ValueError):
                return None
            if found is not None and stat_mode.S_ISREG(found.st_mode):
                response = self.file_response(full_path, found, scope)
                # the type is the file's, not its copy's (a .zst name would be guessed application/zstd, which a
                # browser refuses to run as a script)
                response.headers["Content-Type"] = _media_type(path)
                response.headers["Content-Encoding"] = choice
                response.headers["Vary"] = "Accept-Encoding"
                return response
        return await self._compress_small(path, coding)

    async def _compress_small(self, path: str, coding: str) -> Response | None:
        """Our own modules and styles (no sibling copy, which could go stale while they are edited),
        compressed once per version of the file and coding, and kept in memory."""
        if not path.endswith((".js", ".css", ".svg")):
            return None
        try:
            full_path, found = await anyio.to_thread.run_sync(self.lookup_path, path)
        except (OSError, ValueError):
            return None
        if found is None or not stat_mode.S_ISREG(found.st_mode) or found.st_size > _SMALL:
            return None
        key = (full_path, found.st_mtime_ns, found.st_size, coding)
        body = self._packed.get(key)
        if body is None:
            body = await anyio.to_thread.run_sync(lambda: compress_once(Path(full_path).read_bytes(), coding))
            self._packed[key] = body
        return Response(body, media_type=_media_type(path), headers={"Content-Encoding": coding, "Vary": "Accept-Encoding"})


_SMALL = 512 * 1024


def _media_type(path: str) -> str:
    """The Content-Type of a static file, by its name: a module or style sheet with its charset."""
    guessed = mimetypes.guess_type(path)[0] or "application/octet-stream"
    return f"{guessed}; charset=utf-8" if guessed.startswith("text/") else guessed


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
templates.env.globals["embeddable"] = embeddable  # the plots a frame may show beside the animation
templates.env.globals["vendor_ready"] = vendor_ready
templates.env.globals["chapter_about"] = ABOUT
templates.env.globals["slider_steps"] = SLIDER_STEPS  # the controls' slider resolution, for the browser
templates.env.filters["mathml"] = mathml
templates.env.filters["prose"] = prose_html  # a sentence's symbols with their subscripts set (app/web/rendering/prose.py)
# a problem statement: prose, with each formula's minus sign kept on the line of its term
templates.env.filters["statement"] = statement_html
templates.env.filters["unit"] = unit_text  # a unit as printed: m/s², m⁻¹ (app/viz/page_model.py)
