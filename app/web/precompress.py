"""The vendor libraries compressed once at set-up: ``python -m app.web.precompress``.

scripts/setup.sh runs it after scripts/assets.sh has copied KaTeX, plotly.js and swagger-ui into
static/vendor (and written their ``.gz`` copies); the Dockerfile runs it while building the image. It writes
each ``.js`` and ``.css`` file's zstd copy beside it (``name.js.zst``, ``compression.STATIC``'s level), which
the static files app (app/web/rendering/templating.py) sends to a browser that accepts zstd. A copy older than its file
is written again; the vendor folder is made anew by scripts/assets.sh, so no copy outlives its file.
"""

from __future__ import annotations

import sys
from pathlib import Path

from app.web.http.compression import STATIC, compress_once
from app.web.rendering.templating import STATIC_DIR


def precompress(folder: Path, coding: str = "zstd") -> list[Path]:
    """Write ``coding``'s copy of every .js and .css file under ``folder`` that lacks a fresh one; the copies written."""
    suffix = STATIC[coding][0]
    written = []
    for source in sorted([*folder.rglob("*.js"), *folder.rglob("*.css")]):
        copy = source.with_name(source.name + suffix)
        if copy.is_file() and copy.stat().st_mtime_ns >= source.stat().st_mtime_ns:
            continue
        copy.write_bytes(compress_once(source.read_bytes(), coding))
        written.append(copy)
    return written


def main() -> int:
    vendor = STATIC_DIR / "vendor"
    if not vendor.is_dir():
        print("static/vendor is missing: run scripts/assets.sh first", file=sys.stderr)
        return 1
    written = precompress(vendor)
    print(f"{len(written)} zstd copies written under {vendor}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
