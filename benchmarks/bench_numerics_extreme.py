"""The stiff and extreme cases: what ``auto`` chose, the error reached, run time, energy drift.

The cases are tests/numerics/extreme_cases.py (the same the tests check).  Time is the
simulation's wall time without compilation (numba loads from its disk cache after the first run),
including the second run that gives the error estimate.

    .venv/bin/python -m benchmarks.bench_numerics_extreme
"""

from __future__ import annotations

from tests.numerics.extreme_cases import CASES, run


def fmt(x: float | None) -> str:
    return "–" if x is None else f"{x:.1e}"


def main() -> None:
    print(
        "| case | rtol | auto chose | error vs exact | error estimate | time s | drift of E (h if E is not conserved) | notes |"
    )
    print("|---|---|---|---|---|---|---|---|")
    for case in CASES:
        r = run(case)
        o = r.outcome
        est = o.estimate.value if o.estimate else None
        notes = [*o.warnings, *r.summary["warnings"]]
        if "p_phi" in r.summary["conserved_drift"]:
            notes.insert(0, f"p_φ drift {r.summary['conserved_drift']['p_phi']['relative']:.1e} (rel.)")
        text = "; ".join(n.split(":")[0] if len(n) > 90 else n for n in notes) or ""
        print(
            f"| {case.name} | {case.rtol:.0e} | {o.method} | {fmt(r.true_error)} | {fmt(est)} | {r.seconds:.3f} | "
            f"{fmt(r.energy_drift)} | {text} |"
        )


if __name__ == "__main__":
    main()
