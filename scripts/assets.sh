#!/usr/bin/env bash
# Install KaTeX, plotly.js and swagger-ui from npm (versions pinned in package-lock.json)
# and copy the files the pages load into static/vendor.  Install scripts are not run
# (swagger-ui-dist pulls in a package whose install script reports usage to a server).
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v npm >/dev/null 2>&1; then
    apt-get update -qq && apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi
# (npm ci also installs the dev dependencies: axe-core, which the accessibility tests load into the browser; it is never served)
SCARF_ANALYTICS=false npm ci --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null

vendor=static/vendor
rm -rf "$vendor"
mkdir -p "$vendor/katex/contrib" "$vendor/plotly" "$vendor/swagger-ui"
cp node_modules/katex/dist/katex.min.js node_modules/katex/dist/katex.min.css "$vendor/katex/"
cp node_modules/katex/dist/contrib/auto-render.min.js "$vendor/katex/contrib/"
cp -r node_modules/katex/dist/fonts "$vendor/katex/fonts"
# the basic bundle (scatter, bar; about 0.36 MB gzipped): every plot is 2-D, the mechanism is drawn on our own canvas
cp node_modules/plotly.js-basic-dist-min/plotly-basic.min.js "$vendor/plotly/plotly.min.js"
# the API reference at /docs (app/web/api/docs.py)
cp node_modules/swagger-ui-dist/swagger-ui-bundle.js node_modules/swagger-ui-dist/swagger-ui.css "$vendor/swagger-ui/"
# Precompressed copies, served to browsers that accept gzip (app/web/rendering/templating.py).
find "$vendor" -type f \( -name '*.js' -o -name '*.css' \) -exec gzip -9 -k -f {} +
