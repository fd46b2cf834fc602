"""Precompute what the chapter's pages need: run at image build and before serving.

    python -m app.service.warm
"""

from app.service.derivations import warm_all


def main() -> None:
    warm_all()


if __name__ == "__main__":
    main()
