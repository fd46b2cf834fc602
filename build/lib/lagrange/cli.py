"""The console command: ``lagrange serve`` starts the web book (uvicorn, as scripts/serve.sh does)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="lagrange", description="Lagrangian mechanics, step by step.")
    commands = parser.add_subparsers(dest="command", required=True)
    serve = commands.add_parser("serve", help="serve the web book (from the project's directory)")
    serve.add_argument("--host", default="127.0.0.1", help="address to listen on (default 127.0.0.1)")
    serve.add_argument("--port", type=int, default=8000, help="port (default 8000)")
    args = parser.parse_args(argv)

    from app.settings import ROOT

    # the pages' templates and static files are not part of the Python package: they live in the project
    if not (Path(ROOT) / "templates").is_dir() or not (Path(ROOT) / "static").is_dir():
        print(
            f"lagrange serve: no templates/ and static/ in {ROOT}: run it from the project's directory "
            "(a clone of the repository, after scripts/setup.sh)",
            file=sys.stderr,
        )
        return 2
    import uvicorn

    uvicorn.run("app.main:app", host=args.host, port=args.port)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
