"""Precompute everything the chapter's pages need (``app.web.warm`` runs it at set-up and image build).

Derivations (JSON on disk), numba's compiled kernels and each scene's right-hand
sides (numba's disk cache), the work-precision reports, the measured normal modes and the chaotic scenes'
Lyapunov exponents (JSON on disk),
the tutor's catalogues of mistakes for every scene's steps (pickles on disk).

    python -m app.service.warm
"""

import time
from collections.abc import Callable, Sequence

from app.service.chapter import derivations
from app.service.simulations import lyapunov, modes, simulation, work_precision
from app.service.tutor import check_jobs


def main(more: Sequence[tuple[str, Callable[[], object]]] = ()) -> None:
    """Each step in turn, with its time; ``more``: steps of the layers above (app.web.warm)."""
    steps: list[tuple[str, Callable[[], object]]] = [
        ("derivations", derivations.warm_all),
        ("compiled integrators", lambda: simulation.warm_all(derivations.PROCESS_SCENES)),  # this process's scenes
        ("work-precision reports", work_precision.warm_all),
        ("measured normal modes", modes.warm_all),
        ("Lyapunov exponents", lyapunov.warm_all),
        ("the tutor's catalogues of mistakes", check_jobs.warm_all),
        *more,
    ]
    for name, step in steps:
        start = time.perf_counter()
        step()
        print(f"{name}: {time.perf_counter() - start:.1f} s", flush=True)


if __name__ == "__main__":
    main()
