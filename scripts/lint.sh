#!/usr/bin/env bash
# The rules of the house, executable: ruff; the layer contract (import-linter:
# settings/errors -> scenes -> engine -> numerics -> viz -> service -> web -> main);
# deptry (every import declared, every declared package used); mypy on the typed
# packages (pyproject.toml's [tool.mypy] files); the settings table in docs/deployment.md.
# Usage: scripts/lint.sh   (from a set-up checkout: .venv, or PYTHON=...)
set -euo pipefail
cd "$(dirname "$0")/.."
python=${PYTHON:-.venv/bin/python}
bin=$(dirname "$python")
export PYTHONPATH=$PWD
"$bin/ruff" check app tests benchmarks scripts
"$bin/lint-imports"
"$bin/deptry" .
"$bin/mypy"
"$python" scripts/settings_table.py --check
