"""Exports of a derivation: a Jupyter notebook, a standalone Python script, a LaTeX document.

Pure functions of a ``Source`` (a derivation, its JSON document and the
problem's data); ``render`` picks one by format.  The service glue that feeds
them scenes and user systems is ``app.service.export.exporting``.
"""

from __future__ import annotations

from collections.abc import Callable

from app.service.export.latex import latex
from app.service.export.notebook import notebook
from app.service.export.script import script
from app.service.export.source import FORMATS, Source

RENDERERS: dict[str, Callable[[Source], str]] = {"ipynb": notebook, "py": script, "tex": latex}
assert set(RENDERERS) == set(FORMATS)


def render(source: Source, fmt: str) -> str:
    return RENDERERS[fmt](source)


def filename(source: Source, fmt: str) -> str:
    return f"{source.stem}.{fmt}"
