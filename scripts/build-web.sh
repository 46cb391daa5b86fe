#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/build-web.sh [OUTDIR]   lutkit for the browser (docs/web.md): the portable CLI compiled
# to WebAssembly with Debian's emscripten, and the page, into OUTDIR (default build/web):
# index.html, lutkit.mjs, lutkit.wasm and the page's own files, static files any host serves.
# The build tree is build-web/ (ccache works with emcc). Needs scripts/install-deps.sh's packages.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build/web}"
case "$out" in /*) ;; *) out="$PWD/$out" ;; esac
tree="${LUTKIT_WEB_BUILD_DIR:-$root/build-web}"
# Debian's emscripten runs its tools with the node on the PATH; they need Debian's acorn modules.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
if ! command -v emcmake >/dev/null; then
  echo "build-web: emscripten is not installed (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
emcmake cmake -S "$root" -B "$tree" -DCMAKE_BUILD_TYPE=Release -DLUTKIT_PORTABLE=ON \
  -DLUTKIT_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build "$tree" -j"$(nproc)" --target lutkit
mkdir -p "$out"
cp "$tree/bin/lutkit.mjs" "$tree/bin/lutkit.wasm" "$out/"
if [ -d "$root/web/site" ]; then
  cp -r "$root/web/site/." "$out/"
fi
echo "build-web: $out (lutkit.wasm $(stat -c %s "$out/lutkit.wasm") bytes, $(gzip -9c "$out/lutkit.wasm" | wc -c) gzipped)"
