#!/usr/bin/env bash
# ./run.sh            install what is missing, build (Release), run the main job on the sample:
#                     a neutral 16^3 LUT in every native format + the sample grade converted.
# ./run.sh ARGS...    the same set-up, then run the CLI: ./run.sh convert a.cube b.nutexb
set -euo pipefail
root="$(cd "$(dirname "$0")" && pwd)"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j"$(nproc)" >/dev/null
if [ $# -gt 0 ]; then
  exec "$root/build/bin/lutkit" "$@"
fi
exec "$root/scripts/main-job.sh" "$root/build/bin/lutkit" "$root/out"
