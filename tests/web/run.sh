#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The browser edition's tests: builds it (scripts/build-web.sh, into build/web unless
# LUTKIT_WEB_DIR names a built site), then in headless Chromium (Debian's chromium +
# chromium-driver through python3-selenium), against the native CLI (build/bin/lutkit,
# LUTKIT_NATIVE): every command's output files and messages (test_same_bytes.py), and the page
# driven like a user (run-page-tests.sh); under Node, the WebAssembly sampler kernels against
# their definition (wasm_kernels_check.cpp). Exit non-zero on any failure.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
export LUTKIT_WEB_DIR="${LUTKIT_WEB_DIR:-$root/build/web}"
if [ "${LUTKIT_WEB_SKIP_BUILD:-0}" != "1" ]; then
  "$root/scripts/build-web.sh" "$LUTKIT_WEB_DIR"
fi
# Debian's python3 (with selenium and numpy), whatever python3 comes first on the PATH.
py=/usr/bin/python3
[ -x "$py" ] || py=python3
status=0
# The WebAssembly SIMD sampler kernels against their definition, bit for bit, under Node.
echo "== tests/web/wasm_kernels_check.cpp"
tree="${LUTKIT_WEB_BUILD_DIR:-$root/build-web}"
if [ -f "$tree/CMakeCache.txt" ]; then
  NODE_PATH="${NODE_PATH:-/usr/share/nodejs}" cmake --build "$tree" --target lutkit_wasm_kernels_check >/dev/null &&
    node --no-experimental-fetch "$tree/bin/lutkit_wasm_kernels_check.js" || status=1
else
  echo "no WebAssembly build tree at $tree (scripts/build-web.sh makes it): skipped"
fi
echo "== tests/web/test_same_bytes.py"
"$py" "$root/tests/web/test_same_bytes.py" || status=1
echo "== tests/web/run-page-tests.sh"
"$root/tests/web/run-page-tests.sh" "$LUTKIT_WEB_DIR" || status=1
exit $status
