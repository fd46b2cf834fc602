#!/usr/bin/env bash
# Set up (idempotent, dev tools included) and run the whole test suite: lint (scripts/lint.sh), then pytest
# (engine, API, numerics, and the pages in Debian's headless Chromium; exported
# LaTeX documents are compiled with Debian's pdflatex; the classes' database also on Debian's PostgreSQL,
# their limits across replicas on Debian's redis-server).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh dev
if [ ! -x /usr/bin/chromium ]; then
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends chromium fonts-liberation >/dev/null
fi
if ! command -v pdflatex >/dev/null; then
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends texlive-latex-base texlive-latex-recommended >/dev/null
fi
# the classes' tests start a throwaway PostgreSQL cluster (tests/postgres.py) with Debian's binaries
if ! ls /usr/lib/postgresql/*/bin/initdb >/dev/null 2>&1; then
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends postgresql >/dev/null
fi
# the classes across replicas are tested against a throwaway Redis (tests/redis.py) behind Debian's nginx
if ! command -v redis-server >/dev/null || [ ! -x /usr/sbin/nginx ]; then
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends redis-server nginx >/dev/null
fi
scripts/lint.sh
# set-up warmed the caches (python -m app.web.warm): the tests never compile kernels meanwhile.
# One pytest worker per core (pytest-xdist; TEST_WORKERS=0 runs in this process); worksteal hands the
# tests left to an idle worker, so one long module does not keep the other core waiting.
.venv/bin/python -m pytest -n "${TEST_WORKERS:-auto}" --dist worksteal -m "not load" "$@"
# the tests that load the machine on purpose (busy processes beside a server) run alone, so that their load
# slows no other test; only the modules that hold one are collected (the marker is a module's pytestmark), unless
# arguments choose the tests; exit 5 (none selected, when arguments chose other tests) is not a failure
if [ $# -eq 0 ]; then
    mapfile -t loaded < <(grep -rlE 'pytest\.mark\.load\b' tests --include='test_*.py')
    set -- "${loaded[@]}"
fi
.venv/bin/python -m pytest -n 0 -m load "$@" || [ $? -eq 5 ]
