"""Deterministic results the tests need, computed once and kept on disk between runs (keyed by source).

``case_list``: some modules list their cases by running the engine (one case per equilibrium found, say).
pytest collects every module in every worker before a test runs, so that work would be paid once per worker
and per run, also when none of those tests is selected.  Only the list of cases is kept; each test still
computes everything it checks.

``stored``: a JSON result of the tests' own independent route (tests/reference.py), which does not change
unless its source or SymPy does.

Both live under ``<cache>/tests``, keyed by the source of the named ``app`` packages, the test files named, and
SymPy's version: a change to any of them computes the result again.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from pathlib import Path
from typing import Any

import sympy

from app.service.runtime.cache import JsonCache, source_fingerprint


def stored(name: str, compute: Callable[[], Any], sources: tuple[str | Path, ...], packages: tuple[str, ...]) -> Any:
    digest = hashlib.sha256(f"{source_fingerprint(*packages)} sympy {sympy.__version__}".encode())
    for source in sources:
        digest.update(Path(source).read_bytes())
    return JsonCache("tests", digest.hexdigest()[:16]).get(name, compute)


def case_list(name: str, compute: Callable[[], list[tuple]], *sources: str | Path) -> list[tuple]:
    """The cases ``compute`` lists from the engine's results (lists of JSON values), as tuples."""
    cases = stored(name, lambda: [list(case) for case in compute()], sources, ("engine", "scenes"))
    return [tuple(case) for case in cases]
