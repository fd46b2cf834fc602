"""Parametrizations computed by the engine, kept on disk between runs so collecting the suite stays cheap.

Some modules list their cases by running the engine (one case per equilibrium found, say). pytest collects
every module in every worker before a test runs, so that work would be paid once per worker and per run,
also when none of those tests is selected.  ``case_list`` stores the list as JSON under
``<cache>/test-cases``, keyed by the source of ``app/engine`` and ``app/scenes``, the test files named, and
SymPy's version: a change to any of them computes it again.  Only the list of cases is cached; each test still
computes everything it checks.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from pathlib import Path

import sympy

from app.service.cache import JsonCache, source_fingerprint


def case_list(name: str, compute: Callable[[], list[tuple]], *sources: str | Path) -> list[tuple]:
    digest = hashlib.sha256(f"{source_fingerprint('engine', 'scenes')} sympy {sympy.__version__}".encode())
    for source in sources:
        digest.update(Path(source).read_bytes())
    cache = JsonCache("test-cases", digest.hexdigest()[:16])
    return [tuple(case) for case in cache.get(name, lambda: [list(case) for case in compute()])]
