"""The Jinja2 templates object and the /static files app, shared by every page.

``templates`` renders files under ``templates/`` (autoescaped); ``static_app``
serves ``static/`` (our CSS and JS modules, and ``static/vendor`` -- KaTeX and
plotly.js copied from npm by scripts/assets.sh, never from a CDN).
Templates get ``static(path)``, a URL with a version stamp so a browser never
keeps a stale module after an upgrade.
"""

from __future__ import annotations

import hashlib
from functools import cache
from pathlib import Path

from fastapi.staticfiles import StaticFiles
from fastapi.templating import Jinja2Templates


def _root() -> Path:
    # the source tree; an installed package (the Docker image) runs from its working directory
    here = Path(__file__).resolve().parents[2]
    return here if (here / "templates").is_dir() else Path.cwd()


ROOT = _root()
TEMPLATES_DIR = ROOT / "templates"
STATIC_DIR = ROOT / "static"

templates = Jinja2Templates(directory=str(TEMPLATES_DIR))
static_app = StaticFiles(directory=str(STATIC_DIR), check_dir=False)


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
templates.env.globals["vendor_ready"] = vendor_ready
