#!/bin/sh
# Serve the app with uvicorn: PORT (default 8000), WORKERS (0 or unset: one per CPU core),
# HOST (default 0.0.0.0). Long keep-alive for many students behind one address;
# uvicorn shuts down gracefully on SIGTERM (finishes requests in flight).
set -eu
workers=${WORKERS:-0}
if [ "$workers" = "0" ]; then
    workers=$(python -c "import os; print(max(1, len(os.sched_getaffinity(0))))")
fi
exec python -m uvicorn app.main:app --host "${HOST:-0.0.0.0}" --port "${PORT:-8000}" \
    --workers "$workers" --timeout-keep-alive 75 --timeout-graceful-shutdown 20 --no-access-log
