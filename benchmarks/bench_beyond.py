"""What Hamilton's equations and the normal modes add to a scene's derivation document.

For each chapter scene: the time to build the document without them (derivation
JSON with its steps), then the time of the added parts alone (engine, steps and
JSON), each in a fresh display budget.  Goal: the added parts take at most 25 %
of the chapter's documents in total.

    .venv/bin/python -m benchmarks.bench_beyond
"""

from __future__ import annotations

import time

from app.engine.algebra.budget import display_budget
from app.engine.derivation.derive import derive
from app.engine.document.contract import DISPLAY_WORK, add_beyond, derivation_json
from app.engine.document.report import Printer
from app.scenes import SCENES

GOAL = 0.25


def main() -> None:
    base_total = added_total = 0.0
    print(f"{'scene':22s} {'document (s)':>12s} {'added (s)':>10s}")
    for sid, scene in SCENES.items():
        d = derive(scene.system)
        start = time.perf_counter()
        doc = derivation_json(d, scene, beyond=False)
        base = time.perf_counter() - start
        with display_budget(DISPLAY_WORK):
            start = time.perf_counter()
            add_beyond(d, scene, doc, Printer(d.table.latex_names()))
            added = time.perf_counter() - start
        print(f"{sid:22s} {base:12.2f} {added:10.2f}")
        if not scene.beyond_chapter:
            base_total, added_total = base_total + base, added_total + added
    ratio = added_total / base_total
    print(
        f"chapter scenes: documents {base_total:.2f} s, added {added_total:.2f} s, ratio {ratio:.2f} (goal <= {GOAL})"
    )


if __name__ == "__main__":
    main()
