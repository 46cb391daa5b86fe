#!/usr/bin/env bash
# ./test.sh   install what is missing, build, and run the whole test suite with ctest.
# Exits non-zero on any failure. Set LUTKIT_QUICK=1 to skip the sanitizer build and fuzzing.
set -euo pipefail
root="$(cd "$(dirname "$0")" && pwd)"
"$root/scripts/install-deps.sh"
jobs="$(nproc)"

echo "== Release build and tests"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j"$jobs"
(cd "$root/build" && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$jobs")
