#!/usr/bin/env bash
# Set up the app on a fresh machine: a virtual environment with the Python
# packages, the front-end libraries (KaTeX, plotly.js) from npm, copied into
# static/vendor so the app serves them itself (no CDN, works offline), and the
# caches a first request would otherwise wait for (derivations, numba's
# compiled kernels, the work-precision reports).  Idempotent.
# Usage: scripts/setup.sh [dev]   ("dev" adds the test tools)
set -euo pipefail
cd "$(dirname "$0")/.."

python=${PYTHON:-python3}
if [ ! -x .venv/bin/python ]; then
    "$python" -m venv .venv
fi
.venv/bin/python -m pip install --quiet --upgrade pip
# the versions the tests passed with (requirements.lock) as constraints
if [ "${1:-}" = "dev" ]; then
    .venv/bin/python -m pip install --quiet -c requirements.lock -e ".[dev]"
else
    .venv/bin/python -m pip install --quiet -c requirements.lock -e .
fi

scripts/assets.sh
# their zstd copies beside them (a browser that accepts zstd is sent 0.34 MB of plotly.js, not 0.39)
.venv/bin/python -m app.web.precompress
# the app's bytecode, written once here: a server started with PYTHONDONTWRITEBYTECODE set would
# otherwise compile every module of the app at every start (0.3-0.5 s)
.venv/bin/python -m compileall -q app
.venv/bin/python -m app.web.warm
mkdir -p .cache
scripts/stamp.sh > .cache/setup.stamp
