#!/usr/bin/env bash
# Set up (idempotent) and serve the app on http://127.0.0.1:8000.
# HOST, PORT and WORKERS may be set in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# The app derives the chapter and loads its compiled integrators in the background
# at start-up (cached on disk after the first run); `python -m app.service.warm`
# also precomputes the work-precision reports, as the Docker image does at build.
exec .venv/bin/uvicorn app.main:app --host "${HOST:-127.0.0.1}" --port "${PORT:-8000}" \
    --workers "${WORKERS:-1}" --timeout-keep-alive 75
