#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# ./run.sh              install what is missing, build the CLI (Release), run the main job on the
#                       sample: a neutral 16^3 LUT in every native format + the sample grade
#                       converted, each with the error it cost.
# ./run.sh ARGS...      the same set-up, then run the CLI: ./run.sh convert a.cube b.nutexb
# ./run.sh editor ARGS  build the editor instead and start it: ./run.sh editor shot.png grade.cube
# ./run.sh web [PORT]   build lutkit for the browser into build/web/ (scripts/build-web.sh) and
#                       serve the page on http://127.0.0.1:PORT/ (default 8000; docs/web.md)
# Only what the job needs is installed and built: the CLI and its image module (the editor and
# Qt 6 when asked). The tests and benchmarks are ./test.sh's.
set -euo pipefail
root="$(cd "$(dirname "$0")" && pwd)"
if [ "${1:-}" = "web" ]; then
  shift
  "$root/scripts/install-deps.sh" --web
  "$root/scripts/build-web.sh" "$root/build/web"
  exec python3 "$root/scripts/serve-web.py" "$root/build/web" --port "${1:-8000}"
fi
editor=0
if [ "${1:-}" = "editor" ]; then
  editor=1
  shift
fi
if [ "$editor" = 1 ]; then
  "$root/scripts/install-deps.sh" --editor
else
  "$root/scripts/install-deps.sh" --cli
fi
# As ./test.sh: a clone's objects are reused by another clone through ccache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
# No tests or benchmarks in the build system (./test.sh turns them on in the same tree: what is
# built stays built).
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DLUTKIT_BUILD_TESTS=OFF \
  -DLUTKIT_BUILD_BENCH=OFF >/dev/null
if [ "$editor" = 1 ]; then
  cmake --build "$root/build" -j"$(nproc)" --target lutkit-editor >/dev/null
  exec "$root/build/bin/lutkit-editor" "$@"
fi
cmake --build "$root/build" -j"$(nproc)" --target lutkit >/dev/null
if [ $# -gt 0 ]; then
  exec "$root/build/bin/lutkit" "$@"
fi
exec "$root/scripts/main-job.sh" "$root/build/bin/lutkit" "$root/out"
