#!/usr/bin/env bash
# Serve the app on http://127.0.0.1:8000, setting up first only when needed: on
# a fresh clone, or when the dependency lists or set-up scripts changed since
# the last set-up (scripts/stamp.sh).  HOST, PORT and WORKERS may be set.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -x .venv/bin/uvicorn ] || [ ! -d static/vendor ] \
    || [ "$(cat .cache/setup.stamp 2>/dev/null)" != "$(scripts/stamp.sh)" ]; then
    scripts/setup.sh
fi
# The app loads the chapter's derivations and compiled integrators in the background
# at start-up (from the caches set-up filled) and answers with scipy meanwhile.
# One web process unless WORKERS says otherwise; the slow-client options as in scripts/serve.sh.
export LAGRANGE_WEB_PROCESSES="${WORKERS:-1}"
# shellcheck disable=SC2046 # the options are words
exec .venv/bin/uvicorn app.main:app --host "${HOST:-127.0.0.1}" --port "${PORT:-8000}" \
    $(.venv/bin/python -m app.web.http.server_options)
