#!/bin/sh
# Serve the app with uvicorn: PORT (default 8000), WORKERS (web processes; 0 or unset: from the
# container's CPUs, see app/settings.py), HOST (default 0.0.0.0). The other options come from
# the settings (python -m app.web.http.server_options): a long keep-alive for many students behind one
# address, a cap on open connections (then 503), a graceful shutdown on SIGTERM that finishes the
# requests in flight, uvicorn's proxy-header rewriting off (LAGRANGE_PROXY_HEADER decides). The
# per-address connection caps and the header, body and write deadlines are the app's own
# (app/web/http/slow_clients.py, app/web/api/limits.py): they hold under plain `uvicorn app.main:app` too.
set -eu
if [ "${WORKERS:-0}" != "0" ]; then
    export LAGRANGE_WEB_PROCESSES="$WORKERS"  # the memory budget counts them
fi
# shellcheck disable=SC2046 # the options are words
exec python -m uvicorn app.main:app --host "${HOST:-0.0.0.0}" --port "${PORT:-8000}" \
    $(python -m app.web.http.server_options) --no-access-log
