# Lagrange: the app with its front-end assets, fully offline at run time.
# Stage 1 fetches the npm packages; the final image has no node.
FROM node:20-bookworm-slim AS assets
WORKDIR /src
COPY package.json package-lock.json ./
COPY scripts/assets.sh scripts/assets.sh
RUN mkdir -p static && scripts/assets.sh

FROM python:3.11-slim
ENV PYTHONDONTWRITEBYTECODE=1 PYTHONUNBUFFERED=1 LAGRANGE_CACHE_DIR=/app/.cache
WORKDIR /app
COPY pyproject.toml README.md ./
COPY app app
RUN pip install --no-cache-dir .
COPY templates templates
COPY static static
COPY --from=assets /src/static/vendor static/vendor
# Derive the chapter at build time so the first request waits for nothing.
RUN python -m app.service.derivations && useradd --create-home lagrange && chown -R lagrange /app/.cache
USER lagrange
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=5s CMD python -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/healthz')"
CMD ["sh", "-c", "uvicorn app.main:app --host 0.0.0.0 --port ${PORT:-8000} --workers ${WORKERS:-2} --timeout-keep-alive 75"]
