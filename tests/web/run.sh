#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The browser edition's tests: builds it (scripts/build-web.sh, into build/web unless
# LUTKIT_WEB_DIR names a built site), then in headless Chromium (Debian's chromium +
# chromium-driver through python3-selenium), against the native CLI (build/bin/lutkit,
# LUTKIT_NATIVE): every command's output files and messages (test_same_bytes.py), and the page
# driven like a user (run-page-tests.sh). Exit non-zero on any failure.
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
echo "== tests/web/test_same_bytes.py"
"$py" "$root/tests/web/test_same_bytes.py" || status=1
echo "== tests/web/run-page-tests.sh"
"$root/tests/web/run-page-tests.sh" "$LUTKIT_WEB_DIR" || status=1
exit $status
