"""Precompute everything the server needs at start: run at set-up and at image build.

The service's caches (``app.service.warm``: derivations, compiled kernels, work-precision
reports, measured modes), then the playground examples' derivations, so that a restarted
server loads all of them from disk and derives nothing.

    python -m app.web.warm
"""

from app.service import warm
from app.web.pages.playground import example_derivations


def main() -> None:
    warm.main(more=[("playground examples", example_derivations)])


if __name__ == "__main__":
    main()
