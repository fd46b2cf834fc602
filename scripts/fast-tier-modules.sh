#!/usr/bin/env bash
# The modules of app/ that no test of the fast tier reaches: runs scripts/test-fast.sh once with the plugin
# tests/tier_calls.py (which records the modules whose functions ran), then lists the modules it never saw.
# The list must be empty, or each module in it named in tests/tier_calls.py's OUTSIDE with the reason.
# Arguments go to pytest.  Exit 1 when a module is unreached without a reason.
set -euo pipefail
cd "$(dirname "$0")/.."
python=${PYTHON:-.venv/bin/python}
calls=$(mktemp)
trap 'rm -f "$calls"' EXIT
LAGRANGE_TIER_CALLS=$calls PYTHON=$python scripts/test-fast.sh -q -p tests.tier_calls "$@" >/dev/null
PYTHONPATH=$PWD "$python" -m tests.tier_calls "$calls"
