#!/usr/bin/env bash
# The development loop: every test but the slow, browser and load ones (CI runs them all
# through scripts/test.sh).  Arguments go to pytest: scripts/test-fast.sh tests/engine -x
set -euo pipefail
cd "$(dirname "$0")/.."
# one worker per core, as scripts/test.sh (TEST_WORKERS=0: in this process, e.g. for a debugger)
exec "${PYTHON:-.venv/bin/python}" -m pytest -m "not slow and not browser and not load" -n "${TEST_WORKERS:-auto}" --dist worksteal "$@"
