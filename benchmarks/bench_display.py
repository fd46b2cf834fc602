"""What the textbook forms cost: each scene's derivation document, and a user's double pendulum, cold.

For each system the derivation (``derive``) is done once; then its document (``derivation_json``: steps,
results, Hamilton's equations, normal modes) is built three ways, with every cache of ours and SymPy's
emptied before each build:

* ``none``      every expression printed as the engine made it (no display simplification at all);
* ``before``    the display simplification this project had before the textbook forms (sin² + cos² = 1
                collapsed, then SymPy's ``simplify`` within its budget: ``tidy(pythagoras(expr))``);
* ``forms``     the textbook forms (app.engine.display.forms), as served.

It reports each time, ``forms / none`` (what the forms add over printing alone) and ``forms / before``
(the goal: no more than before, ≤ 1).  Times are the minimum of REPEATS runs; note the load average.

    PYTHONPATH=$PWD .venv/bin/python -m benchmarks.bench_display
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from contextlib import contextmanager
from typing import Any

import sympy as sp
from sympy.core.cache import clear_cache

from app.engine.algebra import simplify
from app.engine.derivation.derive import Derivation, derive
from app.engine.display import forms
from app.engine.document import report
from app.engine.document.contract import derivation_json
from app.scenes import SCENES
from tests.engine.unseen_systems import UNSEEN

REPEATS = 2


def _identity(expr: Any, names: Any = None, seconds: float = 0.0) -> Any:
    return expr


def _before(expr: Any, names: Any = None, seconds: float = 0.0) -> Any:
    if not isinstance(expr, sp.Expr) or not expr.free_symbols:
        return expr
    return simplify.tidy(simplify.pythagoras(expr))


@contextmanager
def _display(kind: str):
    """Swap the textbook form for another display form (where report and the contract call it)."""
    replacement: Callable[..., Any] | None = {"none": _identity, "before": _before}.get(kind)
    saved = (forms.textbook_form, report.textbook_form)
    if replacement is not None:
        forms.textbook_form = report.textbook_form = replacement  # type: ignore[assignment]
    try:
        yield
    finally:
        forms.textbook_form, report.textbook_form = saved


def _cold() -> None:
    clear_cache()
    forms._CACHE.clear()
    simplify._TIDY_CACHE.clear()


def _time(d: Derivation, kind: str, scene: Any) -> float:
    best = float("inf")
    for _ in range(REPEATS):
        _cold()
        with _display(kind):
            started = time.perf_counter()
            derivation_json(d, scene)
            best = min(best, time.perf_counter() - started)
    return best


def main() -> None:
    print(f"load average at start: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    cases: list[tuple[str, Derivation, Any]] = [(sid, derive(s.system), s) for sid, s in SCENES.items()]
    cases.append(("user double pendulum", derive(UNSEEN["double-pendulum"].system), None))
    print(f"{'system':<24}{'none s':>9}{'before s':>10}{'forms s':>9}{'forms/none':>12}{'forms/before':>14}")
    totals = {"none": 0.0, "before": 0.0, "forms": 0.0}
    for name, d, scene in cases:
        times = {kind: _time(d, kind, scene) for kind in ("none", "before", "forms")}
        for kind, value in times.items():
            totals[kind] += value
        print(
            f"{name:<24}{times['none']:>9.2f}{times['before']:>10.2f}{times['forms']:>9.2f}"
            f"{times['forms'] / times['none']:>12.2f}{times['forms'] / times['before']:>14.2f}"
        )
    print(
        f"{'all':<24}{totals['none']:>9.2f}{totals['before']:>10.2f}{totals['forms']:>9.2f}"
        f"{totals['forms'] / totals['none']:>12.2f}{totals['forms'] / totals['before']:>14.2f}"
    )
    print(f"load average at end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
