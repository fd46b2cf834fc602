"""ARCHITECTURE.md is a map: every file and every function it names at a hop of its walks exists."""

from __future__ import annotations

import os
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TEXT = (ROOT / "ARCHITECTURE.md").read_text()
SKIPPED = {".venv", "node_modules", ".git", ".cache", "build", "__pycache__"}


def project_files() -> list[Path]:
    """The project's files; the skipped folders are not even walked (a glob went through the whole .venv)."""
    out = []
    for folder, folders, names in os.walk(ROOT):
        folders[:] = [f for f in folders if f not in SKIPPED]
        out.extend(Path(folder, name) for name in names)
    return out


FILES = project_files()
# `engine/derivation/derive.derive`: a module (its path's tail) and a name defined in it
NAMED = re.compile(r"`([\w/]+)\.(\w+)`")
# `engine/parser/read.py`, `_derivation.html`, `scripts/lint.sh`: a file (its path's tail)
FILE = re.compile(r"`([\w/.-]+\.(?:py|html|sh|md|toml))`")


def where(tail: str) -> list[Path]:
    return [p for p in FILES if p.as_posix().endswith("/" + tail.lstrip("/"))]


def test_every_file_it_names_exists():
    missing = [tail for tail in FILE.findall(TEXT) if not where(tail)]
    assert not missing, f"ARCHITECTURE.md names files that do not exist: {missing}"


def test_every_function_it_names_is_defined_where_it_says():
    wrong = []
    for module, name in NAMED.findall(TEXT):
        if name in {"py", "html", "sh", "md", "toml"}:
            continue  # a file, checked above
        found = where(module + ".py") or where(module + "/__init__.py")
        defined = re.compile(rf"^\s*(?:async def|def|class) {name}\b|^{name}\s*[:=]", re.M)
        if not any(defined.search(p.read_text()) for p in found):
            wrong.append(f"{module}.{name}")
    assert not wrong, f"ARCHITECTURE.md names functions that are not where it says: {wrong}"
