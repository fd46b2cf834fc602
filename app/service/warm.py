"""Precompute everything the chapter's pages need: run at image build and before serving.

Derivations (JSON on disk), numba's compiled kernels and each scene's right-hand
sides (numba's disk cache), the work-precision reports and the measured normal modes (JSON on disk).

    python -m app.service.warm
"""

import time

from app.service import derivations, modes, simulation, work_precision


def main() -> None:
    for name, step in (
        ("derivations", derivations.warm_all),
        ("compiled integrators", simulation.warm_all),
        ("work-precision reports", work_precision.warm_all),
        ("measured normal modes", modes.warm_all),
    ):
        start = time.perf_counter()
        step()
        print(f"{name}: {time.perf_counter() - start:.1f} s", flush=True)


if __name__ == "__main__":
    main()
