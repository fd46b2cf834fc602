# Lagrange for classrooms: one `docker run -p 8000:8000 IMAGE`, fully offline at run time.
# scripts/serve.sh bounds slow clients (header and body deadlines, a connection cap) and derives
# the process counts and memory caps from the container's limits: `docker run --cpus 2 --memory 2g`.
#
# Stage "assets" fetches KaTeX and plotly.js from npm; the final image has no node.
# The chapter's derivations and work-precision reports are computed at build time.
# PIP_CERT / NODE_EXTRA_CA_CERTS let a build behind a TLS-inspecting proxy use a
# mounted CA bundle (scripts/container_test.sh does this); the defaults are harmless.
ARG PYTHON_IMAGE=python:3.11-slim

FROM ${PYTHON_IMAGE} AS assets
ARG NODE_EXTRA_CA_CERTS=/etc/ssl/certs/ca-certificates.crt
RUN apt-get update -qq && apt-get install -y -qq --no-install-recommends nodejs npm ca-certificates \
    && rm -rf /var/lib/apt/lists/*
WORKDIR /src
COPY package.json package-lock.json ./
COPY scripts/assets.sh scripts/assets.sh
RUN mkdir -p static && scripts/assets.sh

FROM ${PYTHON_IMAGE}
ARG PIP_CERT=/etc/ssl/certs/ca-certificates.crt
ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    LAGRANGE_CACHE_DIR=/app/.cache \
    LAGRANGE_DATA_DIR=/app/data \
    NUMBA_CACHE_DIR=/app/.cache/numba \
    PORT=8000 \
    WORKERS=0
WORKDIR /app
COPY pyproject.toml README.md ./
COPY app app
RUN pip install --no-cache-dir --disable-pip-version-check . && rm -rf build *.egg-info
# the server imports ./app (the working directory comes first on the path): its bytecode, compiled once
# here, since PYTHONDONTWRITEBYTECODE would have every start compile every module again
RUN python -m compileall -q app
COPY templates templates
COPY static static
COPY --from=assets /src/static/vendor static/vendor
# the vendor libraries' zstd copies beside them (app/web/precompress.py), written before the files become read-only
RUN python -m app.web.precompress
COPY scripts/serve.sh scripts/serve.sh
RUN useradd --create-home --uid 10001 lagrange && mkdir -p .cache data && chown -R lagrange /app/.cache /app/data
USER lagrange
# Derive the chapter (and precompute its reports) so the first student waits for nothing.
RUN python -m app.web.warm
# The classes' database (SQLite) lives here: `docker run -v lagrange-data:/app/data ...` keeps classes across
# restarts and upgrades (LAGRANGE_DATABASE_URL names a PostgreSQL instead).
VOLUME ["/app/data"]
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=5s --start-period=20s --retries=3 \
    CMD python -c "import os, urllib.request; urllib.request.urlopen('http://127.0.0.1:%s/healthz' % os.environ.get('PORT', '8000'), timeout=4)"
STOPSIGNAL SIGTERM
CMD ["scripts/serve.sh"]
