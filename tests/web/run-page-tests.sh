#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# tests/web/run-page-tests.sh [SITE_DIR]   the page's tests (tests/web/test_page_*.py) in headless
# Chromium: the start, the modder's whole route, the colourist's tools, errors and the keyboard;
# the modder's route in Firefox too where firefox-esr is installed (skipped otherwise).
# Needs the page built (scripts/build-web.sh, default build/web) and the native CLI
# (build/bin/lutkit, LUTKIT_NATIVE), the oracle of every downloaded file. Screenshots of each step
# go to build/page-shots/ (LUTKIT_PAGE_SHOTS). Debian's python3 (python3-selenium), chromium and
# chromium-driver; nothing is downloaded.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
export LUTKIT_WEB_DIR="${1:-${LUTKIT_WEB_DIR:-$root/build/web}}"
cd "$root/tests/web"
exec /usr/bin/python3 -m unittest -v test_page_start test_page_modder test_page_colourist test_page_firefox
