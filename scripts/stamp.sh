#!/usr/bin/env bash
# Print a fingerprint of what set-up depends on: the Python and npm dependency
# lists and the set-up scripts.  scripts/setup.sh records it when it finishes;
# scripts/run.sh sets up again only when it changed.
set -euo pipefail
cd "$(dirname "$0")/.."
cat pyproject.toml requirements.lock package-lock.json scripts/setup.sh scripts/assets.sh scripts/stamp.sh | sha256sum | cut -c1-32
